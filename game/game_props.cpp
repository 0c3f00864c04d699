#include "game_props.h"

#include "core/error.h"
#include "core/log.h"

namespace terrasol {

GameProps::GameProps(std::filesystem::path baseDir) : baseDir_(std::move(baseDir)) {}

std::filesystem::path GameProps::resolve(const std::string& model) const {
  const std::filesystem::path file(model);
  return file.is_absolute() ? file : baseDir_ / file;
}

LevelProp GameProps::standingIn(const std::string& model, BlockPos at) {
  const Model& m = placed_.model(resolve(model));
  LevelProp prop;
  prop.model = model;
  const glm::dvec3 centre = 0.5 * (glm::dvec3(m.min) + glm::dvec3(m.max));
  prop.position = {at.x + 0.5 - centre.x, at.y - static_cast<double>(m.min.y), at.z + 0.5 - centre.z};
  return prop;
}

WorldBounds GameProps::boundsOf(const LevelProp& prop) {
  const Model& m = placed_.model(resolve(prop.model));
  return placedBounds(propTransform(prop.position, prop.rotation, prop.scale), m.min, m.max);
}

void GameProps::place(const LevelProp& prop, const World& world, const LightEngine& light,
                      bool keepIfBroken) {
  try {
    placed_.place(resolve(prop.model), propTransform(prop.position, prop.rotation, prop.scale), world, light);
  } catch (const Error& e) {
    if (keepIfBroken) {
      broken_.push_back(prop);
      logWarning(std::string("prop not drawn: ") + e.what());
    }
    throw;
  }
  drawn_.push_back(prop);
}

void GameProps::remove(int index) {
  placed_.remove(index);
  drawn_.erase(drawn_.begin() + index);
}

std::vector<LevelProp> GameProps::level() const {
  std::vector<LevelProp> out = broken_;
  out.insert(out.end(), drawn_.begin(), drawn_.end());
  return out;
}

}  // namespace terrasol
