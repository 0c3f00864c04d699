#include "scene_render/placed_props.h"

#include <algorithm>
#include <cmath>

namespace terrasol {

const Model& PlacedProps::model(const std::filesystem::path& file) {
  return models_[models_.load(file)];
}

int PlacedProps::place(const std::filesystem::path& file, const PropTransform& transform, const World& world,
                       const LightEngine& light) {
  const int model = models_.load(file);
  if (gpuModels_.size() <= static_cast<std::size_t>(model))
    gpuModels_.resize(static_cast<std::size_t>(model) + 1, -1);
  int& gpuModel = gpuModels_[static_cast<std::size_t>(model)];
  if (gpuModel < 0) gpuModel = gpu_.addModel(models_[model]);
  const Model& m = models_[model];
  const WorldBounds bounds = placedBounds(transform, m.min, m.max);
  placed_.push_back({model, transform, bounds});
  gpu_.place(gpuModel, {transform.position, transform.basis, transform.rotation, bounds.min, bounds.max},
             std::vector<glm::vec2>(m.vertexCount()));
  relight(placed_.size() - 1, world, light);
  return static_cast<int>(placed_.size()) - 1;
}

void PlacedProps::remove(int index) {
  placed_.erase(placed_.begin() + index);
  gpu_.remove(index);
}

void PlacedProps::relight(std::size_t index, const World& world, const LightEngine& light) {
  Placed& p = placed_[index];
  const std::vector<glm::vec2> vertexLight = modelLight(models_[p.model], p.transform, world, light);
  glm::vec2 sum(0.0f);
  for (const glm::vec2& l : vertexLight) sum += l;
  p.meanLight = vertexLight.empty() ? glm::vec2(0.0f) : sum / static_cast<float>(vertexLight.size());
  gpu_.relight(static_cast<int>(index), vertexLight);
}

void PlacedProps::relightAll(const World& world, const LightEngine& light) {
  for (std::size_t i = 0; i < placed_.size(); ++i) relight(i, world, light);
}

void PlacedProps::relightNear(const std::vector<SectionPos>& sections, const World& world,
                              const LightEngine& light) {
  for (std::size_t i = 0; i < placed_.size(); ++i) {
    // The box grown by one block: smooth light reads the cells around each vertex.
    const WorldBounds& b = placed_[i].bounds;
    const glm::dvec3 lo = glm::floor(b.min - 1.0), hi = glm::floor(b.max + 1.0);
    const auto near = [&](const SectionPos& s) {
      const double x0 = s.x * kChunkSize, y0 = s.minBlockY(), z0 = s.z * kChunkSize, side = kChunkSize;
      return hi.x >= x0 && lo.x < x0 + side && hi.y >= y0 && lo.y < y0 + side && hi.z >= z0 &&
             lo.z < z0 + side;
    };
    if (std::any_of(sections.begin(), sections.end(), near)) relight(i, world, light);
  }
}

std::optional<PlacedProps::Hit> PlacedProps::pick(const glm::dvec3& eye, const glm::dvec3& direction,
                                                  double reach) const {
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

}  // namespace terrasol
