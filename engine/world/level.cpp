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

glm::dvec3 finite3(const json& value, const std::string& where) {
  std::vector<double> v;
  try {
    v = value.get<std::vector<double>>();
  } catch (const json::exception&) {
  }
  if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) {
    throw Error(where + " must be three finite numbers");
  }
  return {v[0], v[1], v[2]};
}

LevelProp parseProp(const json& value, const std::string& where) {
  if (!value.is_object()) throw Error(where + ": expected an object");
  LevelProp prop;
  prop.model = required<std::string>(value, "model", where);
  if (prop.model.empty()) throw Error(where + ": \"model\" is empty");
  prop.position = finite3(required<json>(value, "position", where), where + ".position");
  prop.rotation = glm::vec3(finite3(required<json>(value, "rotation", where), where + ".rotation"));
  prop.scale = required<float>(value, "scale", where);
  if (!(prop.scale > 0.0f && prop.scale <= 1000.0f)) throw Error(where + ".scale must be in (0, 1000]");
  return prop;
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
  if (root.contains("props")) {
    const json& props = root["props"];
    if (!props.is_array()) throw Error(name + ": \"props\" must be an array");
    for (std::size_t i = 0; i < props.size(); ++i) {
      level.props.push_back(parseProp(props[i], name + ": props[" + std::to_string(i) + "]"));
    }
  }
  return level;
}

void saveLevel(const std::filesystem::path& file, const Level& level) {
  json props = json::array();
  for (const LevelProp& p : level.props) {
    props.push_back({{"model", p.model},
                     {"position", {p.position.x, p.position.y, p.position.z}},
                     {"rotation", {p.rotation.x, p.rotation.y, p.rotation.z}},
                     {"scale", p.scale}});
  }
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
      {"props", props},
  };
  writeFileAtomically(file, root.dump(2) + "\n");
}

}  // namespace terrasol
