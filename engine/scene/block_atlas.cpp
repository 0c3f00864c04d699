#include "scene/block_atlas.h"

#include <map>

namespace terrasol {

BlockAtlas buildBlockAtlas(const BlockRegistry& blocks, const PackStack& packs) {
  // Each distinct candidate list is loaded once, in a stable order.
  std::map<std::vector<std::string>, std::uint16_t> index;
  for (BlockId id = 0; id < blocks.size(); ++id) {
    for (const auto& face : blocks[id].textures) {
      if (!face.empty()) index.emplace(face, 0);
    }
  }
  BlockAtlas result;
  std::vector<LoadedTexture> textures;
  for (auto& [candidates, texture] : index) {
    texture = static_cast<std::uint16_t>(textures.size());
    textures.push_back(loadBlockTexture(packs, candidates, result.problems));
  }
  if (textures.empty()) textures.push_back(loadBlockTexture(packs, {"missing"}, result.problems));
  result.atlas = buildAtlas(textures);
  result.faceTextures.resize(blocks.size());
  for (BlockId id = 0; id < blocks.size(); ++id)
    for (int f = 0; f < 6; ++f) {
      const auto& face = blocks[id].textures[static_cast<std::size_t>(f)];
      result.faceTextures[id][static_cast<std::size_t>(f)] = face.empty() ? 0 : index.at(face);
    }
  return result;
}

}  // namespace terrasol
