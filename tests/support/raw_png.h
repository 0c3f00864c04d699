#pragma once
// PNG files of any bit depth and colour type, written without an image library: the image readers'
// tests need inputs (16-bit grey with alpha) that stb_image_write cannot make, in every build.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace terrasol::testing {

// PNG colour types (the IHDR field).
enum class PngColour : std::uint8_t { Grey = 0, Rgb = 2, GreyAlpha = 4, Rgba = 6 };

// Writes `rows` (height rows of packed samples, 16-bit ones big-endian, no filter bytes) as an
// unfiltered PNG with stored (uncompressed) deflate blocks.
void writeRawPng(const std::filesystem::path& file, int width, int height, int bitDepth, PngColour colour,
                 const std::vector<std::uint8_t>& rows);

}  // namespace terrasol::testing
