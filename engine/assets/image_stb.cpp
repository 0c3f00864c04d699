// image.h through stb_image, for builds without OpenImageIO (TERRASOL_IMAGE_IO=stb): the GPU check's
// bundle, which must travel to machines where OpenImageIO's libraries cannot. Reads what stb_image
// reads (PNG of every bit depth and colour type, with tRNS; JPEG, TGA, BMP), writes PNG.

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_RESIZE_IMPLEMENTATION
#include <stb/stb_image.h>
#include <stb/stb_image_resize.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "assets/image.h"
#include "core/error.h"

namespace terrasol {
namespace {

// A PNG's size from its header. stb_image refuses a PNG too large to decode with a reason that gives
// no size ("unknown image type" once every format has declined it), so the size is read here first.
bool pngSize(const std::vector<std::uint8_t>& bytes, int& w, int& h) {
  static constexpr std::uint8_t kStart[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n',  // signature
                                            0,    0,   0,   13,  'I',  'H',  'D',  'R'};  // IHDR first
  if (bytes.size() < sizeof kStart + 8 || !std::equal(std::begin(kStart), std::end(kStart), bytes.begin())) {
    return false;
  }
  const auto get32 = [&](std::size_t at) {
    return static_cast<std::uint32_t>(bytes[at]) << 24 | static_cast<std::uint32_t>(bytes[at + 1]) << 16 |
           static_cast<std::uint32_t>(bytes[at + 2]) << 8 | bytes[at + 3];
  };
  w = static_cast<int>(std::min<std::uint32_t>(get32(16), 0x7FFFFFFF));
  h = static_cast<int>(std::min<std::uint32_t>(get32(20), 0x7FFFFFFF));
  return true;
}

Image decode(const std::vector<std::uint8_t>& bytes, const std::string& name, const ImageLimits& limits) {
  if (bytes.empty()) throw Error(name + ": empty file");
  const auto size = static_cast<int>(std::min<std::size_t>(bytes.size(), 0x7FFFFFFF));
  int w = 0, h = 0, channels = 0;
  if (!pngSize(bytes, w, h) && !stbi_info_from_memory(bytes.data(), size, &w, &h, &channels)) {
    throw Error(name + ": cannot read image: " + stbi_failure_reason());
  }
  if (w <= 0 || h <= 0 || w > limits.maxSide || h > limits.maxSide ||
      static_cast<std::int64_t>(w) * h > limits.maxPixels) {
    throw Error(name + ": unsupported image size " + std::to_string(w) + "x" + std::to_string(h));
  }
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(bytes.data(), size, &w, &h, &channels, 4), stbi_image_free);
  if (!pixels) throw Error(name + ": corrupt or truncated image: " + stbi_failure_reason());
  Image image(w, h);
  std::copy_n(pixels.get(), image.rgba.size(), image.rgba.begin());
  return image;
}

}  // namespace

Image loadImage(const std::filesystem::path& file, const ImageLimits& limits) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(locate(file, 0, "cannot read image: cannot open the file"));
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  return decode(bytes, file.string(), limits);
}

Image decodeImage(const std::vector<std::uint8_t>& bytes, const std::string& name,
                  const ImageLimits& limits) {
  return decode(bytes, name, limits);
}

void saveImage(const std::filesystem::path& file, const Image& image) {
  if (file.extension() != ".png")
    throw Error(locate(file, 0, "cannot write image: this build writes PNG only"));
  if (!stbi_write_png(file.string().c_str(), image.width, image.height, 4, image.rgba.data(),
                      image.width * 4)) {
    throw Error(locate(file, 0, "cannot write image"));
  }
}

Image resizeImage(const Image& src, int w, int h, bool filtered) {
  Image image(w, h);
  if (filtered) {
    stbir_resize_uint8(src.rgba.data(), src.width, src.height, 0, image.rgba.data(), w, h, 0, 4);
    return image;
  }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int sx = std::min(src.width - 1, static_cast<int>((x + 0.5) * src.width / w));
      const int sy = std::min(src.height - 1, static_cast<int>((y + 0.5) * src.height / h));
      std::copy_n(src.pixel(sx, sy), 4, image.pixel(x, y));
    }
  return image;
}

ImageComparison compareImages(const Image& actual, const Image& expected, const ImageTolerance& tolerance) {
  ImageComparison result;
  result.sameSize = actual.width == expected.width && actual.height == expected.height;
  if (!result.sameSize || actual.width == 0 || actual.height == 0) return result;
  result.diff = Image(actual.width, actual.height);
  int largest = 0;
  for (std::size_t p = 0; p < actual.rgba.size(); p += 4) {
    int pixel = 0;
    for (std::size_t c = 0; c < 4; ++c) {
      const int d = std::abs(actual.rgba[p + c] - expected.rgba[p + c]);
      pixel = std::max(pixel, d);
      if (c < 3) result.diff.rgba[p + c] = static_cast<std::uint8_t>(std::min(255, d * 8));
    }
    result.diff.rgba[p + 3] = 255;
    largest = std::max(largest, pixel);
    if (static_cast<float>(pixel) / 255.0f > tolerance.pixel) ++result.failingPixels;
  }
  const double pixels = static_cast<double>(actual.width) * actual.height;
  result.failingPercent = 100.0 * static_cast<double>(result.failingPixels) / pixels;
  result.maxError = largest / 255.0;
  result.matches = result.failingPercent <= tolerance.percent;
  return result;
}

}  // namespace terrasol
