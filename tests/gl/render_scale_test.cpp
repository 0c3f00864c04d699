// Render scale: the scene drawn smaller and scaled up to the target in the final pass.
#include <filesystem>

#include "scene_render/scene_render.h"
#include "support/gl_test.h"

namespace terrasol {
namespace {

class RenderScaleTest : public testing::GlTest {};

// At half scale the picture keeps the target's size, shows the same scene (most pixels close to the
// full-scale ones), is not a copy of it, and has no NaN or Inf; a scale outside 0.25..1 is refused.
TEST_F(RenderScaleTest, AHalfScaleSceneIsScaledUpToTheTarget) {
  const auto scene = std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "scenes" / "noon_terrain.json";
  FrameRequest request;
  request.checkNan = true;
  SceneRenderer full(loadScene(scene));
  const RenderedFrame whole = full.renderFrame(0, request);
  SceneRenderer half(loadScene(scene, {"render.scale=0.5"}));
  const RenderedFrame scaled = half.renderFrame(0, request);
  context_->checkErrors("rendering at half scale");
  ASSERT_EQ(scaled.image.width, whole.image.width);
  ASSERT_EQ(scaled.image.height, whole.image.height);
  EXPECT_EQ(scaled.nanPixels, 0);
  const ImageComparison close = compareImages(scaled.image, whole.image, {40.0f / 255.0f, 8.0f});
  EXPECT_TRUE(close.matches) << close.failingPercent << " % of pixels differ by more than 40/255";
  const ImageComparison exact = compareImages(scaled.image, whole.image, {2.0f / 255.0f, 0.0f});
  EXPECT_GT(exact.failingPercent, 1.0) << "drawn at half the size, it cannot match texel for texel";
  EXPECT_THROW(loadScene(scene, {"render.scale=0.1"}), Error);
  EXPECT_THROW(loadScene(scene, {"render.scale=1.5"}), Error);
}

}  // namespace
}  // namespace terrasol
