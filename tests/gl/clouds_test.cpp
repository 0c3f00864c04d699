// The cloud layer (render.clouds): the pixels that show a cloud are those whose ray meets a cloud texel
// of the CPU's map (core/cloud_layer.h), the same at the same tick and moved 100 ticks later; the
// ground darkens under them; and with clouds off no program carries them.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <glm/geometric.hpp>
#include <optional>

#include "assets/cloud_map.h"
#include "core/luma.h"
#include "core/paths.h"
#include "scene_render/scene_render.h"
#include "support/frame_probe.h"
#include "support/gl_test.h"
#include "support/pack_builder.h"

namespace terrasol {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "scenes";

CloudMap defaultClouds() {
  std::vector<PackProblem> problems;
  return loadCloudMap(testing::stackOf({resourcePackDir() / "default"}), problems);
}

float difference(const glm::vec4& a, const glm::vec4& b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

// The map's coverage (0..1) read bilinearly at a world point, texel centres at the cells' centres, as
// the GPU filters it for shadows.
double filteredCover(const CloudMap& map, glm::dvec3 at, std::int64_t ticks) {
  const double u = (at.x + cloudDrift(ticks, map.width)) / kCloudCellBlocks - 0.5;
  const double v = at.z / kCloudCellBlocks - 0.5;
  const auto i = static_cast<std::int64_t>(std::floor(u)), j = static_cast<std::int64_t>(std::floor(v));
  const double fu = u - static_cast<double>(i), fv = v - static_cast<double>(j);
  auto c = [&](std::int64_t di, std::int64_t dj) { return map.at(i + di, j + dj) / 255.0; };
  return (c(0, 0) * (1 - fu) + c(1, 0) * fu) * (1 - fv) + (c(0, 1) * (1 - fu) + c(1, 1) * fu) * fv;
}

// Whether a world point lies within `margin` cells of a cell's edge at `ticks`: its pixel's footprint
// may straddle two cells, and go either way.
bool nearCellEdge(const CloudMap& map, glm::dvec3 at, std::int64_t ticks, double margin) {
  const double u = (at.x + cloudDrift(ticks, map.width)) / kCloudCellBlocks, v = at.z / kCloudCellBlocks;
  return std::abs(u - std::round(u)) < margin || std::abs(v - std::round(v)) < margin;
}

struct Agreement {
  int compared = 0, agreeing = 0, clouds = 0;
  double share() const { return compared ? static_cast<double>(agreeing) / compared : 0.0; }
};

class CloudsTest : public testing::GlTest {
 protected:
  RenderedFrame draw(const SceneFile& scene) {
    RenderedFrame frame = testing::measuredFrame(scene);
    context_->checkErrors("rendering clouds");
    return frame;
  }

  // Sky pixels (none drawn in the clear frame `off`) whose view direction `expected` decides: which
  // show a cloud (differ from the clear sky) against whether it says they should.
  static Agreement skyAgreement(const RenderedFrame& on, const RenderedFrame& off,
                                const std::function<std::optional<bool>(glm::dvec3)>& expected) {
    Agreement a;
    const glm::ivec2 size = on.pixels.size;
    for (int y = 0; y < size.y; ++y)
      for (int x = 0; x < size.x; ++x) {
        const std::size_t i = static_cast<std::size_t>(y * size.x + x);
        if (off.pixels.depth[i] < 1.0f) continue;
        const std::optional<bool> cloud = expected(glm::normalize(testing::pixelPoint(on, x, y, 1.0f)));
        if (!cloud) continue;
        const bool shown = difference(on.pixels.scene[i], off.pixels.scene[i]) > 0.3f;
        ++a.compared;
        a.agreeing += shown == *cloud ? 1 : 0;
        a.clouds += shown ? 1 : 0;
      }
    return a;
  }

  // Sky pixels whose ray meets the flat layer within half its range, against the map at `ticks`.
  static Agreement skyAgainstMap(const RenderedFrame& on, const RenderedFrame& off, const SceneFile& scene,
                                 const CloudMap& map, std::int64_t ticks) {
    return skyAgreement(on, off, [&](glm::dvec3 dir) -> std::optional<bool> {
      if (dir.y <= 0.05) return std::nullopt;
      const double t = (kCloudBottom - scene.cameraPosition.y) / dir.y;
      if (t * glm::length(glm::dvec2(dir.x, dir.z)) > 0.5 * kCloudRange) return std::nullopt;
      const glm::dvec3 hit = scene.cameraPosition + dir * t;
      if (nearCellEdge(map, hit, ticks, 0.01 * t / kCloudCellBlocks + 0.02)) return std::nullopt;
      return cloudCovers(map, hit.x, hit.z, ticks);
    });
  }
};

TEST_F(CloudsTest, SkyShowsTheMapsCloudsTheSameAtATickAndMovedAHundredTicksLater) {
  SceneFile scene = loadScene(kScenes / "clouds_overhead.json");
  const CloudMap map = defaultClouds();
  const RenderedFrame on = draw(scene);
  EXPECT_EQ(on.nanPixels, 0u);
  EXPECT_TRUE(draw(scene).image.rgba == on.image.rgba) << "the same tick, the same sky";
  scene.clouds.mode = CloudMode::Off;
  const RenderedFrame off = draw(scene);

  const Agreement now = skyAgainstMap(on, off, scene, map, scene.time);
  std::printf("clouds at tick %lld: %d of %d sky pixels agree with the map (%d show a cloud)\n",
              static_cast<long long>(scene.time), now.agreeing, now.compared, now.clouds);
  ASSERT_GT(now.compared, 2000);
  EXPECT_GT(now.clouds, now.compared / 10) << "the view holds clouds";
  EXPECT_LT(now.clouds, now.compared * 9 / 10) << "and clear sky";
  EXPECT_GE(now.share(), 0.99);

  const std::int64_t later = scene.time + 100;
  scene.clouds.mode = CloudMode::Flat;
  scene.time = later;
  const RenderedFrame moved = draw(scene);
  scene.clouds.mode = CloudMode::Off;
  const RenderedFrame clear = draw(scene);
  const Agreement then = skyAgainstMap(moved, clear, scene, map, later);
  const Agreement stale = skyAgainstMap(on, off, scene, map, later);
  const int missed = then.compared - then.agreeing, staleMissed = stale.compared - stale.agreeing;
  std::printf("100 ticks later: %d of %d pixels disagree with the moved map; the earlier sky %d\n", missed,
              then.compared, staleMissed);
  EXPECT_GE(then.share(), 0.99);
  EXPECT_GE(staleMissed, 20) << "3 blocks of drift moves the clouds' edges across the view";
  EXPECT_GT(staleMissed, 4 * missed);
}

// Volumetric clouds fill a thicker slab with a density shaped by noise, so only the sky pixels whose
// ray crosses it where the map's cover is decided (at its bottom, middle and top alike) are compared:
// well inside a cloud they show one, well outside it the clear sky; the same at a tick, moved later.
TEST_F(CloudsTest, VolumetricCloudsStandWhereTheMapHasThem) {
  SceneFile scene = loadScene(kScenes / "clouds_overhead.json");
  const CloudMap map = defaultClouds();
  const auto against = [&](const RenderedFrame& on, const RenderedFrame& off, std::int64_t ticks) {
    return skyAgreement(on, off, [&](glm::dvec3 dir) -> std::optional<bool> {
      if (dir.y <= 0.1) return std::nullopt;
      double least = 1.0, most = 0.0;
      for (const double h : {0.0, 0.5, 1.0}) {
        const double t = (kCloudBottom + h * kCloudVolumeThickness - scene.cameraPosition.y) / dir.y;
        const double cover = filteredCover(map, scene.cameraPosition + dir * t, ticks);
        least = std::min(least, cover);
        most = std::max(most, cover);
      }
      if (least < 0.9 && most > 0.1) return std::nullopt;  // an edge: the noise decides
      return least >= 0.9;
    });
  };
  const auto drawWith = [&](CloudMode mode) {
    scene.clouds.mode = mode;
    return draw(scene);
  };
  const RenderedFrame on = drawWith(CloudMode::Volumetric), off = drawWith(CloudMode::Off);
  EXPECT_EQ(on.nanPixels, 0u);
  EXPECT_TRUE(drawWith(CloudMode::Volumetric).image.rgba == on.image.rgba) << "the same tick, the same sky";
  const Agreement now = against(on, off, scene.time);
  std::printf("volumetric clouds: %d of %d decided sky pixels agree with the map (%d show a cloud)\n",
              now.agreeing, now.compared, now.clouds);
  ASSERT_GT(now.compared, 1000);
  EXPECT_GT(now.clouds, now.compared / 10);
  EXPECT_LT(now.clouds, now.compared * 9 / 10);
  EXPECT_LE(now.compared - now.agreeing, now.compared / 1000);  // the map read 9 blocks off: 30

  scene.time += 1000;  // 30 blocks of drift
  const RenderedFrame clear = drawWith(CloudMode::Off);
  const Agreement then = against(drawWith(CloudMode::Volumetric), clear, scene.time),
                  stale = against(on, clear, scene.time);
  std::printf("1000 ticks later: %d of %d agree with the moved map, the earlier sky %d of %d\n",
              then.agreeing, then.compared, stale.agreeing, stale.compared);
  EXPECT_LE(then.compared - then.agreeing, then.compared / 1000);
  EXPECT_GE(stale.compared - stale.agreeing, 10 * (then.compared - then.agreeing) + 100) << "they moved";
}

TEST_F(CloudsTest, GroundDarkensWhereTheLayerHidesTheSun) {
  SceneFile scene = loadScene(kScenes / "clouds_overhead.json");
  scene.viewDistance = 4;
  scene.time = 4000;  // mid-morning: the shadows fall some 75 blocks west of the clouds casting them
  scene.cameraPosition.y = 110.0;  // over the ground, looking down on some 60 blocks of it
  scene.cameraLookAt = scene.cameraPosition + glm::dvec3(1.0, -20.0, 0.0);
  const CloudMap map = defaultClouds();
  const RenderedFrame shaded = draw(scene);
  EXPECT_EQ(shaded.nanPixels, 0u);
  scene.clouds.shadows = false;
  const RenderedFrame lit = draw(scene);
  const glm::dvec3 toLight = glm::dvec3(shaded.geometry.toLight);
  ASSERT_GT(toLight.y, 0.5);
  int compared = 0, agreeing = 0, darkened = 0;
  const glm::ivec2 size = shaded.pixels.size;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * size.x + x);
      if (lit.pixels.depth[i] >= 1.0f) continue;
      const glm::dvec3 relative = testing::pixelPoint(lit, x, y, lit.pixels.depth[i]);
      if (glm::length(glm::dvec2(relative.x, relative.z)) > 0.75 * scene.viewDistance * 16.0)
        continue;  // fog
      const glm::dvec3 ground = scene.cameraPosition + relative;
      // Where the sun's ray crosses the middle of the layer (lib/clouds.glsl reads the map there).
      const glm::dvec3 above =
          ground + toLight * ((kCloudBottom + 0.5 * kCloudThickness - ground.y) / toLight.y);
      const double cover = filteredCover(map, above, scene.time);
      if (std::abs(cover - 0.5) < 0.25) continue;  // the shadow's soft edge
      const double ratio =
          luma(glm::vec3(shaded.pixels.scene[i])) / std::max(luma(glm::vec3(lit.pixels.scene[i])), 1e-6f);
      const bool dark = ratio < 0.8;
      ++compared;
      agreeing += dark == (cover > 0.5) ? 1 : 0;
      darkened += dark ? 1 : 0;
    }
  std::printf("cloud shadows: %d of %d ground pixels agree with the map (%d darkened)\n", agreeing, compared,
              darkened);
  ASSERT_GT(compared, 1000);
  EXPECT_GT(darkened, compared / 10);
  EXPECT_GE(static_cast<double>(agreeing) / compared, 0.98);
}

TEST_F(CloudsTest, WaterMirrorsThem) {
  SceneFile scene = loadScene(kScenes / "clouds_overhead.json");
  scene.edits.push_back({SceneEdit::Kind::Fill, {-40, 60, -40}, {40, 63, 40}, "water", "test", -1});
  scene.cameraPosition = {0.5, 66.0, 0.5};
  scene.cameraLookAt = {20.5, 50.0, 0.5};  // down at the water: its reflected rays climb to the layer
  scene.clouds.shadows = false;            // only the reflection differs
  const RenderedFrame on = draw(scene);
  scene.clouds.mode = CloudMode::Off;
  const RenderedFrame off = draw(scene);
  std::size_t water = 0, differing = 0;
  for (std::size_t i = 0; i < on.pixels.scene.size(); ++i) {
    if (off.pixels.depth[i] >= 1.0f) continue;
    ++water;
    differing += difference(on.pixels.scene[i], off.pixels.scene[i]) > 0.05f ? 1 : 0;
  }
  std::printf("clouds change %zu of %zu water pixels\n", differing, water);
  ASSERT_GT(water, on.pixels.scene.size() / 2);
  EXPECT_GT(differing, water / 10);
  EXPECT_EQ(on.nanPixels, 0u);
}

TEST_F(CloudsTest, OffLeavesThemOutOfEveryProgram) {
  SceneFile scene = loadScene(kScenes / "clouds_overhead.json");
  scene.clouds.mode = CloudMode::Off;
  SceneRenderer off(scene);
  for (const std::string& v : off.renderer().shaderVariants())
    EXPECT_EQ(v.find("CLOUD"), std::string::npos) << v;
  scene.clouds.mode = CloudMode::Fancy;
  SceneRenderer on(scene);
  const auto& variants = on.renderer().shaderVariants();
  EXPECT_EQ(
      std::count_if(variants.begin(), variants.end(),
                    [](const std::string& v) { return v.find("+CLOUDS+CLOUDS_FANCY") != std::string::npos; }),
      std::count_if(variants.begin(), variants.end(), [](const std::string& v) {
        return v.starts_with("sky") || v.starts_with("lighting") || v.starts_with("translucent") ||
               v.starts_with("reflection+") || v.starts_with("surface_reflection");
      }));
}

}  // namespace
}  // namespace terrasol
