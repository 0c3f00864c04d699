// The deferred renderer end to end: scene files from tests/scenes rendered headless and compared with
// goldens (each looked at before it was committed), every debug view, reproducibility, and no NaN or
// Inf in any float target.

#include "scene_render/scene_render.h"

#include <cstdio>
#include <filesystem>
#include <limits>

#include "scene_render/aa_error.h"
#include "support/gl_test.h"
#include "support/golden.h"
#include "support/test_data.h"

namespace terrasol {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "scenes";

class SceneRenderTest : public testing::GlTest {
 protected:
  Image render(const SceneFile& scene) {
    SceneRenderer renderer(scene);
    const Image image = renderer.render();
    context_->checkErrors("rendering a scene");
    return image;
  }
};

class SceneGoldenTest : public SceneRenderTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(SceneGoldenTest, MatchesGolden) {
  const std::string name = GetParam();
  // These scenes show real third-party packs and models ($TERRASOL_TESTDATA in their paths).
  if (readTextFile(kScenes / (name + ".json")).find("$TERRASOL_TESTDATA") != std::string::npos) {
    TERRASOL_SKIP_WITHOUT_TEST_DATA();
  }
  const SceneFile scene = loadScene(kScenes / (name + ".json"));
  EXPECT_TRUE(testing::matchesGolden(render(scene), "scene_" + name));
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneGoldenTest,
                         ::testing::Values("noon_terrain", "sunset_terrain", "night_cave_torches",
                                           "metal_emissive", "stone_closeup", "water_glass",
                                           "pack_pixel_perfection", "shadow_noon", "shadow_low_sun",
                                           "shadow_moon", "shadow_forest", "shadow_cave_mouth",
                                           "props_beside_blocks", "props_night_torch", "mirror_floor",
                                           "lake_pillar", "lake_sunset", "flooded_cave", "shapes",
                                           "bloom_glowstone", "clouds_fancy", "shafts_roof_hole"));

TEST_F(SceneRenderTest, EveryDebugViewMatchesItsGolden) {
  SceneRenderer renderer(loadScene(kScenes / "metal_emissive.json"));
  for (std::size_t v = 1; v < kDebugViews.size(); ++v) {
    if (showsReflections(static_cast<DebugView>(v)))
      continue;  // reflections are off here (reflection_test.cpp)
    const Image image = renderer.render(static_cast<DebugView>(v));
    const std::string name(kDebugViews[v]);
    context_->checkErrors(name.c_str());
    EXPECT_TRUE(testing::matchesGolden(image, "scene_debug_" + name));
  }
}

// GGX is a real alternative lobe: a smooth metal close up looks different with it, and stays finite.
TEST_F(SceneRenderTest, GgxSpecularIsAVariantOfItsOwn) {
  SceneFile scene = loadScene(kScenes / "metal_emissive.json");
  const Image blinnPhong = render(scene);
  scene.specular = SpecularModel::Ggx;
  const Image ggx = render(scene);
  EXPECT_GT(compareImages(ggx, blinnPhong, {}).failingPixels, 0);
  EXPECT_TRUE(testing::matchesGolden(ggx, "scene_metal_emissive_ggx"));
}

// Stars: single bright pixels on the night sky, none by day (sky.frag adds them where the sky shows).
TEST_F(SceneRenderTest, StarsShowOnTheNightSkyAndNotByDay) {
  SceneFile scene = loadScene(kScenes / "shadow_moon.json");
  scene.cameraLookAt = scene.cameraPosition + glm::dvec3(0.3, 1.0, 0.2);  // up, away from the moon
  const auto stars = [](const Image& image) {
    int count = 0;
    for (int y = 1; y + 1 < image.height; ++y)
      for (int x = 1; x + 1 < image.width; ++x) {
        const auto grey = [&](int px, int py) {
          const std::uint8_t* p = image.pixel(px, py);
          return (p[0] + p[1] + p[2]) / 3;
        };
        const int around = (grey(x - 1, y) + grey(x + 1, y) + grey(x, y - 1) + grey(x, y + 1)) / 4;
        if (grey(x, y) > around + 60) ++count;
      }
    return count;
  };
  EXPECT_GT(stars(render(scene)), 20) << "midnight";
  scene.time = 6000;
  EXPECT_EQ(stars(render(scene)), 0) << "noon";
}

// FXAA brings a frame nearer its supersampled truth (render.antialiasing), and changes nothing when off.
TEST_F(SceneRenderTest, FxaaBringsTheFrameNearerItsSupersampledTruth) {
  SceneFile scene = loadScene(kScenes / "shadow_noon.json");
  scene.width = 160;
  scene.height = 90;
  SceneFile big = scene;
  big.width *= 3;
  big.height *= 3;
  const Image truth = downsample(render(big), 3);
  const AaError none = measureAaError(render(scene), truth);
  scene.antialiasing = Antialiasing::Fxaa;
  const AaError fxaa = measureAaError(render(scene), truth);
  EXPECT_LT(fxaa.mean, none.mean);
  EXPECT_LT(fxaa.edgeOverPct, none.edgeOverPct);
  EXPECT_GT(none.edgePixels, 500u) << "a scene with edges";
  std::printf("aa_error against 3x3 supersampling: none mean %.4f edges over %.1f %%, fxaa %.4f, %.1f %%\n",
              none.mean, none.edgeOverPct, fxaa.mean, fxaa.edgeOverPct);
}

TEST_F(SceneRenderTest, TheSameSceneRendersToIdenticalPixelsTwice) {
  const SceneFile scene = loadScene(kScenes / "water_glass.json");
  const Image first = render(scene);
  const Image second = render(scene);
  EXPECT_TRUE(first.rgba == second.rgba);
}

// The counter the NaN checks rely on finds a bad value in any of the float targets.
TEST(NonFinitePixels, CountsPixelsWithNanOrInfInAnyFloatTarget) {
  GBufferPixels g;
  g.size = {2, 2};
  g.depth.assign(4, 0.5f);
  g.normals.assign(4, glm::vec4(0.0f));
  g.scene.assign(4, glm::vec4(1.0f));
  g.light.assign(4, glm::u8vec4(0));
  EXPECT_EQ(nonFinitePixels(g), 0u);
  g.scene[1].a = std::numeric_limits<float>::quiet_NaN();
  g.normals[2].y = std::numeric_limits<float>::infinity();
  g.depth[3] = -std::numeric_limits<float>::infinity();
  EXPECT_EQ(nonFinitePixels(g), 3u);
}

// The stiff cases for the lighting maths: the sun exactly at the horizon and overhead, the camera
// looking straight down and straight up, fov 1 and 170, a 1x1 target.
TEST_F(SceneRenderTest, NoFloatTargetHoldsNanOrInf) {
  SceneFile base = loadScene(kScenes / "metal_emissive.json");
  base.width = 64;
  base.height = 36;
  struct Case {
    const char* name;
    std::int64_t time;
    glm::dvec3 lookAt;
    float fov;
    glm::ivec2 size;
  };
  const Case cases[] = {
      {"sunrise", 0, {5, 64.5, 0}, 70, {64, 36}},
      {"sunset", 12000, {5, 64.5, 0}, 70, {64, 36}},
      {"noon, straight down", 6000, {5, 0, 7}, 70, {64, 36}},
      {"midnight, straight up", 18000, {5, 300, 7}, 70, {64, 36}},
      {"fov 1", 6000, {5, 64.5, 0}, 1, {64, 36}},
      {"fov 170", 6000, {5, 64.5, 0}, 170, {64, 36}},
      {"1x1", 6000, {5, 64.5, 0}, 70, {1, 1}},
  };
  for (const Case& c : cases) {
    SceneFile scene = base;
    scene.time = c.time;
    scene.cameraLookAt = c.lookAt;
    scene.fov = c.fov;
    scene.width = c.size.x;
    scene.height = c.size.y;
    SceneRenderer renderer(scene);
    renderer.render();
    const GBuffer* g = renderer.renderer().gbuffer();
    ASSERT_NE(g, nullptr);
    EXPECT_EQ(nonFinitePixels(g->read()), 0u) << c.name << ": lit scene, normals or depth";
    context_->checkErrors(c.name);
  }
}

// The real third-party pack stacked over the default one shows its own textures.
// A window minimised to 0 x 0 asks for frames of no size: nothing is drawn, no GL error, and the next
// frame at a real size is whole.
TEST_F(SceneRenderTest, AZeroSizedFrameDrawsNothingAndRaisesNoGlError) {
  SceneFile scene = loadScene(kScenes / "noon_terrain.json");
  scene.width = 64;
  scene.height = 36;
  SceneRenderer renderer(scene);
  renderer.draw(0, 0, {0, 0});
  renderer.draw(0, 0, {0, 5});
  context_->checkErrors("a zero-sized frame");
  FrameRequest request;
  request.checkNan = true;
  const RenderedFrame frame = renderer.renderFrame(0, request);
  context_->checkErrors("the frame after it");
  EXPECT_EQ(frame.nanPixels, 0u);
  EXPECT_EQ(frame.image.width, 64);
}

TEST_F(SceneRenderTest, AStackedPackReplacesTheDefaultTextures) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  SceneFile stacked = loadScene(kScenes / "pack_pixel_perfection.json");
  SceneFile plain = stacked;
  plain.packs.resize(1);
  const ImageComparison c = compareImages(render(plain), render(stacked), {});
  EXPECT_GT(c.failingPercent, 5.0) << "the blocks must look different with the pack on top";
}

}  // namespace
}  // namespace terrasol
