#pragma once
// glTF props in the game world. level.json keeps them (LevelProp); PlacedProps draws and lights them.
// A prop whose model cannot be read stays in the level (and so in the next save) but is not drawn,
// with a warning naming the file. GL thread only.

#include <filesystem>
#include <vector>

#include "scene_render/placed_props.h"
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
  LevelProp standingIn(const std::string& model, BlockPos at);
  // Where a prop's box would be once placed (loads its model; Error when it cannot).
  WorldBounds boundsOf(const LevelProp& prop);
  void remove(int index);

  std::vector<LevelProp> level() const;  // every prop, drawn or not, for the save
  const LevelProp& prop(int index) const { return drawn_[static_cast<std::size_t>(index)]; }
  // The drawn props, in the order of their level entries.
  PlacedProps& placed() { return placed_; }
  const PlacedProps& placed() const { return placed_; }

 private:
  std::filesystem::path resolve(const std::string& model) const;

  std::filesystem::path baseDir_;
  PlacedProps placed_;
  std::vector<LevelProp> drawn_;   // PlacedProps index order
  std::vector<LevelProp> broken_;  // kept for the save, not drawn
};

}  // namespace terrasol
