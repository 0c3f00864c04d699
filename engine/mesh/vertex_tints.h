#pragma once
// The tint colour of a section's tinted vertices (PackedVertex::tintRgb), from the snapshot's column
// tints through the pack's palette: each column's colour, interpolated bilinearly between the centres
// of the four columns around a vertex, so colours change smoothly across faces and blocks (Minecraft
// blends its vertex colours in sRGB too).

#include "core/tint_palette.h"
#include "mesh/mesh_data.h"
#include "mesh/section_snapshot.h"

namespace terrasol {

// Every tinted vertex gets its colour; untinted ones are left alone.
void applyTints(PackedVertices& vertices, const SectionSnapshot& s, const TintPalette& palette);
// Every column alike: each tint has one colour, without interpolating.
void applyUniformTint(PackedVertices& vertices, const ColumnTint& column, const TintPalette& palette);

}  // namespace terrasol
