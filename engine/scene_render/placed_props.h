#pragma once
// Props placed in a world, CPU and GPU together: each model file loaded once (render/props.h keeps its
// GPU copy), each placement's transform, box and voxel light, relit when the light around it changes.
// What scenes (scene_render.h) and the game share. GL thread only.

#include <filesystem>
#include <optional>
#include <vector>

#include "render/props.h"
#include "scene/prop_placement.h"

namespace terrasol {

class PlacedProps {
 public:
  // The model in `file`, loaded on first use. Throws Error naming the file when it cannot be read.
  const Model& model(const std::filesystem::path& file);
  // Places the model in `file` with `transform`, lit from the world; its index is the next one
  // (placements keep their order). Throws Error when the model cannot be loaded.
  int place(const std::filesystem::path& file, const PropTransform& transform, const World& world,
            const LightEngine& light);
  void remove(int index);  // later placements move down one index

  void relightAll(const World& world, const LightEngine& light);
  // Relights the props whose box reaches into (or borders) one of `sections` (light or blocks changed there).
  void relightNear(const std::vector<SectionPos>& sections, const World& world, const LightEngine& light);

  // The nearest prop whose box the ray (unit `direction`) enters within `reach`, and the distance.
  struct Hit {
    int index;
    double distance;
  };
  std::optional<Hit> pick(const glm::dvec3& eye, const glm::dvec3& direction, double reach) const;

  std::size_t size() const { return placed_.size(); }
  const WorldBounds& bounds(int index) const { return at(index).bounds; }
  glm::vec2 meanLight(int index) const { return at(index).meanLight; }  // block, sky 0..1 over its vertices
  const Props& gpu() const { return gpu_; }

 private:
  struct Placed {
    int model;  // ModelCache index
    PropTransform transform;
    WorldBounds bounds;
    glm::vec2 meanLight{0.0f};
  };
  const Placed& at(int index) const { return placed_[static_cast<std::size_t>(index)]; }
  void relight(std::size_t index, const World& world, const LightEngine& light);

  ModelCache models_;
  std::vector<int> gpuModels_;  // per ModelCache index: the Props model, -1 before its first placement
  std::vector<Placed> placed_;  // in Props instance order
  Props gpu_;
};

}  // namespace terrasol
