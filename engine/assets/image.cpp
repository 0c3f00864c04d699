#include "assets/image.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <string>

#include "core/error.h"

namespace terrasol {
namespace {

OIIO::ImageBuf wrap(const Image& image) {
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  // ImageBuf only reads through this pointer in the callers below.
  return OIIO::ImageBuf(spec, const_cast<std::uint8_t*>(image.rgba.data()));
}

void expandToRgba(const std::vector<std::uint8_t>& src, int channels, Image& out) {
  const std::size_t n = static_cast<std::size_t>(out.width) * out.height;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* s = &src[i * channels];
    std::uint8_t* d = &out.rgba[i * 4];
    if (channels <= 2) {
      d[0] = d[1] = d[2] = s[0];
      d[3] = channels == 2 ? s[1] : 255;
    } else {
      d[0] = s[0];
      d[1] = s[1];
      d[2] = s[2];
      d[3] = channels >= 4 ? s[3] : 255;
    }
  }
}

}  // namespace

namespace {

// Alpha is data (LabPBR keeps height and emission there, and RGB under alpha 0 matters): OpenImageIO
// must neither premultiply on read nor divide on write.
OIIO::ImageSpec straightAlpha() {
  OIIO::ImageSpec spec;
  spec.attribute("oiio:UnassociatedAlpha", 1);
  return spec;
}

Image readAll(OIIO::ImageInput& in, const std::string& name, const ImageLimits& limits) {
  const OIIO::ImageSpec& spec = in.spec();
  const std::int64_t pixels = static_cast<std::int64_t>(spec.width) * spec.height;
  if (spec.width <= 0 || spec.height <= 0 || spec.width > limits.maxSide || spec.height > limits.maxSide ||
      pixels > limits.maxPixels || spec.nchannels <= 0) {
    throw Error(name + ": unsupported image size " + std::to_string(spec.width) + "x" +
                std::to_string(spec.height) + " with " + std::to_string(spec.nchannels) + " channels");
  }
  const int channels = std::min(spec.nchannels, 4);
  std::vector<std::uint8_t> raw(static_cast<std::size_t>(pixels) * static_cast<std::size_t>(channels));
  if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data())) {
    throw Error(name + ": corrupt or truncated image: " + in.geterror());
  }
  Image image(spec.width, spec.height);
  expandToRgba(raw, channels, image);
  return image;
}

}  // namespace

Image loadImage(const std::filesystem::path& file, const ImageLimits& limits) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(file, ec) && std::filesystem::file_size(file, ec) == 0) {
    throw Error(locate(file, 0, "empty file"));
  }
  const OIIO::ImageSpec config = straightAlpha();
  auto in = OIIO::ImageInput::open(file.string(), &config);
  if (!in) throw Error(locate(file, 0, "cannot read image: " + OIIO::geterror()));
  return readAll(*in, file.string(), limits);
}

Image decodeImage(const std::vector<std::uint8_t>& bytes, const std::string& name,
                  const ImageLimits& limits) {
  if (bytes.empty()) throw Error(name + ": empty file");
  OIIO::Filesystem::IOMemReader reader(const_cast<std::uint8_t*>(bytes.data()), bytes.size());
  OIIO::ImageSpec config = straightAlpha();
  void* proxy = &reader;  // given a config, OpenImageIO 2.4 takes the proxy from it, not from the argument
  config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  auto in = OIIO::ImageInput::open(name, &config, &reader);
  if (!in) throw Error(name + ": cannot read image: " + OIIO::geterror());
  return readAll(*in, name, limits);
}

void saveImage(const std::filesystem::path& file, const Image& image) {
  auto out = OIIO::ImageOutput::create(file.string());
  if (!out) throw Error(locate(file, 0, "cannot write image: " + OIIO::geterror()));
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(file.string(), spec) || !out->write_image(OIIO::TypeDesc::UINT8, image.rgba.data()) ||
      !out->close()) {
    throw Error(locate(file, 0, "cannot write image: " + out->geterror()));
  }
}

Image resizeImage(const Image& src, int w, int h, bool filtered) {
  const OIIO::ImageBuf in = wrap(src);
  const OIIO::ROI roi(0, w, 0, h, 0, 1, 0, 4);
  const OIIO::ImageBuf out =
      filtered ? OIIO::ImageBufAlgo::resize(in, "", 0.0f, roi) : OIIO::ImageBufAlgo::resample(in, false, roi);
  Image image(w, h);
  out.get_pixels(roi, OIIO::TypeDesc::UINT8, image.rgba.data());
  return image;
}

ImageComparison compareImages(const Image& actual, const Image& expected, const ImageTolerance& tolerance) {
  ImageComparison result;
  result.sameSize = actual.width == expected.width && actual.height == expected.height;
  if (!result.sameSize || actual.width == 0 || actual.height == 0) return result;

  const OIIO::ImageBuf a = wrap(actual);
  const OIIO::ImageBuf b = wrap(expected);
  const auto stats = OIIO::ImageBufAlgo::compare(a, b, tolerance.pixel, tolerance.pixel);
  const double pixels = static_cast<double>(actual.width) * actual.height;
  result.failingPixels = static_cast<std::int64_t>(stats.nfail);
  result.failingPercent = 100.0 * static_cast<double>(stats.nfail) / pixels;
  result.maxError = stats.maxerror;
  // (stats.error is set whenever any pixel fails, so it says nothing beyond nfail.)
  result.matches = result.failingPercent <= tolerance.percent;

  OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(a, b);
  diff = OIIO::ImageBufAlgo::mul(diff, {8.0f, 8.0f, 8.0f, 0.0f});
  diff = OIIO::ImageBufAlgo::add(diff, {0.0f, 0.0f, 0.0f, 1.0f});
  result.diff = Image(actual.width, actual.height);
  diff.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, result.diff.rgba.data());
  return result;
}

}  // namespace terrasol
