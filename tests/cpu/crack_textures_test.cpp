#include "assets/crack_textures.h"

#include <gtest/gtest.h>

#include "assets/image.h"
#include "core/paths.h"
#include "packgen.h"

namespace terrasol {
namespace {

bool dark(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return p[3] >= 26 && p[0] < 128;  // drawn (Minecraft's alpha test at 0.1) and darkening (2 x texel < 1)
}

int darkTexels(const Image& image) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += dark(image, x, y);
  return n;
}

// The default pack's crack is the generator's, and it grows: each stage keeps every dark texel of the
// one before and adds more, from a few texels to much of the face.
TEST(CrackTextures, DefaultPackCrackIsTheGeneratorsAndGrowsStageByStage) {
  const std::vector<Image> generated = packgen::generateCracks();
  ASSERT_EQ(generated.size(), static_cast<std::size_t>(kCrackStages));
  const auto dir = resourcePackDir() / "default" / "assets" / "minecraft" / "textures" / "block";
  for (int stage = 0; stage < kCrackStages; ++stage) {
    const Image& image = generated[static_cast<std::size_t>(stage)];
    EXPECT_EQ(loadImage(dir / (crackTextureName(stage) + ".png")).rgba, image.rgba) << stage;
    ASSERT_EQ(image.width, 16);
    if (stage == 0) continue;
    const Image& before = generated[static_cast<std::size_t>(stage - 1)];
    EXPECT_GT(darkTexels(image), darkTexels(before)) << stage;
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) EXPECT_TRUE(!dark(before, x, y) || dark(image, x, y)) << stage;
  }
  EXPECT_LE(darkTexels(generated.front()), 12);
  EXPECT_GE(darkTexels(generated.back()), 80);
}

}  // namespace
}  // namespace terrasol
