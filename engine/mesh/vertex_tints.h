#pragma once
// The biome tint climate of a section's tinted vertices (PackedVertex::light's top bits), from the
// snapshot's column tints: interpolated bilinearly between the centres of the four columns around a
// vertex, so colours change smoothly across faces and blocks.

#include "mesh/mesh_data.h"
#include "mesh/section_snapshot.h"

namespace terrasol {

// Every biome-tinted vertex (grass, foliage, water) gets its climate; others are left alone.
void applyTints(PackedVertices& vertices, const SectionSnapshot& s);
// Inside one biome every column has one climate: every tinted vertex gets it, without interpolating.
void applyUniformTint(PackedVertices& vertices, TintClimate climate);

}  // namespace terrasol
