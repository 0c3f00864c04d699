#pragma once
// level.json: what a world needs besides its chunks. Written to a temporary file and renamed over the
// old one, so a crash leaves either the old or the new file, never half of one.

#include <cstdint>
#include <filesystem>
#include <string>

#include <glm/vec3.hpp>

namespace terrasol {

struct Level {
  std::string generator = "terrain";
  std::uint64_t seed = 0;
  std::int64_t time = 0;                 // world time in ticks (24000 a day)
  glm::dvec3 playerPosition{0.0, 0.0, 0.0};
  float playerYaw = 0.0f, playerPitch = 0.0f;  // degrees
  bool playerFlying = false;             // "flying" (absent in older files: false)
};

// Throws Error naming the file and the key that is missing or wrong.
Level loadLevel(const std::filesystem::path& file);
void saveLevel(const std::filesystem::path& file, const Level& level);

}  // namespace terrasol
