#pragma once
// The atlas for a block registry: every face texture the blocks name, loaded through a pack stack,
// and the atlas texture id of each block face (what the mesher writes into vertices).

#include <array>
#include <cstdint>
#include <vector>

#include "assets/atlas.h"
#include "assets/resource_pack.h"
#include "world/block_registry.h"

namespace terrasol {

struct BlockAtlas {
  Atlas atlas;
  std::vector<std::array<std::uint16_t, 6>> faceTextures;  // per block id, Direction order
  std::vector<PackProblem> problems;                       // never fatal: missing textures show as such
  std::uint16_t textureOf(BlockId id, int face) const { return faceTextures[id][static_cast<std::size_t>(face)]; }
};

BlockAtlas buildBlockAtlas(const BlockRegistry& blocks, const PackStack& packs);

}  // namespace terrasol
