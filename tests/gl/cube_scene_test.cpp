#include "support/cube_scene.h"

#include <set>

#include "render/gl/render_target.h"
#include "support/gl_test.h"
#include "support/golden.h"

namespace terrasol {
namespace {

class CubeSceneTest : public testing::GlTest {
 protected:
  Image render(const Camera& camera, glm::vec3 towardLight) {
    const ShaderPreprocessor shaders = CubeScene::sceneShaders();
    const CubeScene scene(shaders, CubeScene::standardCubes());
    const RenderTarget target({320, 180});
    scene.draw(target.framebuffer(), target.size(), camera, towardLight);
    context_->checkErrors("drawing the cube scene");
    return target.readPixels();
  }
};

const Camera kView{{9.0f, 6.0f, 10.0f}, {0.0f, 0.5f, 0.0f}, 60.0f};

TEST_F(CubeSceneTest, RunsOnOpenGl45Core) {
  EXPECT_NE(context_->description().find("4.5"), std::string::npos) << context_->description();
}

TEST_F(CubeSceneTest, HighSunMatchesGolden) {
  const Image image = render(kView, {0.45f, 0.8f, 0.35f});
  EXPECT_TRUE(testing::matchesGolden(image, "cube_scene_high_sun"));
}

TEST_F(CubeSceneTest, LowSunMatchesGolden) {
  const Image image = render(kView, {-0.9f, 0.15f, 0.2f});
  EXPECT_TRUE(testing::matchesGolden(image, "cube_scene_low_sun"));
}

// Independent of any golden: the sky is the clear colour, the lit slab is brighter than its shade
// under a low sun, and the picture has real content.
TEST_F(CubeSceneTest, LightingFollowsTheLightDirection) {
  const Image high = render(kView, {0.0f, 1.0f, 0.0f});
  const Image grazing = render(kView, {1.0f, 0.02f, 0.0f});
  const std::uint8_t* sky = high.pixel(2, 2);
  EXPECT_EQ(sky[0], 140);  // 0.55 * 255 rounded
  EXPECT_EQ(sky[2], 242);
  const std::uint8_t* floorHigh = high.pixel(160, 170);
  const std::uint8_t* floorGrazing = grazing.pixel(160, 170);
  EXPECT_GT(floorHigh[1], floorGrazing[1] + 40) << "a floor lit from straight above must be much brighter";
  std::set<std::uint32_t> colours;
  for (int y = 0; y < high.height; ++y)
    for (int x = 0; x < high.width; ++x) {
      const std::uint8_t* p = high.pixel(x, y);
      colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
    }
  EXPECT_GT(colours.size(), 8u);
}

TEST_F(CubeSceneTest, ZeroSizeAndDegenerateInputsDrawNothingAndRaiseNoError) {
  const ShaderPreprocessor shaders = CubeScene::sceneShaders();
  const CubeScene scene(shaders, CubeScene::standardCubes());
  scene.draw(0, {0, 0}, kView, {0, 1, 0});
  const RenderTarget tiny({1, 1});
  scene.draw(tiny.framebuffer(), tiny.size(), Camera{{0, 5, 0}, {0, 5, 0}, 170.0f}, {0, 0, 0});
  const Image pixel = tiny.readPixels();
  EXPECT_EQ(pixel.pixel(0, 0)[3], 255);
}

}  // namespace
}  // namespace terrasol
