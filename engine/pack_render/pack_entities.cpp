#include "pack_render/pack_entities.h"

namespace terrasol {

std::vector<glm::vec2> packEntityIds(const BlockIdMap& ids, const BlockMeshTable& table,
                                     std::size_t textures) {
  std::vector<glm::vec2> out(textures, glm::vec2(-1.0f));
  std::vector<bool> taken(textures, false);
  const auto give = [&](std::size_t texture, int id, bool liquid) {
    if (texture >= textures || taken[texture]) return;
    taken[texture] = true;
    out[texture] = glm::vec2(static_cast<float>(id), liquid ? 1.0f : -1.0f);
  };
  for (std::size_t state = 0; state < ids.ids.size(); ++state) {
    const int id = ids.ids[state];
    if (id < 0) continue;
    const BlockMeshTable::Entry& e = table[static_cast<BlockId>(state)];
    const bool liquid = e.liquid != 0 && !e.water;
    for (std::uint16_t t : e.texture) give(t, id, liquid);
    for (const ModelQuad& q : e.quads) give(q.texture, id, liquid);
    for (const ModelChoice& c : e.choices)
      for (const ModelQuad& q : c.quads) give(q.texture, id, liquid);
  }
  return out;
}

}  // namespace terrasol
