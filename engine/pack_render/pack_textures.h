#pragma once
// What a shader pack's samplers read besides its screen buffers and shadow maps: the block atlas as its
// stored sRGB texels (as Minecraft's), vanilla's 16x16 lightmap for the moment, the noise texture, and
// mc_Entity per texture id for the vertex readers; and the binding of a program's samplers to all of
// them at OptiFine's units, each with the filtering and depth comparison the pack asks for. GL thread
// only.

#include <glm/vec2.hpp>
#include <optional>
#include <vector>

#include "assets/image.h"
#include "core/lightmap.h"
#include "pack_render/pack_program.h"
#include "pack_render/pack_shadow_maps.h"
#include "pack_render/pack_targets.h"
#include "render/block_textures.h"
#include "shaderpack/pack_settings.h"

namespace terrasol {

// The GL texture unit of one of OptiFine's units.
GLuint packUnit(int optifineUnit);

class PackTextures {
 public:
  // `noiseImage`: the pack's texture.noise, else random RGB of noiseTextureResolution.
  PackTextures(const BlockTextures& blocks, const PackSettings& settings,
               const std::vector<glm::vec2>& entityIds, const std::optional<Image>& noiseImage);

  GLuint atlas() const { return atlas_.id(); }
  GLuint entities() const { return entities_.id(); }  // the vertex readers' storage buffer
  GLuint emptyVertexArray() const { return empty_.id(); }
  void updateLightmap(const Lightmap& lightmap);

  // Binds every sampler `program` declares; `drawn` is the draw's own texture (the atlas), or 0 where
  // the draw binds it (the sun and moon).
  void bind(const PackGlProgram& program, GLuint drawn, const PackTargets& targets,
            const PackShadowMaps& shadow) const;
  // Unbinds the sampler objects from every unit a pack uses.
  void unbindSamplers() const;

 private:
  const BlockTextures& blocks_;
  PackSettings settings_;
  gl::TextureView atlas_;
  gl::Texture lightmap_, noise_;
  gl::Buffer entities_;
  gl::Sampler compareLinear_, compareNearest_, nearest_, linear_;
  gl::VertexArray empty_;
};

}  // namespace terrasol
