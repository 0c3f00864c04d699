// Bloom (render.bloom): light moved, not added (the frame's energy within 2 % with it on), a glow past
// the emitter's faces, and the pass left out with no pixel changed when off.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "scene_render/scene_render.h"
#include "support/gl_test.h"
#include "support/golden.h"

namespace terrasol {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "scenes";

class BloomTest : public testing::GlTest {
 protected:
  RenderedFrame draw(const SceneFile& scene) {
    SceneRenderer renderer(scene);
    FrameRequest request;
    request.readBack = true;  // the lit scene, linear HDR, after bloom
    RenderedFrame frame = renderer.renderFrame(0, request);
    context_->checkErrors("rendering with bloom");
    return frame;
  }
  static double energy(const GBufferPixels& pixels) {
    double sum = 0.0;
    for (const glm::vec4& p : pixels.scene) sum += p.r + p.g + p.b;
    return sum;
  }
};

TEST_F(BloomTest, MovesLightWithoutAddingAny) {
  SceneFile scene = loadScene(kScenes / "bloom_glowstone.json");
  const RenderedFrame on = draw(scene);
  scene.bloom.enabled = false;
  const RenderedFrame off = draw(scene);
  const double ratio = energy(on.pixels) / energy(off.pixels);
  std::printf("the frame's energy with bloom / without: %.4f\n", ratio);
  EXPECT_NEAR(ratio, 1.0, 0.02);
  EXPECT_EQ(on.nanPixels, 0u);

  // Just past the emitters' faces (within 4 pixels of one brighter than white) bloom brings light in;
  // far from them it moves about as much out as in.
  const GBufferPixels& a = on.pixels;
  const GBufferPixels& b = off.pixels;
  const auto sum = [](const glm::vec4& p) { return p.r + p.g + p.b; };
  const int w = b.size.x, h = b.size.y;
  std::vector<int> distance(b.scene.size(), 1 << 20);  // to the nearest bright pixel, in pixels (max norm)
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (sum(b.scene[static_cast<std::size_t>(y * w + x)]) < 3.0f) continue;
      for (int v = 0; v < h; ++v)
        for (int u = 0; u < w; ++u) {
          int& d = distance[static_cast<std::size_t>(v * w + u)];
          d = std::min(d, std::max(std::abs(u - x), std::abs(v - y)));
        }
    }
  double nearAdded = 0.0, farAdded = 0.0;
  int nearCount = 0, farCount = 0;
  for (std::size_t i = 0; i < b.scene.size(); ++i) {
    const double added = sum(a.scene[i]) - sum(b.scene[i]);
    if (distance[i] >= 1 && distance[i] <= 4) {
      nearAdded += added;
      ++nearCount;
    } else if (distance[i] > 24) {
      farAdded += added;
      ++farCount;
    }
  }
  ASSERT_GT(nearCount, 20);
  ASSERT_GT(farCount, 1000);
  nearAdded /= nearCount;
  farAdded /= farCount;
  std::printf("light bloom adds just past the emitters %.4f a pixel (of rgb summed), far from them %.4f\n",
              nearAdded, farAdded);
  EXPECT_GT(nearAdded, 0.01);  // of light near 1 a pixel
  EXPECT_GT(nearAdded, 10.0 * std::abs(farAdded));
}

TEST_F(BloomTest, LeftOutWithNoPixelChangedWhenOff) {
  SceneFile scene = loadScene(kScenes / "bloom_glowstone.json");
  scene.bloom.enabled = false;
  SceneRenderer renderer(scene);
  const RenderedFrame frame = renderer.renderFrame(0);
  const auto& skipped = frame.stats.passesSkipped;
  EXPECT_TRUE(std::any_of(skipped.begin(), skipped.end(), [](const auto& s) { return s.pass == "bloom"; }));
  scene.bloom = {true, 0.0f};  // on at no strength: left out too
  SceneRenderer none(scene);
  EXPECT_TRUE(none.renderFrame(0).image.rgba == frame.image.rgba);
}

// With nothing bright in view (daylight hills with the sun behind the camera, no emissive texture,
// no water or smooth block) bloom is left out; glowstone in view, or the sun, brings it back.
TEST_F(BloomTest, LeftOutWhenNothingInViewIsBright) {
  auto skippedBecause = [](const RenderedFrame& frame) {
    for (const auto& s : frame.stats.passesSkipped)
      if (s.pass == "bloom") return s.why;
    return std::string();
  };
  SceneFile hills = loadScene(kScenes / "noon_terrain.json");
  hills.bloom.enabled = true;
  hills.time = 3000;  // the sun high in the east, the camera looking steeply down at the hills
  hills.cameraLookAt = glm::dvec3(0.0, 40.0, 0.0);
  EXPECT_EQ(skippedBecause(SceneRenderer(hills).renderFrame(0)), "nothing in view is bright");
  hills.time = 500;                                                        // just risen, low in the east
  hills.cameraLookAt = hills.cameraPosition + glm::dvec3(40.0, 5.0, 0.0);  // east, at the sun
  EXPECT_EQ(skippedBecause(SceneRenderer(hills).renderFrame(0)), "") << "the sun's glow in view";
  EXPECT_EQ(skippedBecause(SceneRenderer(loadScene(kScenes / "bloom_glowstone.json")).renderFrame(0)), "")
      << "glowstone in view";
}

}  // namespace
}  // namespace terrasol
