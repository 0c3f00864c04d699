#include "scene/scene_file.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <sstream>

#include "core/error.h"
#include "core/json_check.h"
#include "core/paths.h"
#include "core/render_preset.h"
#include "core/render_scale.h"

namespace terrasol {
namespace {

using nlohmann::json;
using std::filesystem::path;
using namespace json_check;

constexpr std::array<std::string_view, 5> kGenerators = {"void", "flat", "terrain", "blocks", "lights"};
constexpr std::int64_t kMaxInt64 = std::numeric_limits<std::int64_t>::max();
constexpr std::int64_t kMinInt32 = std::numeric_limits<std::int32_t>::min();
constexpr std::int64_t kMaxInt32 = std::numeric_limits<std::int32_t>::max();
constexpr std::int64_t kMaxFrames = 100000;

template <std::size_t N>
std::array<int, N> cells(const json& value, const std::string& key) {
  if (!value.is_array() || value.size() != N) {
    expected(key, join({"an array of ", std::to_string(N), " whole numbers"}), value);
  }
  std::array<int, N> out{};
  for (std::size_t i = 0; i < N; ++i) {
    out[i] = static_cast<int>(wholeNumber(value[i], element(key, i), kMinInt32, kMaxInt32));
  }
  return out;
}

SceneEdit parseEdit(const json& value, const std::string& key) {
  checkObject(value, key, {"fill", "set", "block", "at_frame"});
  const json* fill = field(value, "fill");
  const json* set = field(value, "set");
  if (fill && set) fail(key, "has both \"fill\" and \"set\"; give one");
  if (!fill && !set) fail(key, "needs \"fill\" (a box) or \"set\" (one block)");
  const json* block = field(value, "block");
  if (!block) fail(key, "needs \"block\"");
  SceneEdit edit;
  edit.key = key;
  edit.block = nonEmptyString(*block, member(key, "block"));
  if (fill) {
    const auto c = cells<6>(*fill, member(key, "fill"));
    edit.kind = SceneEdit::Kind::Fill;
    edit.from = glm::min(glm::ivec3(c[0], c[1], c[2]), glm::ivec3(c[3], c[4], c[5]));
    edit.to = glm::max(glm::ivec3(c[0], c[1], c[2]), glm::ivec3(c[3], c[4], c[5]));
  } else {
    const auto c = cells<3>(*set, member(key, "set"));
    edit.from = edit.to = glm::ivec3(c[0], c[1], c[2]);
  }
  if (const json* f = field(value, "at_frame")) {
    edit.atFrame = static_cast<int>(wholeNumber(*f, member(key, "at_frame"), 0, kMaxFrames - 1));
  }
  return edit;
}

std::vector<SceneEdit> parseEdits(const json& value, const std::string& key) {
  if (!value.is_array()) expected(key, "an array of edits", value);
  std::vector<SceneEdit> edits;
  for (std::size_t i = 0; i < value.size(); ++i) edits.push_back(parseEdit(value[i], element(key, i)));
  return edits;
}

path resolvePath(const std::string& name, const path& sceneDir, const std::string& key);

void parseWorld(const json& world, SceneFile& scene, const path& sceneDir) {
  checkObject(world, "world", {"generator", "seed", "edits", "minecraft"});
  if (const json* v = field(world, "generator")) scene.generator = oneOf(*v, "world.generator", kGenerators);
  if (const json* v = field(world, "seed")) scene.seed = seedNumber(*v, "world.seed");
  if (const json* v = field(world, "edits")) scene.edits = parseEdits(*v, "world.edits");
  if (const json* v = field(world, "minecraft")) {
    if (field(world, "generator") || field(world, "seed"))
      fail("world.minecraft", "a Minecraft save is the world: leave out generator and seed");
    scene.minecraftWorld = resolvePath(nonEmptyString(*v, "world.minecraft"), sceneDir, "world.minecraft");
  }
}

// A file a scene names: absolute, relative to the scene file, or under the third-party test data
// folder with the prefix "$TERRASOL_TESTDATA/" (core/paths.h testDataDir); an error naming `key`
// when that folder is absent.
path resolvePath(const std::string& name, const path& sceneDir, const std::string& key) {
  constexpr std::string_view kTestData = "$TERRASOL_TESTDATA/";
  if (name.starts_with(kTestData)) {
    std::string why;
    const auto dir = testDataDir(&why);
    if (!dir) fail(key, why);
    return (*dir / name.substr(kTestData.size())).lexically_normal();
  }
  const path file(name);
  return file.is_absolute() ? file : (sceneDir / file).lexically_normal();
}

path resolvePack(const std::string& name, const path& sceneDir, const std::string& key) {
  if (name == "default") return resourcePackDir() / "default";
  return resolvePath(name, sceneDir, key);
}

std::vector<path> parsePacks(const json& value, const path& sceneDir) {
  if (!value.is_array() || value.empty()) expected("packs", "a non-empty array of pack paths", value);
  std::vector<path> packs;
  for (std::size_t i = 0; i < value.size(); ++i) {
    packs.push_back(
        resolvePack(nonEmptyString(value[i], element("packs", i)), sceneDir, element("packs", i)));
  }
  return packs;
}

SceneProp parseProp(const json& value, const std::string& key, const path& sceneDir) {
  checkObject(value, key, {"model", "position", "rotation", "scale"});
  const json* model = field(value, "model");
  if (!model) fail(key, "needs \"model\" (a .gltf or .glb file)");
  SceneProp prop;
  prop.key = key;
  prop.model = resolvePath(nonEmptyString(*model, member(key, "model")), sceneDir, member(key, "model"));
  if (const json* v = field(value, "position")) prop.position = vec3(*v, member(key, "position"));
  if (const json* v = field(value, "rotation")) prop.rotation = glm::vec3(vec3(*v, member(key, "rotation")));
  if (const json* v = field(value, "scale"))
    prop.scale = numberIn(*v, member(key, "scale"), 0.0, 1000.0, true);
  return prop;
}

std::vector<SceneProp> parseProps(const json& value, const path& sceneDir) {
  if (!value.is_array()) expected("props", "an array of props", value);
  std::vector<SceneProp> props;
  for (std::size_t i = 0; i < value.size(); ++i)
    props.push_back(parseProp(value[i], element("props", i), sceneDir));
  return props;
}

void parseRender(const json& render, const path& sceneDir, SceneFile& scene) {
  checkObject(render, "render",
              {"width",
               "height",
               "scale",
               "target_fps",
               "view_distance",
               "debug_view",
               "specular",
               "material_ao",
               "cave_culling",
               "shadow_caster_culling",
               "cull_faces_away",
               "leave_out_absent_maps",
               "cull_passes",
               "shadow",
               "reflections",
               "water",
               "shaderpack",
               "antialiasing",
               "bloom",
               "clouds",
               "fog",
               "shafts",
               "lod",
               "preset"});
  // First: the scene's own keys change what the preset set.
  if (const json* v = field(render, "preset")) {
    applyPreset(enumOf(*v, "render.preset", kRenderPresets), scene);
  }
  if (const json* v = field(render, "shaderpack")) {
    scene.shaderpack = resolvePath(nonEmptyString(*v, "render.shaderpack"), sceneDir, "render.shaderpack");
  }
  if (const json* v = field(render, "width")) {
    scene.width = static_cast<int>(wholeNumber(*v, "render.width", 1, 8192));
  }
  if (const json* v = field(render, "height")) {
    scene.height = static_cast<int>(wholeNumber(*v, "render.height", 1, 8192));
  }
  if (const json* v = field(render, "scale")) {
    scene.renderScale =
        static_cast<float>(numberIn(*v, "render.scale", kMinRenderScale, kMaxRenderScale, false));
  }
  if (const json* v = field(render, "target_fps")) {
    scene.targetFps = static_cast<int>(wholeNumber(*v, "render.target_fps", 0, 1000));
  }
  if (const json* v = field(render, "view_distance")) {
    scene.viewDistance = static_cast<int>(wholeNumber(*v, "render.view_distance", 0, 32));
  }
  if (const json* v = field(render, "debug_view")) {
    scene.debugView = enumOf(*v, "render.debug_view", kDebugViews);
  }
  if (const json* v = field(render, "specular"))
    scene.specular = enumOf(*v, "render.specular", kSpecularModels);
  if (const json* v = field(render, "material_ao")) scene.materialAo = boolean(*v, "render.material_ao");
  if (const json* v = field(render, "cave_culling")) scene.caveCulling = boolean(*v, "render.cave_culling");
  if (const json* v = field(render, "antialiasing"))
    scene.antialiasing = enumOf(*v, "render.antialiasing", kAntialiasingModes);
  if (const json* v = field(render, "shadow_caster_culling")) {
    scene.shadowCasterCulling = boolean(*v, "render.shadow_caster_culling");
  }
  if (const json* v = field(render, "cull_faces_away"))
    scene.cullFacesAway = boolean(*v, "render.cull_faces_away");
  if (const json* v = field(render, "cull_passes")) scene.cullPasses = boolean(*v, "render.cull_passes");
  if (const json* v = field(render, "reflections"))
    parseReflections(*v, "render.reflections", scene.reflections);
  if (const json* v = field(render, "water")) {
    checkObject(*v, "render.water", {"waves"});
    if (const json* w = field(*v, "waves")) scene.water.waves = boolean(*w, "render.water.waves");
  }
  if (const json* v = field(render, "bloom")) parseBloom(*v, "render.bloom", scene.bloom);
  if (const json* v = field(render, "clouds")) parseClouds(*v, "render.clouds", scene.clouds);
  if (const json* v = field(render, "fog")) parseFog(*v, "render.fog", scene.fog);
  if (const json* v = field(render, "shafts")) parseShafts(*v, "render.shafts", scene.shafts);
  if (const json* v = field(render, "lod")) parseLod(*v, "render.lod", scene.lod);
  if (const json* v = field(render, "leave_out_absent_maps")) {
    scene.leaveOutAbsentMaps = boolean(*v, "render.leave_out_absent_maps");
  }
  if (const json* v = field(render, "shadow")) parseShadow(*v, "render.shadow", scene.shadow);
}

void parseCamera(const json& camera, SceneFile& scene) {
  checkObject(camera, "camera", {"position", "look_at", "fov"});
  if (const json* v = field(camera, "position")) scene.cameraPosition = vec3(*v, "camera.position");
  if (const json* v = field(camera, "look_at")) scene.cameraLookAt = vec3(*v, "camera.look_at");
  if (const json* v = field(camera, "fov")) scene.fov = numberIn(*v, "camera.fov", 0.0, 180.0, true);
}

CameraKeyframe parseKeyframe(const json& value, const std::string& key, const SceneFile& scene) {
  checkObject(value, key, {"t", "position", "look_at", "fov", "time"});
  for (const char* required : {"t", "position", "look_at"}) {
    if (!field(value, required)) fail(key, join({"needs \"", required, "\""}));
  }
  CameraKeyframe k;
  k.t = numberIn(*field(value, "t"), member(key, "t"), 0.0, 1.0, false);
  k.position = vec3(*field(value, "position"), member(key, "position"));
  k.lookAt = vec3(*field(value, "look_at"), member(key, "look_at"));
  k.fov = scene.fov;
  k.time = scene.time;
  if (const json* v = field(value, "fov")) k.fov = numberIn(*v, member(key, "fov"), 0.0, 180.0, true);
  if (const json* v = field(value, "time")) k.time = wholeNumber(*v, member(key, "time"), 0, kMaxInt64);
  return k;
}

// After "camera" and "time", whose values are the keyframes' defaults.
CameraPath parseCameraPath(const json& value, const SceneFile& scene) {
  checkObject(value, "camera_path", {"frames", "keyframes"});
  CameraPath path;
  if (const json* v = field(value, "frames")) {
    path.frames = static_cast<int>(wholeNumber(*v, "camera_path.frames", 1, kMaxFrames));
  }
  const json* keyframes = field(value, "keyframes");
  if (!keyframes) fail("camera_path", "needs \"keyframes\"");
  if (!keyframes->is_array() || keyframes->empty()) {
    expected("camera_path.keyframes", "a non-empty array of keyframes", *keyframes);
  }
  for (std::size_t i = 0; i < keyframes->size(); ++i) {
    const std::string key = element("camera_path.keyframes", i);
    path.keyframes.push_back(parseKeyframe((*keyframes)[i], key, scene));
    if (i > 0 && path.keyframes[i].t <= path.keyframes[i - 1].t) {
      fail(member(key, "t"), "must be greater than the previous keyframe's");
    }
  }
  return path;
}

void parseCompare(const json& value, SceneFile& scene) {
  checkObject(value, "compare", {"pixel_threshold", "max_failing_percent"});
  if (const json* v = field(value, "pixel_threshold")) {
    scene.compare.pixelThreshold = numberIn(*v, "compare.pixel_threshold", 0.0, 1.0, false);
  }
  if (const json* v = field(value, "max_failing_percent")) {
    scene.compare.maxFailingPercent = numberIn(*v, "compare.max_failing_percent", 0.0, 100.0, false);
  }
}

// Edits keyed to frames must name a frame the scene has.
void checkEditFrames(const SceneFile& scene) {
  for (const SceneEdit& edit : scene.edits) {
    if (edit.atFrame >= scene.frameCount()) {
      fail(member(edit.key, "at_frame"),
           join({"the scene has ", std::to_string(scene.frameCount()), " frame(s), numbered from 0"}));
    }
  }
}

SceneFile parseRoot(const json& root, const path& file) {
  checkObject(
      root, "",
      {"world", "packs", "props", "time", "sun_path_rotation", "render", "camera", "camera_path", "compare"});
  SceneFile scene;
  scene.file = file;
  if (const json* v = field(root, "world")) parseWorld(*v, scene, file.parent_path());
  const json* packs = field(root, "packs");
  scene.packs =
      packs ? parsePacks(*packs, file.parent_path()) : std::vector<path>{resourcePackDir() / "default"};
  if (const json* v = field(root, "props")) scene.props = parseProps(*v, file.parent_path());
  if (const json* v = field(root, "time")) scene.time = wholeNumber(*v, "time", 0, kMaxInt64);
  if (const json* v = field(root, "sun_path_rotation")) {
    scene.sunPathRotation = numberIn(*v, "sun_path_rotation", -90.0, 90.0, false);
  }
  if (const json* v = field(root, "render")) parseRender(*v, file.parent_path(), scene);
  if (const json* v = field(root, "camera")) parseCamera(*v, scene);
  if (const json* v = field(root, "camera_path")) scene.cameraPath = parseCameraPath(*v, scene);
  if (const json* v = field(root, "compare")) parseCompare(*v, scene);
  checkEditFrames(scene);
  return scene;
}

SceneFile parseChecked(const nlohmann::json& root, const std::filesystem::path& file) {
  try {
    return parseRoot(root, file);
  } catch (const Error& e) {
    throw Error(withFile(file, e.what()));
  }
}

}  // namespace

std::string sceneError(const SceneFile& scene, std::string_view key, std::string_view what) {
  return withFile(scene.file, join({key, ": ", what}));
}

SceneFile parseScene(std::string_view json, const std::filesystem::path& file) {
  return parseChecked(parseJson(json, file), file);
}

SceneFile loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  if (std::filesystem::is_directory(file)) throw Error(locate(file, 0, "is a directory, not a scene file"));
  if (overrides.empty()) return parseScene(readTextFile(file), file);
  nlohmann::json root = parseJson(readTextFile(file), file);
  for (const std::string& setting : overrides) applyOverride(root, setting);
  return parseChecked(root, file);
}

}  // namespace terrasol
