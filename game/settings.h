#pragma once
// The player's settings, kept in a JSON file (default ~/.config/terrasol/settings.json) and applied
// live from the menu. A missing file means the defaults; a malformed one is an error naming the file
// and the key (never silently replaced: the player's settings are not thrown away).

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "audio/audio_engine.h"
#include "controls.h"
#include "scene/scene_file.h"

namespace terrasol {

struct PackChoice {
  std::filesystem::path path;
  bool enabled = true;
  friend bool operator==(const PackChoice&, const PackChoice&) = default;
};

// What the first start measured and chose (game/first_run.h), kept in the file and shown in the menu.
struct FirstRunRecord {
  std::string glRenderer;
  double frameMs = 0.0;
  std::string choice;
  friend bool operator==(const FirstRunRecord&, const FirstRunRecord&) = default;
};

struct GameSettings {
  int viewDistance = 6;            // chunks, 2..32
  float fov = 70.0f;               // degrees, 30..110
  float mouseSensitivity = 0.15f;  // degrees per pixel, 0.01..2
  float sunPathRotation = -25.0f;  // degrees, -90..90
  bool survivalDigging = false;    // "survival_digging": blocks take their time to break, as in survival
  ShadowSettings shadow = defaultShadow();
  ReflectionSettings reflections;                  // as in scenes
  Antialiasing antialiasing = Antialiasing::None;  // "antialiasing": as render.antialiasing in scenes
  BloomSettings bloom;                             // "bloom": as render.bloom
  CloudSettings clouds{CloudMode::Fancy};          // "clouds": as render.clouds
  FogSettings fog;                                 // "fog": as render.fog
  ShaftSettings shafts;                            // "shafts": as render.shafts
  LodSettings lod{.distance = 32};                 // "lod": as render.lod
  std::vector<PackChoice> packs;                   // stacked bottom to top over the default pack
  std::filesystem::path shaderpack;  // an OptiFine/Iris shader pack drawing instead of Terrasol's pipeline
  KeyBindings keys;
  AudioVolumes sound;  // "sound": {"master", "blocks", "ambient", "music"}, each 0..1
  bool vsync = true;
  float renderScale = 1.0f;                // the scene drawn at this fraction of the window, 0.25..1
  int targetFps = 30;                      // dynamic resolution holds this rate (below render_scale); 0: off
  std::optional<FirstRunRecord> firstRun;  // "first_run": absent in files written by hand

  static ShadowSettings defaultShadow() {
    ShadowSettings s;
    s.resolution = 1024;  // a 1024^2 map over 96 blocks, warped: sharp near, cheap on llvmpipe
    s.distance = 96.0f;
    s.updateFrames = 8;  // Luanti's default: a changed map is spread over 8 frames
    return s;
  }
};

GameSettings parseSettings(std::string_view json, const std::filesystem::path& file);
// The defaults when the file does not exist; throws Error when it is malformed.
GameSettings loadSettings(const std::filesystem::path& file);
void saveSettings(const std::filesystem::path& file, const GameSettings& settings);
std::filesystem::path defaultSettingsFile();

// The settings and the file they are kept in.
struct SettingsFile {
  std::filesystem::path path;
  GameSettings values;
  void save() const { saveSettings(path, values); }
};

}  // namespace terrasol
