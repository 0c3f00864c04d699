#include "scene/scene_file.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/paths.h"
#include "support/error_of.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

constexpr const char* kFile = "scenes/a.json";

std::string errorOf(const std::string& json, const std::filesystem::path& file = kFile) {
  return testing::errorOf([&] { parseScene(json, file); });
}

// The message must contain `part`, typically "scenes/a.json: <key path>: <what>".
::testing::AssertionResult failsWith(const std::string& json, const std::string& part) {
  const std::string message = errorOf(json);
  if (message.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "scene " << json << "\n  gave \"" << message << "\"\n  expected it to contain \"" << part << "\"";
}

::testing::AssertionResult parses(const std::string& json) {
  const std::string message = errorOf(json);
  if (message == "no error") return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "scene " << json << "\n  gave \"" << message << "\"";
}

std::string withEdit(const std::string& edit) {
  return R"({"world": {"edits": [)" + edit + "]}}";
}

void writeFile(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
}

TEST(SceneFile, FullSceneParsesIntoTheRightValues) {
  const SceneFile scene = parseScene(R"({
    "world": { "generator": "flat", "seed": 18446744073709551615,
               "edits": [ { "fill": [5, 70, -3, 1, 64, 2], "block": "stone" },
                          { "set": [0, 71, 0], "block": "torch" } ] },
    "packs": [ "default", "packs/hd" ],
    "time": 13000,
    "sun_path_rotation": -30,
    "render": { "width": 640, "height": 360, "view_distance": 8, "debug_view": "normal" },
    "camera": { "position": [1.5, 72, -4.25], "look_at": [0, 64, 0], "fov": 55.5 } })",
                                     kFile);
  EXPECT_EQ(scene.file, kFile);
  EXPECT_EQ(scene.generator, "flat");
  EXPECT_EQ(scene.seed, 18446744073709551615ull);
  ASSERT_EQ(scene.edits.size(), 2u);
  EXPECT_EQ(scene.edits[0].kind, SceneEdit::Kind::Fill);
  EXPECT_EQ(scene.edits[0].from, glm::ivec3(1, 64, -3));  // corners normalised
  EXPECT_EQ(scene.edits[0].to, glm::ivec3(5, 70, 2));
  EXPECT_EQ(scene.edits[0].block, "stone");
  EXPECT_EQ(scene.edits[0].key, "world.edits[0]");
  EXPECT_EQ(scene.edits[1].kind, SceneEdit::Kind::Set);
  EXPECT_EQ(scene.edits[1].from, glm::ivec3(0, 71, 0));
  EXPECT_EQ(scene.edits[1].to, glm::ivec3(0, 71, 0));
  EXPECT_EQ(scene.edits[1].block, "torch");
  EXPECT_EQ(scene.edits[1].key, "world.edits[1]");
  ASSERT_EQ(scene.packs.size(), 2u);
  EXPECT_EQ(scene.packs[0], resourcePackDir() / "default");
  EXPECT_EQ(scene.packs[1], std::filesystem::path("scenes/packs/hd"));
  EXPECT_EQ(scene.time, 13000);
  EXPECT_FLOAT_EQ(scene.sunPathRotation, -30.0f);
  EXPECT_EQ(scene.width, 640);
  EXPECT_EQ(scene.height, 360);
  EXPECT_EQ(scene.viewDistance, 8);
  EXPECT_EQ(scene.debugView, DebugView::Normal);
  EXPECT_EQ(scene.cameraPosition, glm::dvec3(1.5, 72.0, -4.25));
  EXPECT_EQ(scene.cameraLookAt, glm::dvec3(0.0, 64.0, 0.0));
  EXPECT_FLOAT_EQ(scene.fov, 55.5f);
}

TEST(SceneFile, AbsentKeysTakeTheirDefaults) {
  for (const char* json : {"{}", R"({"world": {}, "render": {}, "camera": {}})"}) {
    const SceneFile scene = parseScene(json, "");
    EXPECT_EQ(scene.file, std::filesystem::path());
    EXPECT_EQ(scene.generator, "terrain");
    EXPECT_EQ(scene.seed, 1u);
    EXPECT_TRUE(scene.edits.empty());
    EXPECT_EQ(scene.packs, std::vector<std::filesystem::path>{resourcePackDir() / "default"});
    EXPECT_EQ(scene.time, 6000);
    EXPECT_EQ(scene.sunPathRotation, 0.0f);
    EXPECT_EQ(scene.width, 320);
    EXPECT_EQ(scene.height, 180);
    EXPECT_EQ(scene.viewDistance, 4);
    EXPECT_EQ(scene.renderScale, 1.0f) << "goldens are drawn at scale 1";
    EXPECT_EQ(scene.targetFps, 0) << "dynamic resolution is off in scenes";
    EXPECT_EQ(scene.debugView, DebugView::None);
    EXPECT_EQ(scene.cameraPosition, glm::dvec3(0.0, 80.0, 0.0));
    EXPECT_EQ(scene.cameraLookAt, glm::dvec3(0.0, 80.0, -1.0));
    EXPECT_EQ(scene.fov, 70.0f);
  }
}

TEST(SceneFile, PackPathsResolveAgainstTheSceneDirectory) {
  const SceneFile scene = parseScene(
      R"({"packs": ["default", "../packs/x", "/abs/pack", "hd.zip", "./a/../b"]})", "scenes/sub/a.json");
  const std::vector<std::filesystem::path> expected = {resourcePackDir() / "default", "scenes/packs/x",
                                                       "/abs/pack", "scenes/sub/hd.zip", "scenes/sub/b"};
  EXPECT_EQ(scene.packs, expected);
  // With no file name, relative paths stay relative (to the working directory).
  EXPECT_EQ(parseScene(R"({"packs": ["hd"]})", "").packs, std::vector<std::filesystem::path>{"hd"});
}

// Paths under "$TERRASOL_TESTDATA/" name the optional third-party test data; without it the scene
// says which key needed it.
TEST(SceneFile, TestDataPathsResolveUnderTERRASOL_TESTDATAOrNameTheKey) {
  const char* before = std::getenv("TERRASOL_TESTDATA");
  const std::string saved = before ? before : "";
  const auto dir = testing::scratchDir("scene_test_data");
  setenv("TERRASOL_TESTDATA", dir.c_str(), 1);
  const std::string json = R"({ "packs": ["default", "$TERRASOL_TESTDATA/packs/p"],
                                "props": [{ "model": "$TERRASOL_TESTDATA/gltf/b.glb" }] })";
  const SceneFile scene = parseScene(json, kFile);
  EXPECT_EQ(scene.packs.back(), dir / "packs" / "p");
  EXPECT_EQ(scene.props[0].model, dir / "gltf" / "b.glb");
  setenv("TERRASOL_TESTDATA", (dir / "absent").c_str(), 1);
  const std::string message = errorOf(json);
  EXPECT_NE(message.find("packs[1]"), std::string::npos) << message;
  EXPECT_NE(message.find("TERRASOL_TESTDATA"), std::string::npos) << message;
  if (before) {
    setenv("TERRASOL_TESTDATA", saved.c_str(), 1);
  } else {
    unsetenv("TERRASOL_TESTDATA");
  }
}

TEST(SceneFile, LoadsFromDiskWithPacksBesideTheScene) {
  const auto dir = testing::scratchDir("scene_file");
  writeFile(dir / "scene.json", R"({"packs": ["default", "mine"], "time": 18000})");
  const SceneFile scene = loadScene(dir / "scene.json");
  EXPECT_EQ(scene.file, dir / "scene.json");
  EXPECT_EQ(scene.time, 18000);
  EXPECT_EQ(scene.packs, (std::vector<std::filesystem::path>{resourcePackDir() / "default", dir / "mine"}));
}

TEST(SceneFile, MissingOrUnreadableFileIsAnError) {
  const auto dir = testing::scratchDir("scene_file_missing");
  const auto missing = dir / "missing.json";
  try {
    loadScene(missing);
    FAIL() << "no error for a missing file";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string() + ": cannot open"), std::string::npos) << e.what();
  }
  try {
    loadScene(dir);
    FAIL() << "no error for a directory";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(dir.string() + ": is a directory"), std::string::npos) << e.what();
  }
}

TEST(SceneFile, SyntaxErrorsGiveLineAndColumn) {
  EXPECT_TRUE(failsWith("{\n  \"time\": 6000,\n  \"render\": {\"width\": 32,,}\n}",
                        "scenes/a.json:3:26: invalid JSON: "));
  EXPECT_TRUE(failsWith("{\"time\": 6000", "scenes/a.json:1:14: invalid JSON: "));
  EXPECT_TRUE(failsWith("", "scenes/a.json:1:1: invalid JSON: "));
  EXPECT_TRUE(failsWith("{\"time\": 1e999}", "scenes/a.json: invalid JSON: number overflow"));
  EXPECT_EQ(errorOf("{\n\n  x}", "").rfind("line 3, column 3: invalid JSON: ", 0), 0u)
      << errorOf("{\n\n  x}", "");
}

TEST(SceneFile, CommentsAreAllowed) {
  EXPECT_EQ(parseScene("{ // noon\n \"time\": 6000 /* ticks */ }", kFile).time, 6000);
}

TEST(SceneFile, UnknownKeysAreErrorsAtEveryLevel) {
  EXPECT_TRUE(failsWith(R"({"tim": 5})", "scenes/a.json: tim: unknown key"));
  EXPECT_TRUE(failsWith(R"({"world": {"gen": "flat"}})", "scenes/a.json: world.gen: unknown key"));
  EXPECT_TRUE(failsWith(R"({"render": {"widht": 5}})", "scenes/a.json: render.widht: unknown key"));
  EXPECT_TRUE(failsWith(R"({"camera": {"lookat": [0, 0, 0]}})", "scenes/a.json: camera.lookat: unknown key"));
  EXPECT_TRUE(
      failsWith(withEdit(R"({"set": [0, 0, 0], "block": "stone"}, {"set": [0, 0, 0], "blok": "stone"})"),
                "scenes/a.json: world.edits[1].blok: unknown key"));
  // The key path alone when the scene has no file name.
  EXPECT_EQ(errorOf(R"({"tim": 5})", "").rfind("tim: unknown key", 0), 0u) << errorOf(R"({"tim": 5})", "");
}

TEST(SceneFile, WrongTypesNameTheKey) {
  EXPECT_TRUE(failsWith("[1, 2]", "scenes/a.json: expected an object, got an array"));
  EXPECT_TRUE(failsWith(R"({"world": 5})", "scenes/a.json: world: expected an object, got 5"));
  EXPECT_TRUE(
      failsWith(R"({"world": {"generator": "flatt"}})", "scenes/a.json: world.generator: expected one of"));
  EXPECT_TRUE(failsWith(R"({"world": {"generator": 1}})", "scenes/a.json: world.generator: expected one of"));
  EXPECT_TRUE(
      failsWith(R"({"world": {"seed": "abc"}})", "scenes/a.json: world.seed: expected a whole number"));
  EXPECT_TRUE(failsWith(R"({"world": {"seed": -1}})", "scenes/a.json: world.seed: expected a whole number"));
  EXPECT_TRUE(failsWith(R"({"world": {"edits": {}}})", "scenes/a.json: world.edits: expected an array"));
  EXPECT_TRUE(failsWith(R"({"packs": "default"})", "scenes/a.json: packs: expected a non-empty array"));
  EXPECT_TRUE(failsWith(R"({"packs": []})", "scenes/a.json: packs: expected a non-empty array"));
  EXPECT_TRUE(
      failsWith(R"({"packs": ["default", 3]})", "scenes/a.json: packs[1]: expected a non-empty string"));
  EXPECT_TRUE(failsWith(R"({"packs": [""]})", "scenes/a.json: packs[0]: expected a non-empty string"));
  EXPECT_TRUE(failsWith(R"({"time": "noon"})", "scenes/a.json: time: expected a whole number"));
  EXPECT_TRUE(
      failsWith(R"({"sun_path_rotation": null})", "scenes/a.json: sun_path_rotation: expected a number"));
  EXPECT_TRUE(failsWith(R"({"render": []})", "scenes/a.json: render: expected an object"));
  EXPECT_TRUE(
      failsWith(R"({"render": {"width": "320"}})", "scenes/a.json: render.width: expected a whole number"));
  EXPECT_TRUE(failsWith(R"({"camera": {"fov": "wide"}})", "scenes/a.json: camera.fov: expected a number"));
  EXPECT_TRUE(failsWith(R"({"camera": {"position": [0, "1", 0]}})",
                        "scenes/a.json: camera.position[1]: expected a number"));
}

TEST(SceneFile, SpecularModelAndMaterialAo) {
  const SceneFile scene =
      parseScene(R"({"render": {"specular": "ggx", "material_ao": false}})", "scenes/a.json");
  EXPECT_EQ(scene.specular, SpecularModel::Ggx);
  EXPECT_FALSE(scene.materialAo);
  EXPECT_TRUE(
      failsWith(R"({"render": {"specular": "phong"}})", "scenes/a.json: render.specular: expected one of"));
  EXPECT_TRUE(failsWith(R"({"render": {"material_ao": 1}})",
                        "scenes/a.json: render.material_ao: expected true or false"));
}

TEST(SceneFile, ReflectionSettings) {
  const SceneFile scene = parseScene(R"({"render": {"reflections": {"enabled": false, "max_steps": 64,
      "thickness": 0.5, "resolution_scale": 0.5, "min_smoothness": 0.8, "max_distance": 32}}})",
                                     "scenes/a.json");
  const ReflectionSettings& r = scene.reflections;
  EXPECT_FALSE(r.enabled);
  EXPECT_EQ(r.maxSteps, 64);
  EXPECT_FLOAT_EQ(r.thickness, 0.5f);
  EXPECT_FLOAT_EQ(r.resolutionScale, 0.5f);
  EXPECT_FLOAT_EQ(r.minSmoothness, 0.8f);
  EXPECT_FLOAT_EQ(r.maxDistance, 32.0f);
  EXPECT_EQ(parseScene("{}", "a.json").reflections, ReflectionSettings{}) << "absent: the defaults";
  EXPECT_TRUE(failsWith(R"({"render": {"reflections": {"max_steps": 0}}})",
                        "render.reflections.max_steps: expected"));
  EXPECT_TRUE(failsWith(R"({"render": {"reflections": {"resolution_scale": 0.1}}})",
                        "render.reflections.resolution_scale: expected"));
  EXPECT_TRUE(failsWith(R"({"render": {"reflections": {"min_smoothness": 1.5}}})",
                        "render.reflections.min_smoothness: expected"));
  EXPECT_TRUE(failsWith(R"({"render": {"reflections": {"mirror": true}}})",
                        "render.reflections.mirror: unknown key"));
  EXPECT_TRUE(parseScene(R"({"render": {"water": {"waves": true}}})", "a.json").water.waves);
  EXPECT_FALSE(parseScene(R"({"render": {"water": {"waves": false}}})", "a.json").water.waves);
  EXPECT_TRUE(parseScene("{}", "a.json").water.waves) << "waves by default";
  EXPECT_TRUE(
      failsWith(R"({"render": {"water": {"waves": 1}}})", "render.water.waves: expected true or false"));
}

TEST(SceneFile, CloudSettings) {
  EXPECT_EQ(parseScene("{}", "a.json").clouds, CloudSettings{}) << "absent: the defaults";
  EXPECT_EQ(CloudSettings{}.mode, CloudMode::Off) << "a scene draws no clouds unless it asks";
  for (std::size_t i = 0; i < kCloudModes.size(); ++i) {
    const std::string json = R"({"render": {"clouds": {"mode": ")" + std::string(kCloudModes[i]) + R"("}}})";
    EXPECT_EQ(parseScene(json, "a.json").clouds.mode, static_cast<CloudMode>(i)) << kCloudModes[i];
  }
  EXPECT_FALSE(parseScene(R"({"render": {"clouds": {"shadows": false}}})", "a.json").clouds.shadows);
  EXPECT_TRUE(failsWith(R"({"render": {"clouds": {"mode": "cumulus"}}})", "render.clouds.mode: expected"));
  EXPECT_TRUE(failsWith(R"({"render": {"clouds": {"height": 128}}})", "render.clouds.height: unknown key"));
  CloudSettings back;
  parseClouds(cloudsJson({CloudMode::Flat, false}), "clouds", back);
  EXPECT_EQ(back, (CloudSettings{CloudMode::Flat, false}));
}

TEST(SceneFile, FogAndShaftSettings) {
  const SceneFile scene = parseScene(R"({"render": {"fog": {"density": 0.02, "base": 70, "falloff": 8},
      "shafts": {"enabled": true, "samples": 16, "scale": 0.5}}})",
                                     "a.json");
  EXPECT_EQ(scene.fog, (FogSettings{0.02f, 70.0f, 8.0f}));
  EXPECT_EQ(scene.shafts, (ShaftSettings{true, 16, 0.5f}));
  EXPECT_EQ(parseScene("{}", "a.json").fog.density, 0.0f) << "no height fog unless asked";
  EXPECT_FALSE(parseScene("{}", "a.json").shafts.enabled);
  EXPECT_TRUE(failsWith(R"({"render": {"fog": {"falloff": 0}}})", "render.fog.falloff: expected"));
  EXPECT_TRUE(failsWith(R"({"render": {"shafts": {"samples": 0}}})", "render.shafts.samples: expected"));
  FogSettings fog;
  parseFog(fogJson({0.5f, -3.0f, 100.0f}), "fog", fog);
  EXPECT_EQ(fog, (FogSettings{0.5f, -3.0f, 100.0f}));
  ShaftSettings shafts;
  parseShafts(shaftsJson({true, 3, 0.125f}), "shafts", shafts);
  EXPECT_EQ(shafts, (ShaftSettings{true, 3, 0.125f}));
}

// Every name a file may give parses to the enum value of the same index.
TEST(SceneFile, EveryEnumNameParsesToItsValue) {
  for (std::size_t i = 0; i < kDebugViews.size(); ++i) {
    const std::string json = R"({"render": {"debug_view": ")" + std::string(kDebugViews[i]) + R"("}})";
    EXPECT_EQ(parseScene(json, "a.json").debugView, static_cast<DebugView>(i)) << kDebugViews[i];
  }
  for (std::size_t i = 0; i < kSpecularModels.size(); ++i) {
    const std::string json = R"({"render": {"specular": ")" + std::string(kSpecularModels[i]) + R"("}})";
    EXPECT_EQ(parseScene(json, "a.json").specular, static_cast<SpecularModel>(i)) << kSpecularModels[i];
  }
  for (std::size_t i = 0; i < kShadowWarps.size(); ++i) {
    ShadowSettings s;
    parseShadow(
        {{"warp", kShadowWarps[i]}, {"mode", kShadowModes[i % 2]}, {"pcf", {{"pattern", kPcfPatterns[i]}}}},
        "shadow", s);
    EXPECT_EQ(s.warp, static_cast<ShadowWarp>(i));
    EXPECT_EQ(s.mode, static_cast<ShadowMode>(i % 2));
    EXPECT_EQ(s.pcfPattern, static_cast<PcfPattern>(i));
  }
}

TEST(SceneFile, ShadowSettings) {
  const SceneFile scene =
      parseScene(R"({"render": {"shadow": {"enabled": false, "mode": "cascaded", "cascades": 3,
      "resolution": 512, "distance": 64, "warp": "square", "warp_strength": 0.5, "shift_ahead": 0.3,
      "update_frames": 8, "pcf": {"samples": 2, "radius": 0.5, "radius_unit": "blocks", "pattern": "grid"}}}})",
                 "scenes/a.json");
  const ShadowSettings& s = scene.shadow;
  EXPECT_FALSE(s.enabled);
  EXPECT_EQ(s.mode, ShadowMode::Cascaded);
  EXPECT_EQ(s.cascades, 3);
  EXPECT_EQ(s.resolution, 512);
  EXPECT_FLOAT_EQ(s.distance, 64.0f);
  EXPECT_EQ(s.warp, ShadowWarp::Square);
  EXPECT_FLOAT_EQ(s.warpStrength, 0.5f);
  EXPECT_FLOAT_EQ(s.shiftAhead, 0.3f);
  EXPECT_EQ(s.updateFrames, 8);
  EXPECT_EQ(s.pcfSamples, 2);
  EXPECT_FLOAT_EQ(s.pcfRadius, 0.5f);
  EXPECT_TRUE(s.pcfRadiusInBlocks);
  EXPECT_EQ(s.pcfPattern, PcfPattern::Grid);
  ShadowSettings back;
  parseShadow(shadowJson(s), "render.shadow", back);
  EXPECT_EQ(back, s) << "written and read back, every value is the same";
  EXPECT_TRUE(
      failsWith(R"({"render": {"shadow": {"warp_strength": 1}}})", "render.shadow.warp_strength: expected"));
  EXPECT_TRUE(
      failsWith(R"({"render": {"shadow": {"resolution": 8}}})", "render.shadow.resolution: expected"));
  EXPECT_TRUE(failsWith(R"({"render": {"shadow": {"cascades": 5}}})", "render.shadow.cascades: expected"));
  EXPECT_TRUE(failsWith(R"({"render": {"shadow": {"pcf": {"radius_unit": "feet"}}}})",
                        "render.shadow.pcf.radius_unit: expected one of"));
  EXPECT_TRUE(
      failsWith(R"({"render": {"shadow": {"mode": "ray_traced"}}})", "render.shadow.mode: expected one of"));
  EXPECT_TRUE(failsWith(R"({"render": {"shadow": {"softness": 1}}})", "render.shadow.softness: unknown key"));
  EXPECT_TRUE(
      failsWith(R"({"render": {"shadow": {"update_frames": 0}}})", "render.shadow.update_frames: expected"));
  EXPECT_TRUE(
      failsWith(R"({"render": {"shadow": {"update_frames": 17}}})", "render.shadow.update_frames: expected"));
}

TEST(SceneFile, CaveCulling) {
  EXPECT_TRUE(parseScene("{}", "scenes/a.json").caveCulling);
  EXPECT_FALSE(parseScene(R"({"render": {"cave_culling": false}})", "scenes/a.json").caveCulling);
  EXPECT_TRUE(parseScene("{}", "scenes/a.json").shadowCasterCulling);
  EXPECT_FALSE(
      parseScene(R"({"render": {"shadow_caster_culling": false}})", "scenes/a.json").shadowCasterCulling);
  EXPECT_TRUE(
      failsWith(R"({"render": {"cave_culling": "no"}})", "render.cave_culling: expected true or false"));
}

TEST(SceneFile, WrongArrayLengthsNameTheKey) {
  EXPECT_TRUE(failsWith(R"({"camera": {"position": [1, 2]}})",
                        "scenes/a.json: camera.position: expected an array of 3 numbers"));
  EXPECT_TRUE(failsWith(R"({"camera": {"look_at": [1, 2, 3, 4]}})",
                        "scenes/a.json: camera.look_at: expected an array of 3 numbers"));
  EXPECT_TRUE(failsWith(R"({"camera": {"position": 5}})",
                        "scenes/a.json: camera.position: expected an array of 3 numbers"));
  EXPECT_TRUE(
      failsWith(withEdit(R"({"set": [0, 0, 0], "block": "a"}, {"fill": [0, 0, 0, 1, 1], "block": "a"})"),
                "scenes/a.json: world.edits[1].fill: expected an array of 6 whole numbers"));
  EXPECT_TRUE(failsWith(withEdit(R"({"set": [0, 0], "block": "a"})"),
                        "scenes/a.json: world.edits[0].set: expected an array of 3 whole numbers"));
}

TEST(SceneFile, EditCoordinatesAreWholeInt32Numbers) {
  EXPECT_TRUE(failsWith(withEdit(R"({"set": [0, 1.5, 0], "block": "a"})"),
                        "scenes/a.json: world.edits[0].set[1]: expected a whole number"));
  EXPECT_TRUE(failsWith(
      withEdit(R"({"fill": [0, 0, 0, 3000000000, 0, 0], "block": "a"})"),
      "scenes/a.json: world.edits[0].fill[3]: expected a whole number from -2147483648 to 2147483647"));
  EXPECT_TRUE(failsWith(withEdit(R"({"set": [0, true, 0], "block": "a"})"),
                        "scenes/a.json: world.edits[0].set[1]: expected a whole number"));
  // Outside the world's height is fine (ignored later); 2.0 and 1e3 are whole.
  const SceneFile scene = parseScene(withEdit(R"({"set": [-2147483648, 1000, 2.0], "block": "a"},
                                                 {"fill": [2147483647, -500, 1e3, 0, 0, 0], "block": "b"})"),
                                     kFile);
  ASSERT_EQ(scene.edits.size(), 2u);
  EXPECT_EQ(scene.edits[0].from, glm::ivec3(-2147483647 - 1, 1000, 2));
  EXPECT_EQ(scene.edits[1].from, glm::ivec3(0, -500, 0));
  EXPECT_EQ(scene.edits[1].to, glm::ivec3(2147483647, 0, 1000));
}

TEST(SceneFile, EditsNeedExactlyOneShapeAndABlock) {
  EXPECT_TRUE(failsWith(withEdit(R"({"fill": [0, 0, 0, 1, 1, 1], "set": [0, 0, 0], "block": "a"})"),
                        "scenes/a.json: world.edits[0]: has both \"fill\" and \"set\""));
  EXPECT_TRUE(failsWith(withEdit(R"({"block": "a"})"), "scenes/a.json: world.edits[0]: needs \"fill\""));
  EXPECT_TRUE(failsWith(withEdit(R"({"set": [0, 0, 0], "block": "a"}, {"set": [0, 0, 0]})"),
                        "scenes/a.json: world.edits[1]: needs \"block\""));
  EXPECT_TRUE(failsWith(withEdit(R"({"set": [0, 0, 0], "block": ""})"),
                        "scenes/a.json: world.edits[0].block: expected a non-empty string"));
  EXPECT_TRUE(failsWith(withEdit(R"({"set": [0, 0, 0], "block": 1})"),
                        "scenes/a.json: world.edits[0].block: expected a non-empty string"));
  EXPECT_TRUE(failsWith(withEdit(R"("stone")"), "scenes/a.json: world.edits[0]: expected an object"));
}

TEST(SceneFile, OutOfRangeValuesNameTheKey) {
  EXPECT_TRUE(failsWith(R"({"render": {"width": 0}})",
                        "scenes/a.json: render.width: expected a whole number from 1"));
  EXPECT_TRUE(failsWith(R"({"render": {"width": 8193}})", "scenes/a.json: render.width: "));
  EXPECT_TRUE(failsWith(R"({"render": {"width": 320.5}})", "scenes/a.json: render.width: "));
  EXPECT_TRUE(failsWith(R"({"render": {"height": 0}})", "scenes/a.json: render.height: "));
  EXPECT_TRUE(failsWith(R"({"render": {"height": 9000}})", "scenes/a.json: render.height: "));
  EXPECT_TRUE(failsWith(R"({"render": {"view_distance": 33}})", "scenes/a.json: render.view_distance: "));
  EXPECT_TRUE(failsWith(R"({"render": {"target_fps": -1}})", "scenes/a.json: render.target_fps: "));
  EXPECT_TRUE(failsWith(R"({"render": {"scale": 0.2}})", "scenes/a.json: render.scale: "));
  EXPECT_TRUE(failsWith(R"({"render": {"view_distance": -1}})", "scenes/a.json: render.view_distance: "));
  EXPECT_TRUE(
      failsWith(R"({"camera": {"fov": 0}})", "scenes/a.json: camera.fov: expected a number greater than 0"));
  EXPECT_TRUE(failsWith(R"({"camera": {"fov": 180}})", "scenes/a.json: camera.fov: "));
  EXPECT_TRUE(failsWith(R"({"camera": {"fov": -10}})", "scenes/a.json: camera.fov: "));
  EXPECT_TRUE(failsWith(R"({"sun_path_rotation": 90.5})",
                        "scenes/a.json: sun_path_rotation: expected a number from"));
  EXPECT_TRUE(failsWith(R"({"sun_path_rotation": -91})", "scenes/a.json: sun_path_rotation: "));
  EXPECT_TRUE(failsWith(R"({"time": -1})", "scenes/a.json: time: expected a whole number >= 0"));
  EXPECT_TRUE(failsWith(R"({"time": 100.5})", "scenes/a.json: time: "));
  EXPECT_TRUE(failsWith(R"({"time": 1e30})", "scenes/a.json: time: "));
  EXPECT_TRUE(failsWith(R"({"render": {"debug_view": "normals"}})",
                        "scenes/a.json: render.debug_view: expected one of \"none\", \"albedo\""));
}

TEST(SceneFile, ValuesAtTheEdgesOfTheirRangesParse) {
  EXPECT_TRUE(parses(R"({"render": {"width": 1, "height": 8192, "view_distance": 0}})"));
  EXPECT_TRUE(parses(R"({"render": {"width": 8192, "height": 1, "view_distance": 32}})"));
  EXPECT_TRUE(parses(R"({"camera": {"fov": 1}, "sun_path_rotation": -90})"));
  EXPECT_TRUE(parses(R"({"camera": {"fov": 170}, "sun_path_rotation": 90})"));
  EXPECT_TRUE(parses(R"({"camera": {"position": [3, 4, 5], "look_at": [3, 4, 5]}})"));
  EXPECT_TRUE(parses(R"({"world": {"generator": "void", "seed": 0}, "time": 0})"));
  EXPECT_EQ(parseScene(R"({"time": 1e9})", kFile).time, 1000000000);
  EXPECT_EQ(parseScene(R"({"time": 9223372036854775807})", kFile).time, 9223372036854775807);
}

}  // namespace
}  // namespace terrasol
