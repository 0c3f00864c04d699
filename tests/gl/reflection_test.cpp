// Screen-space reflections (render/passes/reflection_pass.h): a polished iron floor mirrors the
// blocks standing on it and the sky above, water mirrors the shore and refracts what lies below, a
// sealed cave's floor reflects no sky, the surface is seen from below under water, and the pass is
// left out, changing no pixel, where it has nothing to do.

#include <filesystem>
#include <stdexcept>

#include "scene_render/reflection_truth.h"
#include "scene_render/scene_render.h"
#include "support/frame_probe.h"
#include "support/gl_test.h"
#include "support/shader_variants.h"

namespace terrasol {
namespace {

using testing::brightness;
using testing::colourAt;

const std::filesystem::path kScenes = std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "scenes";

class ReflectionTest : public testing::GlTest {};

bool identical(const Image& a, const Image& b) {
  return compareImages(a, b, {0.0f, 0.0f}).matches;
}

// The scene's first frame against the ray-traced truth (scene_render/reflection_truth.h).
ReflectionError reflectionErrorOf(const SceneFile& scene) {
  SceneRenderer renderer(scene);
  FrameRequest request;
  request.readBack = true;
  const RenderedFrame frame = renderer.renderFrame(0, request);
  if (!frame.reflections) throw std::runtime_error("the reflection pass did not run");
  return measureReflectionError(renderer.world(), frame.pixels, *frame.reflections, frame.geometry,
                                scene.reflections.maxDistance,
                                renderer.renderer().gbufferContents().surfaceNormals);
}

RenderedFrame renderWith(SceneFile scene, bool reflections) {
  scene.reflections.enabled = reflections;
  FrameRequest request;
  request.checkNan = true;
  return SceneRenderer(scene).renderFrame(0, request);
}

TEST_F(ReflectionTest, APolishedFloorMirrorsTheBlocksOnItAndTheSky) {
  const SceneFile scene = loadScene(kScenes / "mirror_floor.json");
  const RenderedFrame on = renderWith(scene, true), off = renderWith(scene, false);
  EXPECT_EQ(on.nanPixels, 0u);
  // The glowstone pillar (x = 3, z = -3) seen in the floor: the camera's ray to its mirror image
  // below the floor meets the floor here.
  const glm::dvec3 pillarInFloor(2.64, 64.0, 0.36);
  const glm::vec3 mirrored = colourAt(on, pillarInFloor), plain = colourAt(off, pillarInFloor);
  EXPECT_GT(mirrored.r - mirrored.b, 0.15f) << "the warm pillar shows in the floor";
  EXPECT_LT(plain.r - plain.b, 0.05f) << "without reflections the floor only tints the sky";
  // Near the camera the floor looks steeply down and mirrors the sky overhead.
  const glm::vec3 skyInFloor = colourAt(on, {0.5, 64.0, 5.0});
  EXPECT_GT(skyInFloor.b, skyInFloor.r + 0.05f) << "blue sky in the floor";
  EXPECT_FALSE(identical(on.image, off.image));
  for (const FrameStats::Skipped& s : on.stats.passesSkipped) EXPECT_NE(s.pass, "reflection") << s.why;
  context_->checkErrors("mirror floor");
}

// F4's reflection views: the hit mask (white hit, blue found nothing, black not marched), from opaque
// surfaces and from water, keeps the reflection pass and the lighting it reads, though the final
// image is replaced.
TEST_F(ReflectionTest, TheHitMaskViewShowsWhereRaysHit) {
  SceneFile scene = loadScene(kScenes / "mirror_floor.json");
  scene.debugView = DebugView::ReflectionHits;
  const RenderedFrame mask = SceneRenderer(scene).renderFrame(0);
  EXPECT_GT(colourAt(mask, {2.64, 64.0, 0.36}).r, 0.9f) << "the pillar's reflection: a hit";
  const glm::vec3 sky = colourAt(mask, {0.5, 64.0, 5.0});
  EXPECT_GT(sky.b, sky.r + 0.3f) << "the sky overhead: marched, nothing hit";
  EXPECT_LT(brightness(colourAt(mask, {0.5, 64.5, -1.5})), 0.05f)
      << "the gold block is not smooth: not marched";
  for (const FrameStats::Skipped& s : mask.stats.passesSkipped) {
    EXPECT_TRUE(s.pass != "reflection" && s.pass != "lighting") << s.pass << ": " << s.why;
  }
  scene.reflections.enabled = false;
  const RenderedFrame off = SceneRenderer(scene).renderFrame(0);
  EXPECT_LT(brightness(colourAt(off, {2.64, 64.0, 0.36})), 0.05f) << "no pass, nothing shown";
  // Water's rays too: the pillar mirrored in the pool is a hit, the sky in it is not.
  SceneFile lake = loadScene(kScenes / "lake_pillar.json");
  lake.debugView = DebugView::ReflectionHits;
  const RenderedFrame water = SceneRenderer(lake).renderFrame(0);
  EXPECT_GT(colourAt(water, {0.5, 63.875, 2.9}).r, 0.9f) << "the pillar in the water: a hit";
  const glm::vec3 skyInWater = colourAt(water, {-4.0, 63.875, 2.9});
  EXPECT_GT(skyInWater.b, skyInWater.r + 0.3f) << "the sky in the water: marched, nothing hit";
  context_->checkErrors("reflection debug views");
}

// Water (F0 0.02) seen low over the pool mirrors the pillar on the far shore: the reflection pass
// marches from the water's surface, the translucent pass weighs what it saw.
TEST_F(ReflectionTest, WaterMirrorsThePillarOnTheShore) {
  const SceneFile scene = loadScene(kScenes / "lake_pillar.json");
  const RenderedFrame on = renderWith(scene, true), off = renderWith(scene, false);
  EXPECT_EQ(on.nanPixels, 0u);
  // The pillar's middle (0.5, 65.5, -7.5) seen in the water (its surface at y = 63.875).
  const glm::dvec3 pillarInWater(0.5, 63.875, 2.9);
  const glm::vec3 mirrored = colourAt(on, pillarInWater), plain = colourAt(off, pillarInWater);
  EXPECT_GT((mirrored.r - mirrored.b) - (plain.r - plain.b), 0.1f) << "the warm pillar shows in the water";
  SceneRenderer renderer(scene);
  EXPECT_TRUE(testing::hasVariant(renderer, "translucent+SHADOWS+PCF_TENT+REFLECTIONS"));
  context_->checkErrors("water reflections");
}

// render.water.waves: the surface moves with world time and only with it (goldens stay stable).
TEST_F(ReflectionTest, WavesMoveWithWorldTimeAndOnlyWithIt) {
  SceneFile scene = loadScene(kScenes / "lake_pillar.json");
  scene.water.waves = true;
  const RenderedFrame a = renderWith(scene, true), again = renderWith(scene, true);
  EXPECT_EQ(a.nanPixels, 0u);
  EXPECT_TRUE(identical(a.image, again.image)) << "the same tick, the same waves";
  scene.time += 10;  // half a second later
  const RenderedFrame later = renderWith(scene, true);
  EXPECT_FALSE(identical(a.image, later.image)) << "the waves moved";
  scene.water.waves = false;
  scene.time -= 10;
  EXPECT_FALSE(identical(a.image, renderWith(scene, true).image)) << "still water looks different";
  context_->checkErrors("waves");
}

// The march against ray-traced truth: from every marched pixel the same mirror ray walked through the
// voxel grid. On the mirror floor most of them agree (a march on the wrong side of the depth test agrees
// on 3 %) and no sky leaks.
TEST_F(ReflectionTest, TheMarchAgreesWithTheRayTracedTruth) {
  const ReflectionError error = reflectionErrorOf(loadScene(kScenes / "mirror_floor.json"));
  const ReflectionCounts& c = error.total;
  EXPECT_GT(c.evaluated, 5000u);
  EXPECT_GT(100.0 * static_cast<double>(c.agree) / static_cast<double>(c.evaluated),
            90.0)  // 97.5 % at 160x90
      << "wrong " << c.wrongHit << ", missed " << c.missedOnScreen << " on screen and " << c.missedOffScreen
      << " off it, false " << c.falseHit;
  EXPECT_EQ(error.skyLeakPixels, 0u);
  context_->checkErrors("reflection truth");
}

// A scene not made for screen-space reflections: a wall of bumpy polished iron in a sealed, flooded
// cave, where half the rays leave the screen behind the camera. Of the rest, under 2 % hit a surface
// other than the truth's (0.5 %, and 1.1 % the block beside it within a pixel), and 97.5 % agree.
TEST_F(ReflectionTest, AFloodedCavesIronWallAgreesWithTheTruthWhereTheScreenCanSee) {
  const ReflectionError error = reflectionErrorOf(loadScene(kScenes / "flooded_iron_wall.json"));
  const auto pct = [](std::size_t n, std::size_t of) {
    return 100.0 * static_cast<double>(n) / static_cast<double>(of);
  };
  for (const ReflectionCounts* c : {&error.total, &error.opaque, &error.translucent}) {
    ASSERT_GT(c->evaluated, 3000u);
    EXPECT_LT(pct(c->wrongHit, c->evaluated), 2.0) << "border " << c->borderHit << " of " << c->evaluated;
    EXPECT_GT(pct(c->agree, c->evaluated - c->missedOffScreen), 95.0)
        << "wrong " << c->wrongHit << ", missed " << c->missedOnScreen << " on screen, false " << c->falseHit;
  }
  EXPECT_EQ(error.skyLeakPixels, 0u);
  context_->checkErrors("flooded iron wall");
}

// Sky light is 0 inside a sealed box, so a ray that finds nothing must reflect darkness, not the noon
// sky outside (the reflection twin of the shadows' cave leaks). Rays a block long find little, so the
// surfaces at `points` show at most the dark walls beside them (the noon sky would add over 0.4).
void expectNoSkyReflected(SceneFile scene, std::initializer_list<glm::dvec3> points) {
  scene.reflections.maxDistance = 1.0f;
  const RenderedFrame on = renderWith(scene, true), off = renderWith(scene, false);
  EXPECT_EQ(on.nanPixels, 0u);
  for (const glm::dvec3 p : points) {
    EXPECT_LE(brightness(colourAt(on, p)), brightness(colourAt(off, p)) + 0.1f)
        << "no sky reflected at " << p.x << ", " << p.y << ", " << p.z;
  }
}

// A sealed box of polished iron: its floor (the opaque surfaces' reflection pass).
TEST_F(ReflectionTest, ASealedCaveFloorReflectsNoSky) {
  expectNoSkyReflected(parseScene(R"({
      "world": { "generator": "flat", "edits": [
        { "fill": [-5, 64, -5, 5, 70, 5], "block": "iron_block" },
        { "fill": [-4, 65, -4, 4, 69, 4], "block": "air" } ] },
      "packs": ["default", "../packs/extreme_materials"],
      "time": 6000,
      "render": { "width": 160, "height": 90, "view_distance": 1, "shadow": { "resolution": 256, "distance": 32 } },
      "camera": { "position": [0.5, 68.5, 3.5], "look_at": [0.5, 65, -3], "fov": 80 } })",
                                  kScenes / "sealed_mirror.json"),
                       {{0.5, 65.0, 1.5}, {-2.5, 65.0, -1.5}, {2.5, 65.0, 0.0}});
  context_->checkErrors("sealed mirror");
}

// A sealed, flooded stone box lit by glowstone: its water (the translucent pass's reflections).
TEST_F(ReflectionTest, AFloodedCavesWaterReflectsNoSky) {
  expectNoSkyReflected(loadScene(kScenes / "flooded_cave.json"), {{0.5, 64.875, 1.5}, {-2.5, 64.875, -1.5}});
  context_->checkErrors("flooded cave");
}

// Pixels that turned warmer from `before` to `after` (red over blue grew by more than 0.12): where
// glowstone's colour came in; grey stone and the blue sky bent do not count.
int warmedPixels(const Image& before, const Image& after) {
  int n = 0;
  for (int y = 0; y < before.height; ++y)
    for (int x = 0; x < before.width; ++x) {
      const std::uint8_t *p = before.pixel(x, y), *q = after.pixel(x, y);
      n += (q[0] - q[2]) - (p[0] - p[2]) > 30 ? 1 : 0;
    }
  return n;
}

// Water refracts what lies behind it, but never what stands in front of it: a glowstone pillar on the
// near shore, in front of a rippling pool over stone, smears none of its colour into the water around
// it (the bent lookup's depth check). Reflections are kept out (min_smoothness 1) so only the
// refraction differs from a render without it.
TEST_F(ReflectionTest, RefractionBendsWhatLiesBehindTheWaterAndNothingInFrontOfIt) {
  SceneFile scene = parseScene(R"({
      "world": { "generator": "flat", "edits": [
        { "fill": [-6, 60, -8, 6, 63, 3], "block": "stone" },
        { "fill": [-5, 61, -7, 5, 63, 1], "block": "water" },
        { "fill": [-1, 64, 3, 0, 67, 3], "block": "glowstone" } ] },
      "time": 6000,
      "render": { "width": 320, "height": 180, "view_distance": 1, "shadow": { "enabled": false },
                  "reflections": { "min_smoothness": 1.0 }, "water": { "waves": true } },
      "camera": { "position": [0.0, 68.5, 6.5], "look_at": [0.0, 62, -3], "fov": 70 } })",
                               kScenes / "refraction.json");
  const RenderedFrame bent = renderWith(scene, true), straight = renderWith(scene, false);
  EXPECT_EQ(bent.nanPixels, 0u);
  EXPECT_FALSE(identical(bent.image, straight.image)) << "the pool's floor is seen bent";
  // 0; 21 with the depth check taken out of refracted() (translucent.frag).
  EXPECT_LE(warmedPixels(straight.image, bent.image), 3) << "water pixels took the pillar's colour";
  context_->checkErrors("refraction");
}

// Under water looking up, just below the surface: the sky through it within Snell's window, and
// beyond the critical angle (48.6 degrees) the water reflected (total internal reflection), much
// darker; without reflections the surface is still drawn from below, tinting the sky.
TEST_F(ReflectionTest, UnderWaterTheSurfaceIsSeenFromBelow) {
  SceneFile scene = parseScene(R"({
      "world": { "generator": "flat", "edits": [
        { "fill": [-20, 50, -20, 20, 63, 20], "block": "water" } ] },
      "time": 6000,
      "render": { "width": 160, "height": 90, "view_distance": 2, "shadow": { "resolution": 256, "distance": 32 } },
      "camera": { "position": [0.5, 63.5, 0.5], "look_at": [0.5, 64.5, -2.0], "fov": 90 } })",
                               kScenes / "under_water.json");
  // The surface (y = 63.875) 28 and 84 degrees off its normal.
  const glm::dvec3 window(0.5, 63.875, 0.3), beyond(0.5, 63.875, -3.0);
  const RenderedFrame on = renderWith(scene, true);
  EXPECT_EQ(on.nanPixels, 0u);
  const glm::vec3 sky = colourAt(on, window), reflected = colourAt(on, beyond);
  EXPECT_GT(sky.b, 0.5f) << "the sky overhead";
  EXPECT_GT(brightness(sky), brightness(reflected) + 0.5f) << "beyond the window, the darker water";
  EXPECT_GT(reflected.b, reflected.r) << "water's colour";
  const RenderedFrame off = renderWith(scene, false);
  EXPECT_EQ(off.nanPixels, 0u);
  scene.cameraPosition.y += 10.0;  // the same view of the sky from above the water
  scene.cameraLookAt.y += 10.0;
  const RenderedFrame above = renderWith(scene, false);
  EXPECT_LT(colourAt(off, window).r, colourAt(above, window + glm::dvec3(0.0, 10.0, 0.0)).r - 0.1f)
      << "seen from below, the surface tints the sky overhead";
  context_->checkErrors("under water");
}

std::string skipReason(const RenderedFrame& frame) {
  for (const FrameStats::Skipped& s : frame.stats.passesSkipped) {
    if (s.pass == "reflection") return s.why;
  }
  return "(ran)";
}

TEST_F(ReflectionTest, ThePassIsLeftOutWhereItHasNothingToDoAndNoPixelChanges) {
  SceneFile scene = loadScene(kScenes / "noon_terrain.json");
  const RenderedFrame off = renderWith(scene, false);
  EXPECT_EQ(skipReason(off), "reflections are off");
  // The default pack's smoothest texels (glass, water) stay under 0.99: nothing to reflect.
  scene.reflections.minSmoothness = 0.99f;
  const RenderedFrame rough = renderWith(scene, true);
  EXPECT_EQ(skipReason(rough), "no loaded texture is smooth enough");
  EXPECT_TRUE(identical(rough.image, off.image));
  // On, with nothing smooth or translucent in view: left out too.
  scene.reflections.minSmoothness = 0.6f;
  const RenderedFrame on = renderWith(scene, true);
  EXPECT_EQ(skipReason(on), "nothing in view is smooth enough or translucent");
  EXPECT_TRUE(identical(on.image, off.image));
  // Run anyway (render.cull_passes off), its mask keeps every pixel as it was.
  scene.cullPasses = false;
  const RenderedFrame forced = renderWith(scene, true);
  EXPECT_EQ(skipReason(forced), "(ran)");
  EXPECT_TRUE(identical(forced.image, off.image));
  context_->checkErrors("reflections left out");
}

}  // namespace
}  // namespace terrasol
