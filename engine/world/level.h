#pragma once
// level.json: what a world needs besides its chunks. Written to a temporary file and renamed over the
// old one, so a crash leaves either the old or the new file, never half of one.

#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace terrasol {

// A glTF prop placed in the world (the game's "place prop"): the model file as the player chose it,
// where its origin is, its yaw/pitch/roll in degrees and its uniform scale.
struct LevelProp {
  std::string model;
  glm::dvec3 position{0.0};
  glm::vec3 rotation{0.0f};
  float scale = 1.0f;
};

struct Level {
  std::string generator = "terrain";
  std::uint64_t seed = 0;
  std::int64_t time = 0;  // world time in ticks (kTicksPerDay a day)
  glm::dvec3 playerPosition{0.0, 0.0, 0.0};
  float playerYaw = 0.0f, playerPitch = 0.0f;  // degrees
  bool playerFlying = false;                   // "flying" (absent in older files: false)
  std::vector<LevelProp> props;                // "props" (absent in older files: none)
  // "minecraft": the Minecraft save this world overlays (its chunks in the generator's place, read-only;
  // this folder keeps the edits). Empty for Terrasol's own worlds.
  std::filesystem::path minecraft;
};

// Throws Error naming the file and the key that is missing or wrong.
Level loadLevel(const std::filesystem::path& file);
void saveLevel(const std::filesystem::path& file, const Level& level);

}  // namespace terrasol
