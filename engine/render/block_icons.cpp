#include "render/block_icons.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "render/block_textures.h"
#include "render/gl/program.h"
#include "render/gl/render_target.h"
#include "render/gl/uniforms.h"
#include "render/section_meshes.h"
#include "render/shader_defines.h"

namespace terrasol {
namespace {

// Minecraft's inventory view of a block: turned 225 degrees about y, tilted 30 degrees, orthographic,
// so the top and two sides show (north on the right, where a furnace's front is). A whole cube fits
// the view with a small margin; a smaller mesh (a torch, a lantern) is centred and drawn up to twice
// as large, as Minecraft's flat item icons fill their slot.
glm::mat4 iconTransform(const SectionMesh& mesh) {
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const MeshData& layer : mesh.layers)
    for (const PackedVertex& v : layer.vertices) {
      const glm::vec3 p = glm::vec3(v.x32(), v.y32(), v.z32()) / 32.0f;
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  if (lo.x > hi.x) lo = hi = glm::vec3(0.5f);
  const float extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const float zoom = std::clamp(1.0f / std::max(extent, 1e-3f), 1.0f, 2.0f);
  // A big mesh keeps its cell's centre (a slab sits low, as in Minecraft), a small one its own.
  const glm::vec3 middle = (lo + hi) * 0.5f;
  const glm::vec3 centre = zoom > 1.0f ? middle : glm::floor(middle) + 0.5f;
  const glm::vec3 eye =
      centre + glm::normalize(glm::vec3(1.0f, std::tan(glm::radians(30.0f)) * std::sqrt(2.0f), -1.0f)) * 4.0f;
  const float half = 0.86f / zoom;  // a cube's outline is 1.41 wide and 1.57 tall
  return glm::ortho(-half, half, -half, half, 0.1f, 8.0f) *
         glm::lookAt(eye, centre, glm::vec3(0.0f, 1.0f, 0.0f));
}

}  // namespace

BlockIcons::BlockIcons(const ShaderPreprocessor& shaders, const Atlas& atlas, const TintPalette& tints,
                       const std::vector<SectionMesh>& meshes, int cell)
    : count_(meshes.size()),
      cell_(cell),
      columns_(16),
      size_(columns_ * cell, std::max<int>(1, static_cast<int>((meshes.size() + 15) / 16)) * cell),
      texture_(targetTexture(GL_RGBA8, size_, GL_LINEAR)),
      depth_(gl::Renderbuffer::create()),
      framebuffer_(gl::Framebuffer::create()) {
  glNamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT24, size_.x, size_.y);
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, texture_.id(), 0);
  glNamedFramebufferRenderbuffer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  if (glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw Error("block icons: incomplete framebuffer");
  }
  // The atlas and meshes are needed only while drawing: made here, gone when the icons are done.
  const BlockTextures textures(atlas, tints);
  SectionMeshes uploaded;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    SectionMesh mesh = meshes[i];
    mesh.pos = {static_cast<int>(i), 0, 0};
    uploaded.upload(mesh);
  }
  const LinkedProgram program = linkProgram(
      shaders, {{GL_VERTEX_SHADER, "icon.vert"}, {GL_FRAGMENT_SHADER, "icon.frag"}}, rendererDefines());
  const gl::Uniform<glm::mat4> transformOf(program, "u_transform");
  const gl::Uniform<bool> cutout(program, "u_cutout");
  glUseProgram(program.id());
  textures.bind(AtlasUniforms(program));

  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, size_.x, size_.y);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glEnable(GL_CULL_FACE);  // every face once, so translucent ones keep their own alpha
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBindVertexArray(uploaded.vertexArray());
  for (const auto& [pos, section] : uploaded.sections()) {
    const int i = pos.x;
    // GL's rows run bottom up: cell row r from the top starts at size - (r + 1) * cell.
    glViewport(i % columns_ * cell_, size_.y - (i / columns_ + 1) * cell_, cell_, cell_);
    const glm::mat4 transform = iconTransform(meshes[static_cast<std::size_t>(i)]);
    transformOf.set(transform);
    for (const MeshLayer layer : {MeshLayer::Opaque, MeshLayer::Cutout, MeshLayer::Translucent}) {
      const SectionMeshes::Layer& l = section.layers[static_cast<std::size_t>(layer)];
      if (l.quads == 0) continue;
      cutout.set(layer == MeshLayer::Cutout);
      uploaded.bindLayer(l);
      for (int g = 0; g < SectionMeshes::kFaceGroups; ++g) {
        const auto [first, end] = l.range(g, SectionMeshes::View::Camera);
        if (end == first) continue;
        glDrawElements(
            GL_TRIANGLES, (end - first) * 6, GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(static_cast<std::uintptr_t>(first) * 6 * sizeof(GLuint)));
      }
    }
  }
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDisable(GL_CULL_FACE);
  glUseProgram(0);  // the program goes with this scope: nothing may find it current (ImGui restores it)
}

glm::vec4 BlockIcons::uv(std::size_t icon) const {
  const auto i = static_cast<int>(icon);
  const glm::vec2 corner(static_cast<float>(i % columns_ * cell_), static_cast<float>(i / columns_ * cell_));
  const glm::vec2 size(size_);
  // Rendered bottom row first: the texture's v runs upwards, so the top of cell row r is at
  // 1 - r * cell / height.
  return {corner.x / size.x, 1.0f - corner.y / size.y, (corner.x + static_cast<float>(cell_)) / size.x,
          1.0f - (corner.y + static_cast<float>(cell_)) / size.y};
}

Image BlockIcons::read() const {
  return readFramebuffer(framebuffer_.id(), size_);
}

}  // namespace terrasol
