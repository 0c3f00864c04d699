#pragma once
// Where liquids' surfaces lie: the mesher draws the top of a liquid 2/16 below its highest cell's top
// (unless more of the same liquid is above), and a camera below that height is under it. A
// waterlogged cell holds water as a water block does.

#include <glm/vec3.hpp>
#include <optional>

#include "world/world.h"

namespace terrasol {

inline constexpr int kLiquidSurfaceDrop32 = 4;  // in 1/32 blocks, the mesher's unit

// The block index of the liquid a cell holds: a liquid block's own, water's in a waterlogged cell.
std::optional<std::size_t> liquidIn(const World& world, const BlockPos& pos);
bool isLiquid(const World& world, const BlockPos& pos);

// The world height of the surface of the liquid `point` is in, or nothing where it is not in one.
std::optional<double> liquidSurfaceAbove(const World& world, glm::dvec3 point);
// Whether `point` is under water's surface (not lava's): where the eyes hear and dig as under water.
bool underWater(const World& world, glm::dvec3 point);

}  // namespace terrasol
