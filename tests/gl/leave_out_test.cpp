// What the renderer leaves out, rule by rule: each rule must leave something out on a scene that has
// it to leave, and the picture must not change by a single pixel for it.

#include <algorithm>
#include <filesystem>

#include "render/shadow_schedule.h"
#include "scene_render/scene_render.h"
#include "support/frame_probe.h"
#include "support/gl_test.h"
#include "support/golden.h"
#include "support/shader_variants.h"
#include "support/test_data.h"

namespace terrasol {
namespace {

using testing::hasVariant;

const std::filesystem::path kScenes = std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "scenes";

class LeaveOutTest : public testing::GlTest {};

bool identical(const Image& a, const Image& b) {
  return compareImages(a, b, {0.0f, 0.0f}).matches;
}

// Frame 0 with a leave-out rule on (the default) and off.
struct WithAndWithout {
  RenderedFrame on, off;
};
WithAndWithout render(SceneFile scene, bool SceneFile::*rule) {
  WithAndWithout out;
  out.on = SceneRenderer(scene).renderFrame(0);
  scene.*rule = false;
  out.off = SceneRenderer(scene).renderFrame(0);
  return out;
}

TEST_F(LeaveOutTest, CaveCullingHidesSectionsAndCastersButNoPixel) {
  for (const char* name : {"noon_terrain", "shadow_cave_mouth", "night_cave_torches"}) {
    SceneFile scene = loadScene(kScenes / (std::string(name) + ".json"));
    scene.shadowCasterCulling = false;  // it chooses casters by what is in view, which cave culling changes
    const auto [culled, all] = render(scene, &SceneFile::caveCulling);
    EXPECT_GT(culled.stats.sectionsHidden, 0) << name;
    EXPECT_EQ(all.stats.sectionsHidden, 0) << name;
    EXPECT_EQ(culled.stats.sectionsDrawn + culled.stats.sectionsHidden, all.stats.sectionsDrawn) << name;
    // Sections no ray of the light reaches cast nothing (all three scenes have a shadow pass).
    EXPECT_EQ(all.stats.shadowCastersHidden, 0) << name;
    EXPECT_EQ(culled.stats.shadowCasters + culled.stats.shadowCastersHidden, all.stats.shadowCasters) << name;
    EXPECT_TRUE(identical(culled.image, all.image))
        << name << ": leaving hidden sections out changed the image";
    if (std::string(name) == "noon_terrain") {
      EXPECT_GT(culled.stats.shadowCastersHidden, 0) << "caves under the terrain cast nothing";
    }
  }
  context_->checkErrors("cave culling");
}

using testing::skipReason;

// The frame graph leaves out every pass whose output no pass that runs reads: a debug view replaces
// the final image, so the lit scene, the translucent pass and the shadow map are not needed.
TEST_F(LeaveOutTest, PassesADebugViewDoesNotReadAreCulledAndChangeNoPixel) {
  SceneFile scene = loadScene(kScenes / "water_glass.json");  // shadows and water in view
  scene.debugView = DebugView::Normal;
  const auto [culled, all] = render(scene, &SceneFile::cullPasses);
  EXPECT_EQ(skipReason(culled, "final"), "debug_view replaces its target");
  EXPECT_EQ(skipReason(culled, "lighting"), "no pass that runs reads its scene");
  EXPECT_EQ(skipReason(culled, "translucent"), "no pass that runs reads its scene");
  EXPECT_EQ(skipReason(culled, "shadow"), "no pass that runs reads its shadow_map");
  EXPECT_EQ(culled.stats.shadowCasters, 0);
  for (const char* pass : {"shadow", "lighting", "translucent", "final"}) {
    EXPECT_EQ(skipReason(all, pass), "(ran)") << pass << " without the rule";
  }
  EXPECT_TRUE(identical(culled.image, all.image)) << "leaving the unread passes out changed the debug view";
  context_->checkErrors("debug view culling");
}

TEST_F(LeaveOutTest, TheTranslucentPassIsLeftOutWithNothingTranslucentInViewAndChangesNoPixel) {
  const auto [culled, all] = render(loadScene(kScenes / "stone_closeup.json"), &SceneFile::cullPasses);
  EXPECT_EQ(skipReason(culled, "translucent"), "no translucent geometry in view");
  EXPECT_EQ(skipReason(all, "translucent"), "(ran)");
  EXPECT_EQ(all.stats.quadsDrawn, culled.stats.quadsDrawn) << "it had nothing to draw";
  EXPECT_TRUE(identical(culled.image, all.image));
  context_->checkErrors("translucent culling");
}

// Casters behind the camera, or off to its sides, shade nothing it sees.
TEST_F(LeaveOutTest, ShadowCastersOffViewAreNotDrawnAndChangeNoPixel) {
  for (const char* name : {"noon_terrain", "shadow_low_sun", "shadow_forest"}) {
    const auto [culled, all] =
        render(loadScene(kScenes / (std::string(name) + ".json")), &SceneFile::shadowCasterCulling);
    EXPECT_EQ(all.stats.shadowCastersOffView, 0) << name;
    EXPECT_EQ(culled.stats.shadowCasters + culled.stats.shadowCastersOffView, all.stats.shadowCasters)
        << name;
    EXPECT_TRUE(identical(culled.image, all.image)) << name << ": leaving casters out changed the image";
    if (std::string(name) == "noon_terrain") {
      EXPECT_GT(culled.stats.shadowCastersOffView, 0)
          << "the terrain behind the camera shades nothing in view";
    }
  }
  context_->checkErrors("shadow caster culling");
}

TEST_F(LeaveOutTest, FacesTurnedAwayAreNotDrawnAndChangeNoPixel) {
  const auto [culled, all] = render(loadScene(kScenes / "noon_terrain.json"), &SceneFile::cullFacesAway);
  EXPECT_GT(culled.stats.quadsFacingAway, 0);
  EXPECT_EQ(all.stats.quadsFacingAway, 0);
  EXPECT_EQ(culled.stats.quadsDrawn + culled.stats.quadsFacingAway, all.stats.quadsDrawn);
  EXPECT_TRUE(identical(culled.image, all.image)) << "back faces: GL culling drops them anyway";
}

TEST_F(LeaveOutTest, MapsNoPackHasAreNotSampledAndChangeNoPixel) {
  // Pixel Perfection CE alone: no _n, no _s anywhere.
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  SceneFile scene = loadScene(kScenes / "pack_pixel_perfection.json");
  scene.packs = {testing::testData() / "packs" / "pixel_perfection_ce"};
  SceneRenderer lean(scene);
  EXPECT_TRUE(hasVariant(lean, "gbuffer+NO_NORMAL_MAPS+NO_SPECULAR_MAPS"));
  EXPECT_TRUE(hasVariant(lean, "lighting+SHADOWS+PCF_TENT+NO_NORMAL_MAPS+NO_SPECULAR_MAPS"));
  scene.leaveOutAbsentMaps = false;
  SceneRenderer full(scene);
  EXPECT_TRUE(hasVariant(full, "gbuffer"));
  const Image leanImage = lean.renderFrame(0).image, fullImage = full.renderFrame(0).image;
  EXPECT_TRUE(identical(leanImage, fullImage));
  // The G-buffer keeps only the vertex normal (RG16F) and no _s target: 16 of 24 bytes a pixel.
  const GBuffer& g = *lean.renderer().gbuffer();
  EXPECT_FALSE(g.contents().surfaceNormals);
  EXPECT_FALSE(g.contents().specular);
  EXPECT_EQ(g.target(gbuffer::kSpecular), 0u);
  GLint format = 0;
  glGetTextureLevelParameteriv(g.target(gbuffer::kNormals), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  EXPECT_EQ(format, GL_RG16F);
  EXPECT_EQ(g.contents().bytesPerPixel(), 16);
  EXPECT_EQ(full.renderer().gbuffer()->contents().bytesPerPixel(), 24);
  // So does every debug view that reads them: the normals and the (default) specular data.
  for (const DebugView view : {DebugView::Normal, DebugView::VertexNormal, DebugView::Specular}) {
    SceneFile viewScene = scene;
    viewScene.debugView = view;
    const Image a = SceneRenderer(viewScene).renderFrame(0).image;
    viewScene.leaveOutAbsentMaps = true;
    EXPECT_TRUE(identical(a, SceneRenderer(viewScene).renderFrame(0).image)) << nameOf(view, kDebugViews);
  }
  // With the default pack (which has both) nothing is left out.
  SceneRenderer pbr(loadScene(kScenes / "pack_pixel_perfection.json"));
  EXPECT_TRUE(hasVariant(pbr, "gbuffer"));
  EXPECT_TRUE(hasVariant(pbr, "lighting+SHADOWS+PCF_TENT"));
  context_->checkErrors("absent maps");
}

// shadow_noon with its map rebuilt over four frames and kept between frames, after its first frame
// (nothing kept yet: drawn whole).
struct SpreadShadows {
  SceneFile scene = [] {
    SceneFile s = loadScene(kScenes / "shadow_noon.json");
    s.shadow.updateFrames = 4;
    return s;
  }();
  SceneRenderer spread{scene};
  FrameRequest request = [] {
    FrameRequest r;
    r.reuseShadowMap = true;
    return r;
  }();
  RenderedFrame first = spread.renderFrame(0, request);
};

TEST_F(LeaveOutTest, ASpreadShadowUpdateEndsWithTheMapAWholeUpdateDraws) {
  SpreadShadows run;
  auto& [scene, spread, request, first] = run;
  const int whole = first.stats.shadowCasters;
  // Moved past the re-centring distance, well inside a quarter of the map: rebuilt over 4 frames.
  request.shadowCentreOffset =
      glm::dvec3(12.0, 0.0, 0.0) * static_cast<double>(first.geometry.shadowTexelWorld);
  int drawn = 0;
  RenderedFrame last;
  for (int i = 0; i < 4; ++i) {
    last = spread.renderFrame(0, request);
    EXPECT_LT(last.stats.shadowCasters, whole) << "frame " << i << " draws a slice";
    drawn += last.stats.shadowCasters;
  }
  EXPECT_EQ(drawn, whole) << "every caster once over the four frames";
  const RenderedFrame kept = spread.renderFrame(0, request);
  EXPECT_EQ(kept.stats.shadowCasters, 0) << "complete and unchanged: kept";

  SceneRenderer once(scene);
  FrameRequest wholeRequest;
  wholeRequest.shadowCentreOffset = request.shadowCentreOffset;
  const RenderedFrame reference = once.renderFrame(0, wholeRequest);
  EXPECT_TRUE(identical(last.image, reference.image)) << "the finished map is the map a whole update draws";
  context_->checkErrors("spread shadow update");
}

// A camera moving a quarter of the kept map's allowance a frame (a low frame rate while flying) would
// outrun a slice a frame: the kept map would run out mid-build and be redrawn whole, every fourth frame.
// Instead each build is spread over the frames its pace leaves, and no frame draws the whole map.
TEST_F(LeaveOutTest, AFastCameraGetsMoreSlicesAFrameNotAWholeRedraw) {
  SpreadShadows run;
  auto& [scene, spread, request, first] = run;
  ASSERT_EQ(first.stats.shadowSlices, 4) << "nothing kept yet: drawn whole";
  const double reach = ShadowSchedule::kKeptReach * scene.shadow.distance;
  int slices = 0;
  for (int i = 1; i <= 8; ++i) {
    request.shadowCentreOffset = glm::dvec3(0.25 * reach * i, 0.0, 0.0);
    const RenderedFrame frame = spread.renderFrame(0, request);
    EXPECT_EQ(frame.stats.shadowSlices, 2)
        << "frame " << i << ": half the map, so a build lands every second frame";
    EXPECT_LT(frame.stats.shadowCasters, first.stats.shadowCasters) << "frame " << i;
    slices += frame.stats.shadowSlices;
  }
  EXPECT_EQ(slices, 16) << "four maps in eight frames";
  context_->checkErrors("fast spread shadow update");
}

}  // namespace
}  // namespace terrasol
