#include "game_props.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/log.h"

namespace terrasol {

GameProps::GameProps(std::filesystem::path baseDir) : baseDir_(std::move(baseDir)) {}

std::filesystem::path GameProps::resolve(const std::string& model) const {
  const std::filesystem::path file(model);
  return file.is_absolute() ? file : baseDir_ / file;
}

LevelProp GameProps::standingIn(const std::filesystem::path& model, BlockPos at) {
  const Model& m = models_[models_.load(resolve(model.string()))];
  LevelProp prop;
  prop.model = model.string();
  const glm::dvec3 centre = 0.5 * (glm::dvec3(m.min) + glm::dvec3(m.max));
  prop.position = {at.x + 0.5 - centre.x, at.y - static_cast<double>(m.min.y), at.z + 0.5 - centre.z};
  return prop;
}

WorldBounds GameProps::boundsOf(const LevelProp& prop) {
  const Model& m = models_[models_.load(resolve(prop.model))];
  return placedBounds(propTransform(prop.position, prop.rotation, prop.scale), m.min, m.max);
}

void GameProps::place(const LevelProp& prop, const World& world, const LightEngine& light, bool keepIfBroken) {
  int model = 0;
  try {
    model = models_.load(resolve(prop.model));
  } catch (const Error& e) {
    if (keepIfBroken) {
      broken_.push_back(prop);
      logWarning(std::string("prop not drawn: ") + e.what());
    }
    throw;
  }
  if (gpuModels_.size() <= static_cast<std::size_t>(model)) gpuModels_.resize(static_cast<std::size_t>(model) + 1, -1);
  int& gpuModel = gpuModels_[static_cast<std::size_t>(model)];
  if (gpuModel < 0) gpuModel = gpu_.addModel(models_[model]);
  const PropTransform t = propTransform(prop.position, prop.rotation, prop.scale);
  const Model& m = models_[model];
  placed_.push_back({prop, model, t, placedBounds(t, m.min, m.max)});
  const WorldBounds& b = placed_.back().bounds;
  gpu_.place(gpuModel, {t.position, t.basis, t.rotation, b.min, b.max}, std::vector<glm::vec2>(m.vertexCount()));
  relightOne(placed_.size() - 1, world, light);
}

void GameProps::relightOne(std::size_t index, const World& world, const LightEngine& light) {
  Placed& p = placed_[index];
  const std::vector<glm::vec2> vertexLight = modelLight(models_[p.model], p.transform, world, light);
  glm::vec2 sum(0.0f);
  for (const glm::vec2& l : vertexLight) sum += l;
  p.meanLight = vertexLight.empty() ? glm::vec2(0.0f) : sum / static_cast<float>(vertexLight.size());
  gpu_.relight(static_cast<int>(index), vertexLight);
}

void GameProps::relight(const std::vector<SectionPos>& sections, const World& world, const LightEngine& light) {
  for (std::size_t i = 0; i < placed_.size(); ++i) {
    // The section span of the prop's box grown by one block: its smooth light reads the cells around.
    const WorldBounds& b = placed_[i].bounds;
    const glm::dvec3 lo = glm::floor(b.min - 1.0), hi = glm::floor(b.max + 1.0);
    const auto near = [&](const SectionPos& s) {
      const double x0 = s.x * 16.0, y0 = kMinY + s.section * 16.0, z0 = s.z * 16.0;
      return hi.x >= x0 && lo.x < x0 + 16.0 && hi.y >= y0 && lo.y < y0 + 16.0 && hi.z >= z0 && lo.z < z0 + 16.0;
    };
    if (std::any_of(sections.begin(), sections.end(), near)) relightOne(i, world, light);
  }
}

std::vector<LevelProp> GameProps::level() const {
  std::vector<LevelProp> out = broken_;
  for (const Placed& p : placed_) out.push_back(p.prop);
  return out;
}

std::optional<GameProps::Hit> GameProps::pick(const glm::dvec3& eye, const glm::dvec3& direction, double reach) const {
  std::optional<Hit> best;
  for (std::size_t i = 0; i < placed_.size(); ++i) {
    // Slabs: the ray's parameter range inside the box on each axis, intersected.
    const WorldBounds& b = placed_[i].bounds;
    double enter = 0.0, leave = reach;
    for (int a = 0; a < 3; ++a) {
      if (std::abs(direction[a]) < 1e-12) {
        if (eye[a] < b.min[a] || eye[a] > b.max[a]) enter = INFINITY;
        continue;
      }
      const double t0 = (b.min[a] - eye[a]) / direction[a], t1 = (b.max[a] - eye[a]) / direction[a];
      enter = std::max(enter, std::min(t0, t1));
      leave = std::min(leave, std::max(t0, t1));
    }
    if (enter <= leave && (!best || enter < best->distance)) best = Hit{static_cast<int>(i), enter};
  }
  return best;
}

void GameProps::remove(int index) {
  placed_.erase(placed_.begin() + index);
  gpu_.remove(index);
}

std::vector<GameProps::Drawn> GameProps::drawn() const {
  std::vector<Drawn> out;
  for (const Placed& p : placed_) out.push_back({p.prop, p.meanLight});
  return out;
}

}  // namespace terrasol
