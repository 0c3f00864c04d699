#include "render/passes/crack_pass.h"

namespace terrasol {

CrackPass::CrackPass(const VariantBuilder& build, PassShared& shared, const Atlas& atlas)
    : shared_(shared), program_(build("crack.vert", "crack.frag", shared.contents.defines())) {
  for (int stage = 0; stage < kCrackStages; ++stage) {
    const int texture = atlas.find(crackTextureName(stage));
    if (texture >= 0 && !atlas.textures[static_cast<std::size_t>(texture)].missing)
      tiles_[static_cast<std::size_t>(stage)] =
          atlas.tileRect(atlas.textures[static_cast<std::size_t>(texture)].firstTile);
  }
}

void CrackPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  const std::optional<BlockCrack>& crack = frame.inputs.crack;
  if (!crack) return builder.skip("no block is being dug");
  if (crack->stage < 0 || crack->stage >= kCrackStages || !tiles_[static_cast<std::size_t>(crack->stage)])
    return builder.skip("no pack has the crack's texture");
  builder.read(frame.resources.gbuffer);
  builder.write(frame.resources.gbuffer);
}

void CrackPass::execute(Frame& frame) {
  constexpr double kGrow = 1.0 / 64.0;  // the box drawn covers every pixel of the cell's faces
  const BlockCrack& crack = *frame.inputs.crack;
  const GBuffer& gbuffer = *frame.gbuffer;
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer.decalFramebuffer());
  glViewport(0, 0, gbuffer.size().x, gbuffer.size().y);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);  // the box's far side: its whole footprint, even with the camera inside
  glEnable(GL_BLEND);
  glBlendFunc(GL_DST_COLOR, GL_SRC_COLOR);               // 2 x crack x albedo, Minecraft's crumbling blend
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);  // alpha holds material AO
  glBindTextureUnit(0, gbuffer.depth());
  glBindTextureUnit(1, gbuffer.target(gbuffer::kNormals));
  glBindTextureUnit(2, shared_.textures.atlas().albedo());
  const FrameView& view = frame.view;
  program_.u.viewProjection.set(view.viewProjection);
  program_.u.inverseViewProjection.set(view.inverseViewProjection);
  program_.u.boxMin.set(glm::vec3(crack.cell.min - kGrow - view.camera));
  program_.u.boxMax.set(glm::vec3(crack.cell.max + kGrow - view.camera));
  program_.u.cellMin.set(glm::vec3(crack.cell.min - view.camera));
  program_.u.cellMax.set(glm::vec3(crack.cell.max - view.camera));
  program_.u.tile.set(*tiles_[static_cast<std::size_t>(crack.stage)]);
  program_.u.viewport.set(glm::vec2(gbuffer.size()));
  glUseProgram(program_.id());
  glBindVertexArray(shared_.empty.id());  // the box's corners come from gl_VertexID
  glDrawArrays(GL_TRIANGLES, 0, 36);
  glBindVertexArray(0);
  glUseProgram(0);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_BLEND);
  glCullFace(GL_BACK);
}

}  // namespace terrasol
