#pragma once
// glTF props in the game world. level.json keeps them (LevelProp); this loads each model file once,
// lights each placement from the voxels around it, relights it when the light there changes, and
// hands the renderer their GPU side. A prop whose model cannot be read stays in the level (and so in
// the next save) but is not drawn, with a warning naming the file. GL thread only.

#include <filesystem>
#include <optional>
#include <vector>

#include "render/props.h"
#include "scene/prop_placement.h"
#include "world/level.h"

namespace terrasol {

class GameProps {
 public:
  // Relative model paths resolve against `baseDir` (the world's folder).
  explicit GameProps(std::filesystem::path baseDir);

  // Places and lights a prop. Throws Error naming the model file when it cannot be loaded; the prop
  // is then kept (undrawn) only if `keepIfBroken` (props loaded from a save).
  void place(const LevelProp& prop, const World& world, const LightEngine& light, bool keepIfBroken = false);
  // A prop of `model` standing on the floor of cell `at`, centred in it: where place() should put it.
  LevelProp standingIn(const std::filesystem::path& model, BlockPos at);
  // Where a prop's box would be once placed (loads its model; Error when it cannot).
  WorldBounds boundsOf(const LevelProp& prop);
  // Relights the drawn props whose box reaches into (or borders) one of `sections`.
  void relight(const std::vector<SectionPos>& sections, const World& world, const LightEngine& light);

  std::vector<LevelProp> level() const;  // every prop, drawn or not, for the save

  // The nearest drawn prop whose box the ray (unit `direction`) enters within `reach`: its index
  // and distance. Props are picked by their box, as blocks by their cell.
  struct Hit {
    int index;
    double distance;
  };
  std::optional<Hit> pick(const glm::dvec3& eye, const glm::dvec3& direction, double reach) const;
  WorldBounds bounds(int index) const { return placed_[static_cast<std::size_t>(index)].bounds; }
  const LevelProp& prop(int index) const { return placed_[static_cast<std::size_t>(index)].prop; }
  void remove(int index);
  const Props& gpu() const { return gpu_; }
  // Each drawn prop's model and mean vertex light (block, sky 0..1), for reports.
  struct Drawn {
    LevelProp prop;
    glm::vec2 meanLight{0.0f};
  };
  std::vector<Drawn> drawn() const;

 private:
  std::filesystem::path resolve(const std::string& model) const;
  void relightOne(std::size_t index, const World& world, const LightEngine& light);

  std::filesystem::path baseDir_;
  ModelCache models_;
  std::vector<int> gpuModels_;  // per ModelCache index: the Props model
  struct Placed {
    LevelProp prop;
    int model;  // ModelCache index
    PropTransform transform;
    WorldBounds bounds;
    glm::vec2 meanLight{0.0f};
  };
  std::vector<Placed> placed_;  // drawn ones, in Props instance order
  std::vector<LevelProp> broken_;  // kept for the save, not drawn
  Props gpu_;
};

}  // namespace terrasol
