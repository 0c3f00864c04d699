#pragma once
// 8-bit RGBA images and tolerant image comparison. All file I/O goes through OpenImageIO (image.cpp);
// a build for machines where its many libraries cannot go (TERRASOL_IMAGE_IO=stb, the GPU check's
// bundle) reads and writes PNG and the other formats stb_image knows instead (image_stb.cpp).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace terrasol {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width*height*4 bytes, top row first, values as stored (sRGB for colour)

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}
  std::uint8_t* pixel(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
  const std::uint8_t* pixel(int x, int y) const {
    return &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  }
};

// Largest image accepted; checked against the header before any pixel memory is allocated.
struct ImageLimits {
  int maxSide = 32768;
  std::int64_t maxPixels = std::int64_t{1} << 28;
};

// Reads any format OpenImageIO knows; grey, grey+alpha, RGB, palette and 16-bit images become 8-bit
// RGBA. Throws Error naming the file and the problem (missing, empty, corrupt, truncated, too large).
Image loadImage(const std::filesystem::path& file, const ImageLimits& limits = {});
// The same from bytes in memory; `name` (with its extension) names the format and the errors.
Image decodeImage(const std::vector<std::uint8_t>& bytes, const std::string& name,
                  const ImageLimits& limits = {});
// Writes by extension (.png, .exr, ...); throws Error naming the file on failure.
void saveImage(const std::filesystem::path& file, const Image& image);
// Scaled to w x h: `filtered` for colour and normals, else each pixel the source pixel under its
// centre (data that must not blend: specular maps' metal ids and emission).
Image resizeImage(const Image& src, int w, int h, bool filtered);

// A pixel fails when any channel differs by more than `pixel` (0..1); the images match when at most
// `percent` of the pixels fail. Defaults allow llvmpipe's differences across CPU instruction sets
// (measured: up to 7/255 on about 4 % of pixels).
struct ImageTolerance {
  float pixel = 10.0f / 255.0f;
  float percent = 0.5f;
};

struct ImageComparison {
  bool sameSize = false;
  std::int64_t failingPixels = 0;
  double failingPercent = 100.0;
  double maxError = 1.0;  // largest channel difference, 0..1
  bool matches = false;
  Image diff;  // |actual - expected| amplified 8x with opaque alpha; empty when the sizes differ
};

ImageComparison compareImages(const Image& actual, const Image& expected, const ImageTolerance& tolerance);

}  // namespace terrasol
