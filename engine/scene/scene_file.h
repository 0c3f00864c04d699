#pragma once
// Scene files for `terrasol-render`: a world, packs, time, render settings and a camera, read from JSON.
// The format, every key with its default, is documented in README.md ("Scene files"). Parsing checks
// shapes, types and ranges only; block names and pack contents are resolved later by their users.

#include <array>
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/day_cycle.h"
#include "core/render_settings.h"
#include "scene/render_settings_json.h"

namespace terrasol {

struct SceneEdit {
  enum class Kind { Fill, Set } kind = Kind::Set;
  glm::ivec3 from{0},
      to{0};          // inclusive; for Set both are the cell. Fill corners are normalised so from <= to.
  std::string block;  // block name, resolved later against the block registry
  std::string key;    // where it came from, e.g. "world.edits[2]", for later error messages
  int atFrame = -1;   // "at_frame": applied just before that frame is drawn; -1: before light, at load
};

// "camera_path": the camera of frame i is at t = i / (frames - 1) along the keyframes.
struct CameraKeyframe {
  double t = 0.0;  // 0..1, strictly increasing along the path
  glm::dvec3 position{0.0}, lookAt{0.0, 0.0, -1.0};
  float fov = 70.0f;          // defaults to camera.fov
  std::int64_t time = kNoon;  // defaults to the scene's time
};
struct CameraPath {
  int frames = 1;                         // 1..100000
  std::vector<CameraKeyframe> keyframes;  // at least one
};

// "props": a glTF model placed in the world (engine/scene/prop_placement.h turns it into a transform).
struct SceneProp {
  std::filesystem::path model;  // .gltf or .glb; relative paths resolve against the scene file
  glm::dvec3 position{0.0};     // blocks: where the model's origin goes
  glm::vec3 rotation{0.0f};     // degrees: yaw (about y), pitch (about x), roll (about z)
  float scale = 1.0f;           // (0, 1000]
  std::string key;              // "props[i]", for later error messages
};

// "compare": how terrasol-render --compare judges a frame against its golden.
struct CompareSettings {
  float pixelThreshold = 10.0f / 255.0f;  // a pixel fails when any channel differs by more (0..1)
  float maxFailingPercent = 0.5f;         // a frame fails when more of its pixels fail (0..100)
};

struct SceneFile {
  std::filesystem::path file;         // the scene file itself ("" when parsed from memory with no name)
  std::string generator = "terrain";  // "void" | "flat" | "terrain"
  std::uint64_t seed = 1;
  // "world.minecraft": a Minecraft Java save in the generator's place (read-only; resolved as packs are).
  std::filesystem::path minecraftWorld;
  std::vector<SceneEdit> edits;  // in file order: later edits overwrite earlier ones
  // Bottom to top. "default" becomes resourcePackDir()/"default"; relative paths are resolved against
  // the scene file's directory. When the key is absent: just the default pack.
  std::vector<std::filesystem::path> packs;
  // "render.shaderpack": an OptiFine/Iris shader pack (folder or .zip) drawn in place of Terrasol's own
  // pipeline, resolved as packs are; empty: none.
  std::filesystem::path shaderpack;
  std::int64_t time = kNoon;      // ticks, >= 0: core/day_cycle.h (kSunrise, kNoon, kSunset, kMidnight)
  float sunPathRotation = 0.0f;   // degrees in [-90, 90], tilts the sun and moon path
  int width = 320, height = 180;  // pixels, 1..8192 each
  int viewDistance = 4;           // chunks, 0..32
  float renderScale = 1.0f;       // render.scale, 0.25..1: the scene drawn smaller, scaled up at the end
  int targetFps = 0;              // render.target_fps: dynamic resolution below render.scale; 0: off
  DebugView debugView = DebugView::None;               // "render.debug_view": one of kDebugViews
  SpecularModel specular = SpecularModel::BlinnPhong;  // "render.specular": one of kSpecularModels
  bool materialAo = true;   // "render.material_ao": LabPBR _n blue darkens ambient light
  bool caveCulling = true;  // "render.cave_culling": leave out sections hidden behind solid ground
  Antialiasing antialiasing = Antialiasing::None;  // "render.antialiasing": one of kAntialiasingModes
  bool shadowCasterCulling = true;  // "render.shadow_caster_culling": no caster shading nothing in view
  bool leaveOutAbsentMaps = true;   // "render.leave_out_absent_maps": no _n/_s sampling when no pack has them
  bool cullFacesAway = true;        // "render.cull_faces_away": face groups turned away are not drawn
  bool cullPasses =
      true;               // "render.cull_passes": no pass whose output nothing reads, or with nothing to draw
  ShadowSettings shadow;  // "render.shadow"
  ReflectionSettings reflections;  // "render.reflections"
  WaterSettings water;             // "render.water"
  BloomSettings bloom;             // "render.bloom"
  CloudSettings clouds;            // "render.clouds"
  FogSettings fog;                 // "render.fog"
  ShaftSettings shafts;            // "render.shafts"
  LodSettings lod;                 // "render.lod"
  glm::dvec3 cameraPosition{0.0, 80.0, 0.0};
  glm::dvec3 cameraLookAt{0.0, 80.0, -1.0};
  float fov = 70.0f;                     // vertical degrees, in (0, 180)
  std::optional<CameraPath> cameraPath;  // when absent: one frame from `camera`
  std::vector<SceneProp> props;
  CompareSettings compare;

  int frameCount() const { return cameraPath ? cameraPath->frames : 1; }
};

// Throws Error "<file>: <key>: <what is wrong>", e.g. "scenes/a.json: camera.position: expected an array
// of 3 numbers"; JSON syntax errors as "<file>:<line>:<column>: invalid JSON: ...". `file` names the scene
// in messages and is the base for relative pack paths (may be empty: then messages start with the key).
SceneFile parseScene(std::string_view json, const std::filesystem::path& file);

// "<file>: <key>: <what>", the form of every error about a scene's content, also for problems found
// after parsing (an unknown block name, a pack that cannot be opened).
std::string sceneError(const SceneFile& scene, std::string_view key, std::string_view what);

// Reads the file (Error naming it if missing or unreadable), then parseScene. `overrides` are
// "key.path=value" settings applied to the JSON first, as terrasol-render's --set: the value is read as
// JSON when it parses (640, true, [1,2,3], "x") and as a string otherwise; a number in the path indexes
// an array (camera_path.keyframes.0.time=0). The result is checked like any scene.
SceneFile loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

}  // namespace terrasol
