// Shadows measured against ray-traced truth (tools/render/shadow_truth.h): stiff and extreme settings
// stay NaN-free with sane error figures, and a sealed cave never sees the sun.

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "scene_render/scene_render.h"
#include "scene_render/shadow_truth.h"
#include "support/gl_test.h"
#include "support/golden.h"
#include "support/shader_variants.h"

namespace terrasol {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "scenes";

class ShadowTest : public testing::GlTest {
 protected:
  struct Result {
    ShadowError error;
    std::size_t nan;
    FrameStats stats;
  };
  Result measure(const SceneFile& scene) {
    SceneRenderer renderer(scene);
    FrameRequest request;
    request.readBack = true;
    const RenderedFrame frame = renderer.renderFrame(0, request);
    context_->checkErrors("rendering");
    return {measureShadowError(renderer.world(), frame.pixels, frame.geometry, scene.shadow.distance),
            frame.nanPixels, frame.stats};
  }
  static double wrongPercent(const ShadowCounts& c) {
    return c.evaluated
               ? 100.0 * static_cast<double>(c.falseLit + c.falseShadow) / static_cast<double>(c.evaluated)
               : 0.0;
  }
};

TEST_F(ShadowTest, NoonShadowsMatchRayTracedTruth) {
  SceneFile scene = loadScene(kScenes / "shadow_noon.json");
  const Result r = measure(scene);
  EXPECT_GT(r.error.total.evaluated, 10000u);
  EXPECT_LT(wrongPercent(r.error.total), 0.5);
  EXPECT_EQ(r.error.caveLeakPixels, 0u);
  // And the measurement can fail: with the shadow map gone, every shadowed point is wrongly lit.
  scene.shadow.enabled = false;
  scene.sunPathRotation = -30;
  const Result none = measure(scene);
  EXPECT_GT(100.0 * static_cast<double>(none.error.total.falseLit) /
                static_cast<double>(none.error.total.evaluated),
            5.0);
}

// Shaped blocks are measured by their boxes: a ray over a slab's open half or between a fence's rails
// goes on, one into them is shadowed. Against whole cells, 12 % of the shapes scene's pixels were
// ambiguous (every ray leaving a slab's top or crossing a stair's cell); by the boxes, 2.3 %. The
// showcase's thin casters (fence rails, 2/16 wide) need a 2048 map: at 1024, PCF washes their
// shadows out (0.55 % wrongly lit; 0.14 % at 2048, 0.02 % at 4096).
TEST_F(ShadowTest, ShapedBlocksShadowByTheirBoxes) {
  const Result shapes = measure(loadScene(kScenes / "shapes.json"));
  EXPECT_GT(shapes.error.total.evaluated, 30000u);
  EXPECT_LT(100.0 * static_cast<double>(shapes.error.total.ambiguous) /
                static_cast<double>(shapes.error.total.evaluated + shapes.error.total.ambiguous),
            5.0);
  EXPECT_LT(wrongPercent(shapes.error.total), 0.5);
  SceneFile showcase = loadScene(kScenes / "paths" / "builders_showcase.json");
  showcase.shadow.resolution = 2048;
  const Result all = measure(showcase);
  EXPECT_GT(all.error.total.evaluated, 25000u);
  EXPECT_LT(wrongPercent(all.error.total), 0.5);
  EXPECT_EQ(all.error.caveLeakPixels, 0u);
}

// The tent's four bilinear taps sit half the radius apart: at radius 0 they are one tap, exactly;
// at a larger radius they widen the penumbra, the pixels whose shadow term (the lit scene's alpha) is
// neither 0 nor 1.
TEST_F(ShadowTest, TentIsOneTapAtRadiusZeroAndWidensPenumbraeWithItsRadius) {
  SceneFile scene = loadScene(kScenes / "shadow_noon.json");
  scene.width = 320;
  scene.height = 180;
  struct Frame {
    Image image;
    std::size_t penumbra = 0;
  };
  auto render = [&](int samples, float radius) {
    SceneFile s = scene;
    s.shadow.pcfPattern = PcfPattern::Tent;
    s.shadow.pcfSamples = samples;
    s.shadow.pcfRadius = radius;
    SceneRenderer renderer(s);
    FrameRequest request;
    request.readBack = true;
    RenderedFrame f = renderer.renderFrame(0, request);
    const auto partial = [](const glm::vec4& p) { return p.a > 0.02f && p.a < 0.98f; };
    return Frame{std::move(f.image), static_cast<std::size_t>(std::count_if(f.pixels.scene.begin(),
                                                                            f.pixels.scene.end(), partial))};
  };
  const Frame oneTap = render(0, 1.0f), tent0 = render(1, 0.0f), tent4 = render(1, 4.0f);
  context_->checkErrors("tent");
  EXPECT_EQ(oneTap.image.rgba, tent0.image.rgba);
  EXPECT_GT(oneTap.penumbra, 0u);
  EXPECT_GT(tent4.penumbra, 2 * oneTap.penumbra) << oneTap.penumbra << " one tap";
}

// Each stiff setting: rendered without NaN or Inf, and still mostly right.
TEST_F(ShadowTest, ExtremeSettingsStayFiniteAndSane) {
  const SceneFile base = loadScene(kScenes / "shadow_noon.json");
  struct Case {
    const char* name;
    void (*change)(SceneFile&);
    const char* lighting = "lighting+SHADOWS+PCF_TENT";  // the variant the filter settings pick
  };
  const Case cases[] = {
      {"sun 0.5 degrees up", [](SceneFile& s) { s.time = 33; }},
      {"sun overhead, rotation 0", [](SceneFile& s) { s.sunPathRotation = 0.0f; }},
      {"warp strength 0", [](SceneFile& s) { s.shadow.warpStrength = 0.0f; }},
      {"warp strength 0.999", [](SceneFile& s) { s.shadow.warpStrength = 0.999f; }},
      {"square warp", [](SceneFile& s) { s.shadow.warp = ShadowWarp::Square; }},
      {"resolution 256", [](SceneFile& s) { s.shadow.resolution = 256; }},
      {"resolution 8192", [](SceneFile& s) { s.shadow.resolution = 8192; }},
      {"distance 8", [](SceneFile& s) { s.shadow.distance = 8.0f; }},
      {"distance 1024", [](SceneFile& s) { s.shadow.distance = 1024.0f; }},
      {"4 cascades", [](SceneFile& s) { s.shadow.mode = ShadowMode::Cascaded; }},
      {"map shifted 0.9 ahead", [](SceneFile& s) { s.shadow.shiftAhead = 0.9f; }},
      {"PCF radius 0.25 blocks, 8 samples",
       [](SceneFile& s) {
         s.shadow.pcfRadiusInBlocks = true;
         s.shadow.pcfRadius = 0.25f;
         s.shadow.pcfSamples = 8;
       }},
      {"2 cascades at 256 texels",
       [](SceneFile& s) {
         s.shadow.mode = ShadowMode::Cascaded;
         s.shadow.cascades = 2;
         s.shadow.resolution = 256;
       }},
      {"one tap, no PCF", [](SceneFile& s) { s.shadow.pcfSamples = 0; }, "lighting+SHADOWS"},
      {"disk PCF, radius 3",
       [](SceneFile& s) {
         s.shadow.pcfPattern = PcfPattern::Disk;
         s.shadow.pcfRadius = 3.0f;
       },
       "lighting+SHADOWS+PCF_DISK"},
      {"tent PCF, radius 8", [](SceneFile& s) { s.shadow.pcfRadius = 8.0f; }},
      {"grid PCF, 3 samples, radius 4",
       [](SceneFile& s) {
         s.shadow.pcfPattern = PcfPattern::Grid;
         s.shadow.pcfSamples = 3;
         s.shadow.pcfRadius = 4.0f;
       },
       "lighting+SHADOWS+PCF_GRID_SIDE=7"},
  };
  for (const Case& c : cases) {
    SceneFile scene = base;
    scene.width = 160;
    scene.height = 90;
    c.change(scene);
    SceneRenderer renderer(scene);
    EXPECT_TRUE(testing::hasVariant(renderer, c.lighting)) << c.name;
    FrameRequest request;
    request.checkNan = true;
    request.readBack = true;
    const RenderedFrame frame = renderer.renderFrame(0, request);
    context_->checkErrors(c.name);
    EXPECT_EQ(frame.nanPixels, 0u) << c.name;
    const ShadowError e =
        measureShadowError(renderer.world(), frame.pixels, frame.geometry, scene.shadow.distance);
    EXPECT_EQ(e.caveLeakPixels, 0u) << c.name;
    EXPECT_LT(wrongPercent(e.total), 10.0) << c.name << ": " << e.total.falseLit << " false lit, "
                                           << e.total.falseShadow << " false shadow of " << e.total.evaluated;
  }
}

// A room sealed by a one-block roof, the sun straight above: its floor has sky light 0, so no sun
// reaches it whatever the shadow map's bias does.
// Cascades are unwarped and snapped, so moving the camera by a fraction of a texel changes no shadow.
// (Moves of a texel or more may: shifted by whole texels in double, the casters' float vertices can
// round differently, and an alpha-tested plant's shadow then gains or loses a texel.)
TEST_F(ShadowTest, CascadesMatchTruthAndDoNotFlicker) {
  SceneFile scene = loadScene(kScenes / "shadow_noon.json");
  scene.shadow.mode = ShadowMode::Cascaded;
  SceneRenderer renderer(scene);
  FrameRequest request;
  request.readBack = true;
  const RenderedFrame a = renderer.renderFrame(0, request);
  const ShadowError e = measureShadowError(renderer.world(), a.pixels, a.geometry, scene.shadow.distance);
  EXPECT_GT(e.total.evaluated, 10000u);
  EXPECT_LT(wrongPercent(e.total), 0.5);
  for (const glm::dvec3 move :
       {glm::dvec3(0.3, 0.1, -0.2), glm::dvec3(-0.45, 0.4, 0.45), glm::dvec3(0.49, 0.0, -0.49)}) {
    request.shadowCentreOffset = move * static_cast<double>(a.geometry.shadowTexelWorld);
    const RenderedFrame b = renderer.renderFrame(0, request);
    std::size_t compared = 0;
    EXPECT_EQ(flickerPercent(a.pixels, b.pixels, a.geometry, scene.shadow.distance, compared), 0.0);
    EXPECT_GT(compared, 10000u);
  }
  context_->checkErrors("cascades");
}

// The warped map stays put for small camera moves (no flicker) and follows large ones (still right).
TEST_F(ShadowTest, WarpedMapHoldsStillForSmallMovesAndFollowsLargeOnes) {
  const SceneFile scene = loadScene(kScenes / "shadow_noon.json");
  SceneRenderer renderer(scene);
  FrameRequest request;
  request.readBack = true;
  const RenderedFrame a = renderer.renderFrame(0, request);
  const double texel = a.geometry.shadowTexelWorld;
  request.shadowCentreOffset = glm::dvec3(0.4, 0.2, -0.3) * texel;
  const RenderedFrame b = renderer.renderFrame(0, request);
  std::size_t compared = 0;
  EXPECT_EQ(flickerPercent(a.pixels, b.pixels, a.geometry, scene.shadow.distance, compared), 0.0);
  EXPECT_GT(compared, 10000u);
  // 40 texels away: re-centred, and the shadows still match the truth.
  request.shadowCentreOffset = glm::dvec3(40.0, 0.0, 25.0) * texel;
  const RenderedFrame c = renderer.renderFrame(0, request);
  const ShadowError e = measureShadowError(renderer.world(), c.pixels, c.geometry, scene.shadow.distance);
  EXPECT_LT(wrongPercent(e.total), 0.5);
  EXPECT_GT(flickerPercent(a.pixels, c.pixels, a.geometry, scene.shadow.distance, compared), 0.0)
      << "a re-centred warped map moves some shadow edges";
  context_->checkErrors("warped map");
}

TEST_F(ShadowTest, ASealedCaveUnderAOneBlockRoofHasNoLeaks) {
  SceneFile scene = parseScene(R"({
      "world": { "generator": "flat", "edits": [
        { "fill": [-4, 64, -4, 4, 68, 4], "block": "stone" },
        { "fill": [-3, 64, -3, 3, 67, 3], "block": "air" },
        { "set": [0, 64, 0], "block": "torch" } ] },
      "time": 6000, "sun_path_rotation": 0,
      "render": { "width": 160, "height": 90, "view_distance": 1, "shadow": { "distance": 32, "resolution": 256 } },
      "camera": { "position": [2.5, 66.5, 2.5], "look_at": [-2, 64, -2] } })",
                               kScenes / "sealed.json");
  const Result r = measure(scene);
  EXPECT_EQ(r.error.caveLeakPixels, 0u);
  EXPECT_EQ(r.nan, 0u);
}

bool shadowSkipped(const RenderedFrame& f) {
  return std::any_of(f.stats.passesSkipped.begin(), f.stats.passesSkipped.end(),
                     [](const FrameStats::Skipped& s) { return s.pass == "shadow"; });
}

TEST_F(ShadowTest, AKeptMapLooksTheSameAndIsRedrawnWhenItsCentreMoves) {
  const SceneFile scene = loadScene(kScenes / "shadow_noon.json");
  SceneRenderer renderer(scene);
  FrameRequest request;
  request.reuseShadowMap = true;
  const RenderedFrame drawn = renderer.renderFrame(0, request);
  EXPECT_FALSE(shadowSkipped(drawn));
  const RenderedFrame kept = renderer.renderFrame(0, request);
  EXPECT_TRUE(shadowSkipped(kept)) << "nothing changed: the map is kept";
  EXPECT_TRUE(compareImages(kept.image, drawn.image, {0.0f, 0.0f}).matches) << "and the image is the same";
  request.shadowCentreOffset =
      glm::dvec3(40.0, 0.0, 25.0) * static_cast<double>(drawn.geometry.shadowTexelWorld);
  EXPECT_FALSE(shadowSkipped(renderer.renderFrame(0, request))) << "a re-centred map is drawn again";
  request.reuseShadowMap = false;
  request.shadowCentreOffset = glm::dvec3(0.0);
  EXPECT_FALSE(shadowSkipped(renderer.renderFrame(0, request))) << "measured renders always draw it";
}

TEST_F(ShadowTest, NoShadowPassWhenNoLightIsAboveTheHorizon) {
  SceneFile scene = loadScene(kScenes / "shadow_noon.json");
  scene.time = 12000;  // sunset: the sun on the horizon and the moon on the opposite one
  SceneRenderer renderer(scene);
  const RenderedFrame frame = renderer.renderFrame(0);
  ASSERT_FALSE(frame.stats.passesSkipped.empty());
  EXPECT_EQ(frame.stats.passesSkipped.front().pass, "shadow");
  EXPECT_EQ(frame.stats.shadowCasters, 0);
}

}  // namespace
}  // namespace terrasol
