#include "support/golden.h"

#include <cstdlib>
#include <string_view>

namespace terrasol::testing {

::testing::AssertionResult matchesGolden(const Image& actual, const std::string& name,
                                         const ImageTolerance& tolerance) {
  const std::filesystem::path golden = std::filesystem::path(TERRASOL_GOLDEN_DIR) / (name + ".png");
  const char* update = std::getenv("TERRASOL_UPDATE_GOLDENS");
  if (update && std::string_view(update) == "1") {
    saveImage(golden, actual);
    std::printf("updated golden %s\n", golden.c_str());
    return ::testing::AssertionSuccess();
  }
  if (!std::filesystem::exists(golden)) {
    saveImage(testOutputDir() / (name + "_actual.png"), actual);
    return ::testing::AssertionFailure() << "missing golden " << golden
                                         << " (create it on purpose with tools/update-goldens.sh)";
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
