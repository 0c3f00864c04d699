#pragma once
// The block under the crosshair: the first block along the view ray within reach that a player can
// hit (anything drawn but liquids; a shaped block only where the ray meets its boxes, World::shapes),
// the face the ray enters, and the cell a placed block goes in.

#include <glm/vec3.hpp>
#include <optional>

#include "render/frame_inputs.h"
#include "world/world.h"

namespace terrasol {

inline constexpr double kReach = 5.0;  // blocks, from the eye (Minecraft's creative reach)

struct Target {
  BlockPos block;     // the hit block
  glm::ivec3 normal;  // the face hit (zero when the eye is inside the block)
  BlockPos place;     // block + normal: where a placed block goes
  double distance = 0.0;
};

std::optional<Target> targetBlock(const World& world, glm::dvec3 eye, glm::dvec3 direction,
                                  double reach = kReach);

// The box the targeted block's outline is drawn around: its shape's bounds, or the whole cell.
WorldBox outlineOf(const World& world, const BlockPos& block);

}  // namespace terrasol
