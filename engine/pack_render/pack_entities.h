#pragma once
// mc_Entity for a shader pack, by atlas texture: Terrasol's vertex carries its texture, not its block,
// so each texture takes the block.properties id of the first block state (in the registry's order)
// the pack names that is drawn with it; x the id (-1 for none), y 1 for a liquid's texture, else -1
// (Iris's mc_Entity). Blocks sharing a texture share an id: packs tag by material, so they agree in
// practice (stone and its stairs; water's still and flowing). GL-free.

#include <cstddef>
#include <glm/vec2.hpp>
#include <vector>

#include "mesh/block_mesh_table.h"
#include "shaderpack/block_properties.h"

namespace terrasol {

std::vector<glm::vec2> packEntityIds(const BlockIdMap& ids, const BlockMeshTable& table,
                                     std::size_t textures);

}  // namespace terrasol
