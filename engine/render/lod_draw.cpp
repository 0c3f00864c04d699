#include "render/lod_draw.h"

#include <array>

#include "render/gl_slots.h"

namespace terrasol {

LodDrawCounts drawLodTiles(const LodMeshes& lod, const FrustumPlanes& frustum, glm::dvec3 camera,
                           const LodTileUniforms& u, bool facing) {
  LodDrawCounts counts;
  glBindVertexArray(lod.vertexArray());
  glBindTextureUnit(slots::kUnitLodMask, lod.fullDetailMask());
  const glm::ivec2 maskBlock = lod.maskOrigin() * kChunkSize;
  for (const LodMeshes::Tile& tile : lod.tiles()) {
    if (tile.quads == 0 && tile.triangles == 0) continue;
    const LodTileKey key = tile.mesh->key;
    const glm::vec3 lo(glm::dvec3(key.minBlockX(), tile.mesh->minY, key.minBlockZ()) - camera);
    const glm::vec3 hi =
        lo + glm::vec3(key.spanBlocks(), tile.mesh->maxY - tile.mesh->minY, key.spanBlocks());
    if (!boxVisible(frustum, lo, hi)) {
      ++counts.culled;
      continue;
    }
    u.tileOffset.set(glm::vec3(glm::dvec3(key.minBlockX(), 0.0, key.minBlockZ()) - camera));
    u.cellBlocks.set(key.cellBlocks());
    u.maskOffset.set(glm::ivec2(key.minBlockX(), key.minBlockZ()) - maskBlock);
    u.masked.set(tile.mesh->allWalls);
    lod.bindTile(tile);
    ++counts.drawn;
    if (tile.triangles > 0) {  // a heightfield: its skirts are few, back-face culling drops those turned away
      glDrawElements(GL_TRIANGLES, tile.triangles * 3, GL_UNSIGNED_SHORT, nullptr);
      counts.triangles += tile.triangles;
      continue;
    }
    // Each face's quads where some of the tile lies on that face's front side; runs drawn as one.
    const std::array<bool, 6> front =
        facing ? std::array<bool, 6>{hi.x > 0.0f, lo.x < 0.0f, false, lo.y<0.0f, hi.z> 0.0f, lo.z < 0.0f}
               : std::array<bool, 6>{true, true, true, true, true, true};
    const auto& start = tile.mesh->faceStart;
    for (std::size_t f = 0; f < front.size();) {
      if (!front[f]) {
        ++f;
        continue;
      }
      std::size_t end = f + 1;
      while (end < front.size() && front[end]) ++end;
      const GLsizei quads = static_cast<GLsizei>(start[end] - start[f]);
      if (quads > 0) {
        glDrawElements(
            GL_TRIANGLES, quads * 6, GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(static_cast<std::uintptr_t>(start[f]) * 6 * sizeof(GLuint)));
        counts.triangles += 2 * quads;
      }
      f = end;
    }
  }
  return counts;
}

}  // namespace terrasol
