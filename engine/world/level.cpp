#include "world/level.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"

namespace terrasol {
namespace {

using nlohmann::json;

template <class T>
T required(const json& root, const char* key, const std::string& file) {
  if (!root.contains(key)) throw Error(file + ": missing key \"" + key + "\"");
  try {
    return root[key].get<T>();
  } catch (const json::exception&) {
    throw Error(file + ": key \"" + key + "\" has the wrong type");
  }
}

}  // namespace

Level loadLevel(const std::filesystem::path& file) {
  const std::string name = file.string();
  json root;
  try {
    root = json::parse(readTextFile(file));
  } catch (const json::parse_error& e) {
    throw Error(name + ": invalid JSON: " + e.what());
  }
  if (!root.is_object()) throw Error(name + ": expected a JSON object");
  Level level;
  level.generator = required<std::string>(root, "generator", name);
  level.seed = required<std::uint64_t>(root, "seed", name);
  level.time = required<std::int64_t>(root, "time", name);
  const json player = required<json>(root, "player", name);
  const auto position = required<std::vector<double>>(player, "position", name + ": player");
  if (position.size() != 3 || !std::isfinite(position[0]) || !std::isfinite(position[1]) ||
      !std::isfinite(position[2])) {
    throw Error(name + ": player.position must be three finite numbers");
  }
  level.playerPosition = {position[0], position[1], position[2]};
  level.playerYaw = required<float>(player, "yaw", name + ": player");
  level.playerPitch = required<float>(player, "pitch", name + ": player");
  if (player.contains("flying")) level.playerFlying = required<bool>(player, "flying", name + ": player");
  return level;
}

void saveLevel(const std::filesystem::path& file, const Level& level) {
  const json root = {
      {"version", 1},
      {"generator", level.generator},
      {"seed", level.seed},
      {"time", level.time},
      {"player",
       {{"position", {level.playerPosition.x, level.playerPosition.y, level.playerPosition.z}},
        {"yaw", level.playerYaw},
        {"pitch", level.playerPitch},
        {"flying", level.playerFlying}}},
  };
  writeFileAtomically(file, root.dump(2) + "\n");
}

}  // namespace terrasol
