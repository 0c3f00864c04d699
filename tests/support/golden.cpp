#include "support/golden.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace terrasol::testing {
namespace {

// TERRASOL_GOLDEN_TOLERANCE="PIXEL,PERCENT" (PIXEL in 1/255) loosens every golden comparison, for the
// GPU check: another rasterizer rounds and filters differently from llvmpipe, where goldens are made.
ImageTolerance loosened(ImageTolerance tolerance) {
  const char* text = std::getenv("TERRASOL_GOLDEN_TOLERANCE");
  float pixel = 0.0f, percent = 0.0f;
  if (text && std::sscanf(text, "%f,%f", &pixel, &percent) == 2) {
    tolerance.pixel = std::max(tolerance.pixel, pixel / 255.0f);
    tolerance.percent = std::max(tolerance.percent, percent);
  }
  return tolerance;
}

}  // namespace

::testing::AssertionResult matchesGolden(const Image& actual, const std::string& name,
                                         const ImageTolerance& given) {
  const ImageTolerance tolerance = loosened(given);
  const std::filesystem::path golden = std::filesystem::path(TERRASOL_GOLDEN_DIR) / (name + ".png");
  const char* update = std::getenv("TERRASOL_UPDATE_GOLDENS");
  if (update && std::string_view(update) == "1") {
    saveImage(golden, actual);
    std::printf("updated golden %s\n", golden.c_str());
    return ::testing::AssertionSuccess();
  }
  if (!std::filesystem::exists(golden)) {
    saveImage(testOutputDir() / (name + "_actual.png"), actual);
    return ::testing::AssertionFailure()
           << "missing golden " << golden << " (create it on purpose with tools/update-goldens.sh)";
  }
  const ImageComparison cmp = compareImages(actual, loadImage(golden), tolerance);
  if (cmp.matches) return ::testing::AssertionSuccess();

  const auto actualPath = testOutputDir() / (name + "_actual.png");
  saveImage(actualPath, actual);
  auto failure = ::testing::AssertionFailure() << "image differs from golden " << golden << ": ";
  if (!cmp.sameSize) return failure << "size differs; actual written to " << actualPath;
  const auto diffPath = testOutputDir() / (name + "_diff.png");
  saveImage(diffPath, cmp.diff);
  return failure << cmp.failingPercent << " % of pixels differ by more than " << tolerance.pixel * 255.0f
                 << "/255 (allowed " << tolerance.percent << " %), max difference " << cmp.maxError * 255.0
                 << "/255; actual: " << actualPath << ", diff: " << diffPath;
}

}  // namespace terrasol::testing
