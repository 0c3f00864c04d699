#pragma once
// The colour each block state shows from above, for views too far or too small for textures (maps,
// far terrain): the average of its top face's texture (the atlas's level 0, opaque texels only),
// multiplied by its tint at plains' climate on the packs' colormaps (assets/tints.h; birch and spruce
// leaves their own). sRGB 0..1; alpha is
// the share of texels the face covers (0: nothing seen from above, as air).

#include <glm/vec4.hpp>
#include <vector>

#include "assets/tints.h"
#include "scene/block_atlas.h"

namespace terrasol {

std::vector<glm::vec4> blockTopColours(const BlockRegistry& blocks, const BlockAtlas& atlas,
                                       const BiomeColormaps& colormaps);

}  // namespace terrasol
