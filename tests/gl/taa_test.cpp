// Temporal anti-aliasing (render.antialiasing "taa") against supersampled truth: a still frame nearer
// it than none (fails when the jitter is not undone: the image shifts), a recoloured wall that leaves
// no ghost (fails without the history clip), reconstruction at a render scale, the same pixels on every
// run, and the pass left out when off.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "scene_render/aa_error.h"
#include "scene_render/scene_render.h"
#include "support/gl_test.h"

namespace terrasol {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "scenes";

class TaaTest : public testing::GlTest {
 protected:
  // Every frame of the scene's path, in order (TAA's history carries from one to the next).
  std::vector<Image> frames(const SceneFile& scene) {
    SceneRenderer renderer(scene);
    std::vector<Image> out;
    for (int i = 0; i < renderer.frames(); ++i) out.push_back(renderer.renderFrame(i).image);
    context_->checkErrors("rendering with TAA");
    return out;
  }
  // The same frames drawn 3 x 3 times larger with no anti-aliasing, averaged down.
  std::vector<Image> truths(SceneFile scene) {
    scene.width *= 3;
    scene.height *= 3;
    scene.antialiasing = Antialiasing::None;
    scene.renderScale = 1.0f;
    std::vector<Image> out;
    for (const Image& big : frames(scene)) out.push_back(downsample(big, 3));
    return out;
  }
};

TEST_F(TaaTest, AStillFrameIsNearerItsTruthThanWithoutAntialiasing) {
  SceneFile scene = loadScene(kScenes / "shadow_noon.json");
  const Image truth = truths(scene).front();
  const AaError none = measureAaError(frames(scene).front(), truth);
  scene.antialiasing = Antialiasing::Taa;
  const AaError taa = measureAaError(frames(scene).front(), truth);
  std::printf("aa_error against 3x3 supersampling: none mean %.4f edges over %.1f %%, taa %.4f, %.1f %%\n",
              none.mean, none.edgeOverPct, taa.mean, taa.edgeOverPct);
  EXPECT_GT(none.edgePixels, 500u) << "a scene with edges";
  EXPECT_LT(taa.mean, 0.92 * none.mean);
  EXPECT_LT(taa.edgeOverPct, 0.85 * none.edgeOverPct);
}

// At two thirds of the size, TAA rebuilds detail from the jittered frames: nearer the truth than the
// same scale upscaled without it.
TEST_F(TaaTest, ReconstructsDetailAtARenderScale) {
  SceneFile scene = loadScene(kScenes / "shadow_noon.json");
  const Image truth = truths(scene).front();
  scene.renderScale = 0.67f;
  const AaError none = measureAaError(frames(scene).front(), truth);
  scene.antialiasing = Antialiasing::Taa;
  const AaError taa = measureAaError(frames(scene).front(), truth);
  std::printf("at scale 0.67: none mean %.4f edges over %.1f %%, taa %.4f, %.1f %%\n", none.mean,
              none.edgeOverPct, taa.mean, taa.edgeOverPct);
  EXPECT_LT(taa.mean, 0.9 * none.mean);
  EXPECT_LT(taa.edgeOverPct, 0.8 * none.edgeOverPct);
}

// The wall keeps its place as it turns from stone to gold, so the distance check keeps the history:
// only the clip to this frame's samples stops the stone from lingering.
TEST_F(TaaTest, ARecolouredSurfaceLeavesNoGhost) {
  const SceneFile scene = loadScene(kScenes / "paths" / "taa_wall_recoloured.json");
  const std::vector<Image> truth = truths(scene);
  const std::vector<Image> drawn = frames(scene);
  ASSERT_EQ(drawn.size(), 8u);
  const int changedAt = 2;  // the scene's at_frame
  const int i = changedAt + kGhostFrames - 1;
  const GhostError ghost = measureGhosting(drawn[i], truth[i], truth[i - 3], truth[i - 4]);
  std::printf("%zu pixels recoloured; %.1f %% keep over 10 %% of the stone after 4 frames (p99 %.3f)\n",
              ghost.changedPixels, ghost.overPct, ghost.p99);
  EXPECT_GT(ghost.changedPixels, 1000u);
  EXPECT_LT(ghost.overPct, 15.0);
}

// Water changes by itself from frame to frame: with its history weighed like a still wall's, TAA
// showed a walk along a lake as a blur in time, further from its truth than no anti-aliasing (22 %
// at full scale, 6 % at 0.67). The reactive mask keeps this frame's share at half on water.
TEST_F(TaaTest, RipplingWaterStaysNearerItsTruthThanWithoutAntialiasing) {
  SceneFile scene = loadScene(kScenes / "paths" / "taa_lake_walk.json");
  const std::vector<Image> truth = truths(scene);
  const auto meanError = [&](Antialiasing aa, float scale) {
    scene.antialiasing = aa;
    scene.renderScale = scale;
    const std::vector<Image> drawn = frames(scene);
    const std::size_t first = 4;  // past the history's still start
    double mean = 0.0;
    for (std::size_t i = first; i < truth.size(); ++i)
      mean += measureAaError(drawn[i], truth[i]).mean / static_cast<double>(truth.size() - first);
    return mean;
  };
  for (const float scale : {1.0f, 0.67f}) {
    const double taa = meanError(Antialiasing::Taa, scale), none = meanError(Antialiasing::None, scale);
    std::printf("scale %.2f, frames 4 on: none mean %.5f, taa %.5f\n", scale, none, taa);
    EXPECT_LT(taa, (scale < 1.0f ? 0.95 : 1.0) * none) << "at scale " << scale;
  }
}

TEST_F(TaaTest, AStillSceneGivesTheSamePixelsOnEveryRun) {
  SceneFile scene = loadScene(kScenes / "water_glass.json");
  scene.antialiasing = Antialiasing::Taa;
  EXPECT_TRUE(frames(scene).front().rgba == frames(scene).front().rgba);
}

TEST_F(TaaTest, LeftOutWhenOff) {
  for (const Antialiasing aa : {Antialiasing::None, Antialiasing::Fxaa}) {
    SceneFile scene = loadScene(kScenes / "shadow_noon.json");
    scene.antialiasing = aa;
    SceneRenderer renderer(scene);
    const RenderedFrame frame = renderer.renderFrame(0);
    const auto& skipped = frame.stats.passesSkipped;
    EXPECT_TRUE(std::any_of(skipped.begin(), skipped.end(), [](const auto& s) { return s.pass == "taa"; }))
        << kAntialiasingModes.nameOf(aa);
  }
}

}  // namespace
}  // namespace terrasol
