#include "render/passes/lod_pass.h"

#include <array>
#include <cstdint>

#include "render/gl_slots.h"

namespace terrasol {

LodPass::LodPass(const VariantBuilder& build, PassShared& shared)
    : shared_(shared), program_(build("lod.vert", "lod.frag", shared.contents.defines())) {}

void LodPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  if (!frame.inputs.lod || frame.inputs.lod->empty()) return builder.skip("no far terrain");
  builder.read(frame.resources.gbuffer);
  builder.write(frame.resources.gbuffer);
}

void LodPass::execute(Frame& frame) {
  const LodMeshes& lod = *frame.inputs.lod;
  bindForOpaqueGeometry(*frame.gbuffer);
  const FrameView& view = frame.view;
  const Uniforms& u = program_.u;
  u.viewProjection.set(view.viewProjection);
  glUseProgram(program_.id());
  glBindVertexArray(lod.vertexArray());
  glBindTextureUnit(slots::kUnitLodMask, lod.fullDetailMask());
  const glm::ivec2 maskBlock = lod.maskOrigin() * kChunkSize;
  for (const LodMeshes::Tile& tile : lod.tiles()) {
    if (tile.quads == 0) continue;
    const LodTileKey key = tile.mesh->key;
    const glm::dvec3 min(key.minBlockX(), tile.mesh->minY, key.minBlockZ());
    const glm::vec3 lo(min - view.camera);
    const glm::vec3 hi =
        lo + glm::vec3(key.spanBlocks(), tile.mesh->maxY - tile.mesh->minY, key.spanBlocks());
    if (!boxVisible(view.frustum, lo, hi)) {
      ++frame.stats.lodTilesCulled;
      continue;
    }
    u.tileOffset.set(glm::vec3(glm::dvec3(key.minBlockX(), 0.0, key.minBlockZ()) - view.camera));
    u.cellBlocks.set(key.cellBlocks());
    u.maskOffset.set(glm::ivec2(key.minBlockX(), key.minBlockZ()) - maskBlock);
    u.masked.set(tile.mesh->allWalls);
    lod.bindTile(tile);
    // Each face's quads where some of the tile lies on that face's front side; runs drawn as one.
    const std::array<bool, 6> facing = {hi.x > 0.0f, lo.x < 0.0f, false, lo.y<0.0f, hi.z> 0.0f, lo.z < 0.0f};
    const auto& start = tile.mesh->faceStart;
    for (std::size_t f = 0; f < facing.size();) {
      if (!facing[f]) {
        ++f;
        continue;
      }
      std::size_t end = f + 1;
      while (end < facing.size() && facing[end]) ++end;
      const GLsizei quads = static_cast<GLsizei>(start[end] - start[f]);
      if (quads > 0) {
        glDrawElements(
            GL_TRIANGLES, quads * 6, GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(static_cast<std::uintptr_t>(start[f]) * 6 * sizeof(GLuint)));
        frame.stats.lodQuadsDrawn += quads;
      }
      f = end;
    }
    ++frame.stats.lodTilesDrawn;
  }
}

}  // namespace terrasol
