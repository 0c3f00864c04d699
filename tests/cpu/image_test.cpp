#include "assets/image.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "support/error_of.h"
#include "support/golden.h"

namespace terrasol {
namespace {

Image gradient(int w, int h) {
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 255 / w);
      p[1] = static_cast<std::uint8_t>(y * 255 / h);
      p[2] = 128;
      p[3] = static_cast<std::uint8_t>((x * 7 + y * 13) % 256);  // alpha is data: every value, 0 included
    }
  return image;
}

std::string errorOf(const std::filesystem::path& file) {
  return testing::errorOf([&] { loadImage(file); });
}

TEST(Image, PngRoundTripIsExact) {
  const Image image = gradient(37, 21);
  const auto file = testing::testOutputDir() / "roundtrip.png";
  saveImage(file, image);
  const Image back = loadImage(file);
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 21);
  EXPECT_EQ(back.rgba, image.rgba);
}

TEST(Image, BadFilesGiveErrorsNamingTheFile) {
  const auto dir = testing::testOutputDir();
  const auto missing = dir / "does_not_exist.png";
  EXPECT_NE(errorOf(missing).find(missing.string()), std::string::npos) << errorOf(missing);

  const auto garbage = dir / "garbage.png";
  std::ofstream(garbage, std::ios::binary) << "this is not a png at all";
  EXPECT_NE(errorOf(garbage).find(garbage.string()), std::string::npos) << errorOf(garbage);

  // A real PNG cut in half: the header is fine, the pixel data is not.
  const auto whole = dir / "whole.png";
  saveImage(whole, gradient(64, 64));
  std::ifstream in(whole, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  const auto truncated = dir / "truncated.png";
  std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  EXPECT_NE(errorOf(truncated).find(truncated.string()), std::string::npos) << errorOf(truncated);
}

TEST(ImageCompare, ToleratesSmallDifferencesAndCountsLargeOnes) {
  const Image expected = gradient(10, 10);
  Image actual = expected;
  EXPECT_TRUE(compareImages(actual, expected, {}).matches);

  actual.pixel(3, 3)[0] += 9;  // within 10/255 everywhere
  auto cmp = compareImages(actual, expected, {});
  EXPECT_TRUE(cmp.matches);
  EXPECT_EQ(cmp.failingPixels, 0);

  actual.pixel(5, 5)[1] += 40;  // one failing pixel = 1 % of 100
  cmp = compareImages(actual, expected, {});
  EXPECT_EQ(cmp.failingPixels, 1);
  EXPECT_NEAR(cmp.failingPercent, 1.0, 1e-9);
  EXPECT_FALSE(cmp.matches);  // default allows 0.5 %
  EXPECT_TRUE(compareImages(actual, expected, {10.0f / 255.0f, 1.0f}).matches);
  EXPECT_NEAR(cmp.maxError * 255.0, 40.0, 0.5);
  // The diff shows the failing pixel brightly and the identical ones black.
  EXPECT_EQ(cmp.diff.pixel(5, 5)[1], 255);
  EXPECT_EQ(cmp.diff.pixel(0, 0)[1], 0);
  EXPECT_EQ(cmp.diff.pixel(0, 0)[3], 255);

  EXPECT_FALSE(compareImages(gradient(10, 11), expected, {}).matches);
}

}  // namespace
}  // namespace terrasol
