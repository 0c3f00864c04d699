#pragma once
// The colour each block state shows from above, for views too far or too small for textures (maps,
// far terrain): the average of its top face's texture (the atlas's level 0, opaque texels only), and
// the tint that face takes (BlockAtlas::tints gives its colour in a column). sRGB 0..1; alpha is the
// share of texels the face covers (0: nothing seen from above, as air).

#include <glm/vec4.hpp>
#include <vector>

#include "lod/lod_mesh.h"
#include "scene/block_atlas.h"

namespace terrasol {

struct TopColour {
  glm::vec4 texture{0.0f};  // untinted
  Tint tint = Tint::None;
  // In a column of tint `column`.
  glm::vec4 in(const TintPalette& tints, const ColumnTint& column = kPlainsColumn) const {
    return glm::vec4(glm::vec3(texture) * tints.colour(tint, column), texture.a);
  }
};

std::vector<TopColour> blockTopColours(const BlockRegistry& blocks, const BlockAtlas& atlas);

// Far terrain's colours: each block's top as above, its side the mean of its north face (a model
// block's: its top again), tinted as the mesher tints them (a grass block's sides are not).
LodPalette lodPaletteOf(const BlockRegistry& blocks, const BlockAtlas& atlas);

}  // namespace terrasol
