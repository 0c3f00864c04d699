// Light shafts and height fog (render.shafts, render.fog): the shaft through a roof's hole lights the
// haze exactly where the view ray crosses the sunlit column (from the shadow map), adds light and never
// takes it, and the pass is left out, with no pixel changed, when it is off.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>

#include "scene_render/scene_render.h"
#include "support/frame_probe.h"
#include "support/gl_test.h"

namespace terrasol {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "scenes";

float sum(const glm::vec4& p) {
  return p.r + p.g + p.b;
}

// Whether the segment from `a` to `b` passes through the box [lo, hi].
bool crosses(glm::dvec3 a, glm::dvec3 b, glm::dvec3 lo, glm::dvec3 hi) {
  double t0 = 0.0, t1 = 1.0;
  const glm::dvec3 d = b - a;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(d[i]) < 1e-12) {
      if (a[i] < lo[i] || a[i] > hi[i]) return false;
      continue;
    }
    double ta = (lo[i] - a[i]) / d[i], tb = (hi[i] - a[i]) / d[i];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 < t1;
}

class ShaftsTest : public testing::GlTest {
 protected:
  RenderedFrame draw(const SceneFile& scene) {
    RenderedFrame frame = testing::measuredFrame(scene);
    context_->checkErrors("rendering shafts");
    return frame;
  }
};

TEST_F(ShaftsTest, TheShaftLightsTheHazeWhereTheViewCrossesTheSunlitColumn) {
  SceneFile scene = loadScene(kScenes / "shafts_roof_hole.json");
  const RenderedFrame on = draw(scene);
  EXPECT_EQ(on.nanPixels, 0u);
  scene.shafts.enabled = false;
  const RenderedFrame off = draw(scene);
  // The hole's column, straight down from the roof at noon, inset half a block from its edges.
  const glm::dvec3 lo(0.5, 64.0, 0.5), hi(1.5, 77.0, 1.5);
  double across = 0.0, beside = 0.0, taken = 0.0;
  int acrossCount = 0, besideCount = 0;
  const glm::ivec2 size = on.pixels.size;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * size.x + x);
      const float depth = off.pixels.depth[i];
      if (depth >= 1.0f) continue;
      const glm::dvec3 surface = scene.cameraPosition + testing::pixelPoint(off, x, y, depth);
      const double added = sum(on.pixels.scene[i]) - sum(off.pixels.scene[i]);
      taken = std::min(taken, added);
      // Rays that graze the column's widened box go either way: left out.
      if (crosses(scene.cameraPosition, surface, lo, hi)) {
        across += added;
        ++acrossCount;
      } else if (!crosses(scene.cameraPosition, surface, lo - 1.0, hi + 1.0)) {
        beside += added;
        ++besideCount;
      }
    }
  ASSERT_GT(acrossCount, 100);
  ASSERT_GT(besideCount, 1000);
  across /= acrossCount;
  beside /= besideCount;
  std::printf(
      "the shaft adds %.4f a pixel (rgb summed) where the view crosses the sunlit column, %.4f "
      "beside it\n",
      across, beside);
  EXPECT_GT(across, 0.05);
  EXPECT_GT(across, 10.0 * beside);
  EXPECT_GE(taken, -1e-3) << "shafts add light, never take it";
}

TEST_F(ShaftsTest, LeftOutWithNoPixelChangedWhenOff) {
  SceneFile scene = loadScene(kScenes / "shafts_roof_hole.json");
  scene.shafts.enabled = false;
  SceneRenderer renderer(scene);
  const RenderedFrame frame = renderer.renderFrame(0);
  const auto& skipped = frame.stats.passesSkipped;
  EXPECT_TRUE(std::any_of(skipped.begin(), skipped.end(), [](const auto& s) { return s.pass == "shafts"; }));
  for (const std::string& v : renderer.renderer().shaderVariants())
    EXPECT_FALSE(v.starts_with("shafts")) << v;
  scene.fog.density = 0.0f;  // and without fog no program carries it
  SceneRenderer clear(scene);
  for (const std::string& v : clear.renderer().shaderVariants())
    EXPECT_EQ(v.find("HEIGHT_FOG"), std::string::npos) << v;
}

}  // namespace
}  // namespace terrasol
