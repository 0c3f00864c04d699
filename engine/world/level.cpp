#include "world/level.h"

#include <limits>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/json_check.h"

namespace terrasol {
namespace {

using namespace json_check;

constexpr std::int64_t kMinInt64 = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t kMaxInt64 = std::numeric_limits<std::int64_t>::max();

float finiteFloat(const json& object, const std::string& key, std::string_view name) {
  return static_cast<float>(finiteNumber(required(object, key, name), member(key, name)));
}

LevelProp parseProp(const json& value, const std::string& key) {
  checkObject(value, key, {"model", "position", "rotation", "scale"});
  LevelProp prop;
  prop.model = nonEmptyString(required(value, key, "model"), member(key, "model"));
  prop.position = vec3(required(value, key, "position"), member(key, "position"));
  prop.rotation = glm::vec3(vec3(required(value, key, "rotation"), member(key, "rotation")));
  prop.scale = finiteFloat(value, key, "scale");
  if (!(prop.scale > 0.0f && prop.scale <= 1000.0f)) {
    expected(member(key, "scale"), "a number greater than 0 and at most 1000", value["scale"]);
  }
  return prop;
}

void parsePlayer(const json& player, Level& level) {
  checkObject(player, "player", {"position", "yaw", "pitch", "flying"});
  level.playerPosition = vec3(required(player, "player", "position"), "player.position");
  level.playerYaw = finiteFloat(player, "player", "yaw");
  level.playerPitch = finiteFloat(player, "player", "pitch");
  if (const json* v = field(player, "flying")) level.playerFlying = boolean(*v, "player.flying");
}

Level parseLevel(const json& root) {
  // "version" is written for readers to come; this one reads version 1 and files from before it.
  checkObject(root, "", {"version", "generator", "seed", "time", "player", "props", "minecraft"});
  Level level;
  level.generator = nonEmptyString(required(root, "", "generator"), "generator");
  level.seed = seedNumber(required(root, "", "seed"), "seed");
  level.time = wholeNumber(required(root, "", "time"), "time", kMinInt64, kMaxInt64);
  parsePlayer(required(root, "", "player"), level);
  if (const json* v = field(root, "minecraft")) level.minecraft = nonEmptyString(*v, "minecraft");
  if (const json* props = field(root, "props")) {
    if (!props->is_array()) expected("props", "an array", *props);
    for (std::size_t i = 0; i < props->size(); ++i) {
      level.props.push_back(parseProp((*props)[i], element("props", i)));
    }
  }
  return level;
}

}  // namespace

Level loadLevel(const std::filesystem::path& file) {
  const json root = parseJson(readTextFile(file), file);
  try {
    return parseLevel(root);
  } catch (const Error& e) {
    throw Error(withFile(file, e.what()));
  }
}

void saveLevel(const std::filesystem::path& file, const Level& level) {
  json props = json::array();
  for (const LevelProp& p : level.props) {
    props.push_back({{"model", p.model},
                     {"position", {p.position.x, p.position.y, p.position.z}},
                     {"rotation", {p.rotation.x, p.rotation.y, p.rotation.z}},
                     {"scale", p.scale}});
  }
  json root = {
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
  if (!level.minecraft.empty()) root["minecraft"] = level.minecraft.string();
  writeFileAtomically(file, root.dump(2) + "\n");
}

}  // namespace terrasol
