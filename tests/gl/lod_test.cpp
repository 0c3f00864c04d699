// Far terrain (render.lod): full detail hides the tiles beneath it, far terrain adds ground beyond it
// and casts the sun's shadow, no sky shows through it, and its error against full detail out to its far edge
// is measured against that of halving the resolution.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <optional>

#include "scene_render/lod_error.h"
#include "scene_render/scene_render.h"
#include "support/gl_test.h"

namespace terrasol {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "scenes";

class LodTest : public testing::GlTest {};

// The horizontal distance to the surface at G-buffer pixel `i`, or none for sky.
std::optional<double> distanceAt(const RenderedFrame& f, std::size_t i) {
  const float depth = f.pixels.depth[i];
  if (depth >= 1.0f) return std::nullopt;
  const glm::ivec2 size = f.pixels.size;
  const int x = static_cast<int>(i) % size.x, y = static_cast<int>(i) / size.x;
  const glm::vec4 p = f.geometry.inverseViewProjection * glm::vec4((x + 0.5f) / size.x * 2.0f - 1.0f,
                                                                   (y + 0.5f) / size.y * 2.0f - 1.0f,
                                                                   depth * 2.0f - 1.0f, 1.0f);
  return glm::length(glm::dvec2(p.x, p.z) / static_cast<double>(p.w));
}

RenderedFrame drawn(const SceneFile& scene, int frame = 0) {
  SceneRenderer renderer(scene);
  FrameRequest request;
  request.readBack = true;
  return renderer.renderFrame(frame, request);
}

// Where full detail draws ground, far terrain moves no surface: the cells it covers sink beneath it.
// (Looking down the ridge, so full detail fills much of the frame.)
TEST_F(LodTest, FullDetailHidesTheTilesBeneathItAndFarTerrainFillsTheSkyBeyond) {
  SceneFile scene =
      loadScene(kScenes / "paths" / "lod_mountain.json", {"camera_path.keyframes.0.look_at=[-40, 130, 10]"});
  const RenderedFrame far = drawn(scene);
  scene.lod.distance = 0;
  const RenderedFrame near = drawn(scene);
  ASSERT_EQ(far.pixels.depth.size(), near.pixels.depth.size());
  std::size_t ground = 0, moved = 0, added = 0;
  for (std::size_t i = 0; i < near.pixels.depth.size(); ++i) {
    const std::optional<double> n = distanceAt(near, i), f = distanceAt(far, i);
    if (n) {
      ++ground;
      moved +=
          !f || std::abs(*f - *n) > 1e-3 * *n + 0.01 ? 1 : 0;  // the far plane differs: depth's precision
    } else {
      added += f ? 1 : 0;
    }
  }
  std::printf("full detail's %zu ground pixels, %zu moved; far terrain adds %zu\n", ground, moved, added);
  EXPECT_GT(ground, 1000u);
  EXPECT_EQ(moved, 0u);
  EXPECT_GT(added, near.pixels.depth.size() / 4) << "the plains, lakes and sea below the ridge";
  EXPECT_GT(far.stats.lodTilesDrawn, 0);
  context_->checkErrors("far terrain");
}

// Against full detail out to the far edge (12 chunks past 3): no sky through the terrain, and the
// error in the band far terrain draws reported beside that of the truth drawn at half resolution.
TEST_F(LodTest, NoSkyShowsThroughTheFarTerrainAndItsErrorIsMeasured) {
  SceneFile scene = loadScene(kScenes / "paths" / "lod_mountain.json");
  scene.lod.distance = 12;
  const RenderedFrame far = drawn(scene);
  SceneRenderer truthRenderer(lodTruthScene(scene));
  FrameRequest exact;
  exact.readBack = true;
  const RenderedFrame truth = truthRenderer.renderFrame(0, exact);
  FrameRequest half;
  half.renderScale = 0.5f;
  const Image halfImage = truthRenderer.renderFrame(0, half).image;
  const LodError e = measureLodError(far, truth, scene.viewDistance * double(kChunkSize),
                                     scene.lod.distance * double(kChunkSize), &halfImage);
  std::printf("band %zu px: mean %.4f p99 %.4f (half resolution %.4f, %.4f); holes %zu, sky differs %zu\n",
              e.band, e.mean, e.p99, *e.halfResolutionMean, *e.halfResolutionP99, e.holes, e.skyDiffers);
  EXPECT_GT(e.band, 5000u);
  EXPECT_EQ(e.holes, 0u);
  EXPECT_LT(e.mean, 2.0 * *e.halfResolutionMean) << "within twice halving the resolution's error";
  EXPECT_LT(e.skyDiffers, e.band / 20) << "silhouettes near the truth's";
  context_->checkErrors("far terrain's truth");
}

// Far terrain casts into the shadow map: late in the day, with the map reaching 160 blocks, the far
// ground inside that reach lies darker behind its ridges than when far terrain casts nothing (the
// sections alone cast no shadow that far out).
TEST_F(LodTest, FarTerrainCastsTheSunsShadow) {
  SceneFile scene = loadScene(kScenes / "paths" / "lod_mountain.json",
                              {"render.shadow.distance=160", "camera_path.keyframes.0.look_at=[-40, 130, 10]",
                               "camera_path.keyframes.0.time=11000"});
  const RenderedFrame far = drawn(scene);
  scene.lod.shadows = false;
  const RenderedFrame near = drawn(scene);
  const glm::ivec2 size = near.pixels.size;
  ASSERT_EQ(near.image.width, size.x);
  std::size_t ground = 0, shaded = 0;  // far terrain's, inside the map's reach
  for (std::size_t i = 0; i < near.pixels.depth.size(); ++i) {
    const std::optional<double> d = distanceAt(near, i);
    if (!d || *d < scene.viewDistance * double(kChunkSize) || *d > scene.shadow.distance) continue;
    ++ground;
    const int x = static_cast<int>(i) % size.x, y = size.y - 1 - static_cast<int>(i) / size.x;
    const auto luma = [&](const Image& im) {
      const std::uint8_t* p = im.pixel(x, y);
      return p[0] + p[1] + p[2];
    };
    shaded += luma(far.image) + 30 < luma(near.image) ? 1 : 0;
  }
  std::printf("%zu of far terrain's %zu pixels in the map's reach darker when it casts; %d tiles cast\n",
              shaded, ground, far.stats.lodShadowCasters);
  EXPECT_GT(far.stats.lodShadowCasters, 0);
  EXPECT_GT(ground, 5000u);
  EXPECT_GT(shaded, ground / 10);
  context_->checkErrors("far terrain's shadow");
}

}  // namespace
}  // namespace terrasol
