// glTF props in rendered scenes: they cast shadows and receive them in both shadow modes, take block
// light from the voxels around them, honour the alpha modes, show in the debug views as blocks do,
// and cost no shader variant a scene does not need.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "core/day_cycle.h"
#include "core/error.h"
#include "scene_render/scene_render.h"
#include "support/frame_probe.h"
#include "support/gl_test.h"
#include "support/gltf_box.h"
#include "support/shader_variants.h"
#include "support/test_data.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

using testing::brightness;
using testing::colourAt;
using testing::hasAnyVariantOf;
using testing::hasVariant;

// The Khronos samples, where present (after TERRASOL_SKIP_WITHOUT_TEST_DATA).
std::filesystem::path models() {
  return testing::testData() / "gltf";
}

class PropsTest : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    box_ = testing::writeBoxGltf(testing::scratchDir("props_box"));
  }
  std::filesystem::path box_;  // red, 1 block, centred (support/gltf_box.h)
};

// A flat world in the afternoon sun, the camera looking down at the origin from the south.
SceneFile flatAfternoon(ShadowMode shadowMode = ShadowMode::Warped) {
  SceneFile scene = parseScene(R"({ "world": { "generator": "flat" }, "time": 8000, "sun_path_rotation": -30,
      "render": { "width": 160, "height": 120, "view_distance": 1, "shadow": { "resolution": 1024, "distance": 32 } },
      "camera": { "position": [0.5, 72, 8.5], "look_at": [0.5, 64, 0.5], "fov": 60 } })",
                               "props_test.json");
  scene.shadow.mode = shadowMode;
  return scene;
}

SceneProp prop(const std::filesystem::path& model, glm::dvec3 position, float scale = 1.0f) {
  SceneProp p;
  p.model = model;
  p.position = position;
  p.scale = scale;
  p.key = "props[0]";
  return p;
}

glm::vec3 toLightAt(const SceneFile& scene) {
  return dayStateAt(scene.time, scene.sunPathRotation).toShadowLight;
}

TEST_F(PropsTest, APropCastsItsShadowOnTheGroundInBothShadowModes) {
  for (const ShadowMode mode : {ShadowMode::Warped, ShadowMode::Cascaded}) {
    SceneFile scene = flatAfternoon(mode);
    const glm::dvec3 centre(0.5, 67.5, 0.5);
    // Where the light through the box's centre meets the grass (its top at y = 64).
    const glm::dvec3 toLight(toLightAt(scene));
    const glm::dvec3 shadow = centre - toLight * ((centre.y - 64.0) / toLight.y);
    const RenderedFrame bare = SceneRenderer(scene).renderFrame(0);
    scene.props = {prop(box_, centre, 2.0f)};
    SceneRenderer withProp(scene);
    const RenderedFrame shaded = withProp.renderFrame(0);
    EXPECT_EQ(shaded.stats.propsDrawn, 1) << nameOf(mode, kShadowModes);
    EXPECT_GE(shaded.stats.propShadowCasters, 1) << nameOf(mode, kShadowModes);
    EXPECT_LT(brightness(colourAt(shaded, shadow)), 0.7f * brightness(colourAt(bare, shadow)))
        << nameOf(mode, kShadowModes) << ": the ground under the box is in its shadow";
    // And away from it the ground is as it was.
    const glm::dvec3 open = shadow + glm::dvec3(4.0, 0.0, 0.0);
    EXPECT_NEAR(brightness(colourAt(shaded, open)), brightness(colourAt(bare, open)), 0.05f)
        << nameOf(mode, kShadowModes);
  }
  context_->checkErrors("prop shadows");
}

TEST_F(PropsTest, APropInTheShadowOfABlockIsDarkerInBothShadowModes) {
  for (const ShadowMode mode : {ShadowMode::Warped, ShadowMode::Cascaded}) {
    SceneFile scene = flatAfternoon(mode);
    const glm::dvec3 centre(0.5, 64.5, 0.5);
    scene.props = {prop(box_, centre)};
    const RenderedFrame lit = SceneRenderer(scene).renderFrame(0);
    // A stone block three blocks up the light's way from the box's top shades it.
    const glm::dvec3 above = centre + glm::dvec3(0.0, 0.5, 0.0) + glm::dvec3(toLightAt(scene)) * 3.0;
    const glm::ivec3 cell(glm::floor(above));
    scene.edits.push_back({SceneEdit::Kind::Fill, cell - glm::ivec3(1, 0, 1), cell + glm::ivec3(1, 0, 1),
                           "stone", "world.edits[0]"});
    const RenderedFrame shaded = SceneRenderer(scene).renderFrame(0);
    const glm::dvec3 top = centre + glm::dvec3(0.0, 0.5, 0.0);
    EXPECT_LT(brightness(colourAt(shaded, top)), 0.75f * brightness(colourAt(lit, top)))
        << nameOf(mode, kShadowModes) << ": the box's top is in the stone's shadow";
  }
  context_->checkErrors("shadows on props");
}

TEST_F(PropsTest, APropNextToATorchTakesItsWarmBlockLight) {
  // Midnight, in a sealed stone room: only block light reaches the box.
  SceneFile scene = flatAfternoon();
  scene.time = 18000;
  scene.shadow.enabled = false;
  scene.edits.push_back({SceneEdit::Kind::Fill, {-4, 64, -4}, {4, 68, 4}, "stone", "world.edits[0]"});
  scene.edits.push_back({SceneEdit::Kind::Fill, {-3, 64, -3}, {3, 67, 3}, "air", "world.edits[1]"});
  scene.cameraPosition = {0.5, 66.5, 3.0};
  scene.cameraLookAt = {0.5, 64.5, 0.5};
  const glm::dvec3 centre(0.5, 64.5, 0.5);
  scene.props = {prop(box_, centre)};
  const RenderedFrame dark = SceneRenderer(scene).renderFrame(0);
  scene.edits.push_back({SceneEdit::Kind::Set, {2, 64, 1}, {2, 64, 1}, "torch", "world.edits[2]"});
  const RenderedFrame torchlit = SceneRenderer(scene).renderFrame(0);
  const glm::vec3 before = colourAt(dark, centre + glm::dvec3(0.0, 0.5, 0.0));
  const glm::vec3 after = colourAt(torchlit, centre + glm::dvec3(0.0, 0.5, 0.0));
  EXPECT_GT(brightness(after), 3.0f * brightness(before) + 0.05f) << "the torch lights the box's top";
  EXPECT_GT(after.r, after.b) << "warm";
  context_->checkErrors("prop light");
}

// The red box with its material edited, in the test's scratch folder.
std::filesystem::path editedBox(const std::string& name, const nlohmann::json& material) {
  return testing::writeBoxGltf(testing::scratchDir("props_" + name), material);
}

TEST_F(PropsTest, AlphaModesMaskAndBlend) {
  SceneFile scene = flatAfternoon();
  const glm::dvec3 centre(0.5, 64.5, 0.5), top = centre + glm::dvec3(0.0, 0.5, 0.0);
  const RenderedFrame bare = SceneRenderer(scene).renderFrame(0);
  scene.props = {prop(box_, centre)};
  SceneRenderer opaqueRenderer(scene);
  const RenderedFrame opaque = opaqueRenderer.renderFrame(0);
  EXPECT_TRUE(hasVariant(opaqueRenderer, "prop"));
  EXPECT_FALSE(hasAnyVariantOf(opaqueRenderer, "prop+CUTOUT")) << "no MASK material: no alpha-tested variant";
  EXPECT_FALSE(hasAnyVariantOf(opaqueRenderer, "prop_translucent"))
      << "no BLEND material: no forward variant";

  // MASK below the cutoff: nothing drawn, and nothing cast either (the grass is as without the box).
  scene.props[0].model =
      editedBox("mask_clear",
                {{"alphaMode", "MASK"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0, 0, 0.3}}}}});
  SceneRenderer clear(scene);
  EXPECT_TRUE(hasVariant(clear, "prop+CUTOUT"));
  EXPECT_TRUE(hasVariant(clear, "prop_shadow+CUTOUT"));
  EXPECT_EQ(compareImages(clear.renderFrame(0).image, bare.image, {0.0f, 0.0f}).failingPercent, 0.0);
  // MASK above it: the box as if opaque.
  scene.props[0].model =
      editedBox("mask_solid",
                {{"alphaMode", "MASK"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0, 0, 0.7}}}}});
  const RenderedFrame solid = SceneRenderer(scene).renderFrame(0);
  EXPECT_NEAR(brightness(colourAt(solid, top)), brightness(colourAt(opaque, top)), 0.02f);

  // BLEND at half alpha: between the grass and the opaque box, drawn in the translucent pass.
  scene.props[0].model = editedBox(
      "blend", {{"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0, 0, 0.5}}}}});
  SceneRenderer blendRenderer(scene);
  const RenderedFrame blended = blendRenderer.renderFrame(0);
  EXPECT_TRUE(hasVariant(blendRenderer, "prop_translucent+SHADOWS+PCF_TENT"));
  const glm::vec3 b = colourAt(blended, top), o = colourAt(opaque, top), g = colourAt(bare, top);
  EXPECT_GT(b.g, o.g + 0.05f) << "the green grass shows through";
  EXPECT_GT(b.r, g.r + 0.05f) << "the red box tints it";
  EXPECT_TRUE(std::none_of(blended.stats.passesSkipped.begin(), blended.stats.passesSkipped.end(),
                           [](const FrameStats::Skipped& s) { return s.pass == "translucent"; }))
      << "a blended prop in view needs the translucent pass";
  context_->checkErrors("alpha modes");
}

TEST_F(PropsTest, DebugViewsShowPropsLikeBlocks) {
  SceneFile scene = flatAfternoon();
  const glm::dvec3 centre(0.5, 64.5, 0.5), top = centre + glm::dvec3(0.0, 0.5, 0.0);
  scene.props = {prop(box_, centre)};
  SceneRenderer renderer(scene);
  FrameRequest request;
  request.debugView = DebugView::VertexNormal;
  const glm::vec3 normal = colourAt(renderer.renderFrame(0, request), top);
  EXPECT_NEAR(normal.x, 0.5f, 0.02f);
  EXPECT_NEAR(normal.y, 1.0f, 0.02f) << "the top face points up";
  EXPECT_NEAR(normal.z, 0.5f, 0.02f);
  request.debugView = DebugView::Albedo;
  const glm::vec3 albedo = colourAt(renderer.renderFrame(0, request), top);
  EXPECT_NEAR(albedo.r, 0.906f, 0.02f) << "base colour 0.8 (linear) shown in sRGB";
  EXPECT_LT(albedo.g, 0.02f);
  request.debugView = DebugView::Specular;
  const glm::vec3 spec = colourAt(renderer.renderFrame(0, request), top);
  EXPECT_NEAR(spec.r, 0.0f, 0.02f) << "glTF's default roughness 1 is smoothness 0";
  EXPECT_NEAR(spec.g, 10.0f / 255.0f, 0.01f) << "a dielectric: F0 0.04";
  context_->checkErrors("prop debug views");
}

TEST_F(PropsTest, NormalMapsAndEmissionReachTheGBufferEvenWithoutPackMaps) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();  // the textured sample, over a real pack with no _n or _s
  // The textured box with a normal map tilting every texel towards +u, and a white glow.
  const auto dir = testing::scratchDir("props_normal_map");
  std::filesystem::remove_all(dir);
  std::filesystem::copy(models() / "BoxTextured" / "glTF", dir);
  Image tilted(4, 4);
  for (std::size_t i = 0; i < tilted.rgba.size(); i += 4) {
    tilted.rgba[i] = 218;  // x = 0.71
    tilted.rgba[i + 1] = 128;
    tilted.rgba[i + 2] = 218;  // z = 0.71
    tilted.rgba[i + 3] = 255;
  }
  saveImage(dir / "tilted.png", tilted);
  nlohmann::json j = nlohmann::json::parse(readTextFile(dir / "BoxTextured.gltf"));
  j["images"].push_back({{"uri", "tilted.png"}});
  j["textures"].push_back({{"source", j["images"].size() - 1}});
  j["materials"][0]["normalTexture"] = {{"index", j["textures"].size() - 1}};
  j["materials"][0]["emissiveFactor"] = {1.0, 1.0, 1.0};
  std::ofstream(dir / "BoxTextured.gltf") << j.dump();

  // Pixel Perfection alone has no _n and no _s: only the prop keeps the surface normals and _s target.
  SceneFile scene = flatAfternoon();
  scene.packs = {testing::testData() / "packs" / "pixel_perfection_ce"};
  const glm::dvec3 centre(0.5, 64.5, 0.5), top = centre + glm::dvec3(0.0, 0.5, 0.0);
  scene.props = {prop(dir / "BoxTextured.gltf", centre)};
  SceneRenderer renderer(scene);
  FrameRequest request;
  request.debugView = DebugView::Normal;
  const glm::vec3 mapped = colourAt(renderer.renderFrame(0, request), top);
  request.debugView = DebugView::VertexNormal;
  const glm::vec3 vertex = colourAt(renderer.renderFrame(0, request), top);
  EXPECT_GT(glm::length(mapped - vertex), 0.2f) << "the normal map tilts the top face's normal";
  EXPECT_TRUE(renderer.renderer().gbufferContents().surfaceNormals);
  EXPECT_TRUE(renderer.renderer().gbufferContents().specular);
  request.debugView = DebugView::Emission;
  EXPECT_GT(colourAt(renderer.renderFrame(0, request), top).r, 0.5f) << "the glow is LabPBR emission";
  EXPECT_LT(colourAt(renderer.renderFrame(0, request), centre + glm::dvec3(3.0, -0.5, 0.0)).r, 0.02f)
      << "the grass does not glow";
  context_->checkErrors("normal maps and emission");
}

TEST_F(PropsTest, BaseColourMipmapsAverageInLinearLight) {
  // Black and white texels: their mean in linear light is 0.5, which sRGB stores as 188, not 128.
  Model model;
  model.meshes.push_back({});
  model.materials.push_back({});
  model.materials[0].baseColorImage = 0;
  model.materials[0].metallicRoughnessImage = 0;
  Image checker(2, 2);
  checker.rgba = {0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255};
  model.images.push_back(checker);
  Props props;
  const Props::Material& m = props.models()[static_cast<std::size_t>(props.addModel(model))].materials[0];
  std::uint8_t texel[4] = {};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(m.baseColor, 1, GL_RGBA, GL_UNSIGNED_BYTE, sizeof texel, texel);
  EXPECT_NEAR(texel[0], 188, 2) << "sRGB base colour";
  glGetTextureImage(m.metallicRoughness, 1, GL_RGBA, GL_UNSIGNED_BYTE, sizeof texel, texel);
  EXPECT_NEAR(texel[1], 128, 2) << "linear data averages as stored";
  context_->checkErrors("prop mipmaps");
}

TEST_F(PropsTest, AMissingModelNamesThePropAndTheFile) {
  SceneFile scene = flatAfternoon();
  scene.props = {prop(box_.parent_path() / "nothing_here.glb", {0.5, 64.5, 0.5})};
  try {
    SceneRenderer renderer(scene);
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("props[0].model"), std::string::npos) << message;
    EXPECT_NE(message.find("nothing_here.glb"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace terrasol
