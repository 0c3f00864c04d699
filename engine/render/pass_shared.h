#pragma once
// What the renderer's passes share for the renderer's life: its options, the G-buffer's contents,
// the block textures, an empty vertex array, and the names of the shader variants built.

#include <optional>
#include <string>
#include <vector>

#include "assets/shader_source.h"
#include "render/block_textures.h"
#include "render/cloud_texture.h"
#include "render/frame_inputs.h"
#include "render/gbuffer.h"
#include "render/gl/program.h"
#include "render/shader_defines.h"

namespace terrasol {

struct PassShared {
  PassShared(const Atlas& atlas, const TintPalette& tints, const CloudMap& clouds,
             const RendererOptions& options);

  // The sky library's variant (lib/sky.glsl) of the programs that draw the sky or fog what lies under
  // it: the cloud layer (none with clouds off or no map in any pack) and the height fog.
  std::vector<ShaderDefine> skyDefines() const;

  RendererOptions options;
  GBufferContents contents;       // the programs are built for it
  std::vector<float> smoothness;  // each atlas texture's highest _s smoothness (none without specular maps)
  float maxSmoothness;            // of them all
  std::vector<float> emission;    // each atlas texture's highest _s emission (none without specular maps)
  BlockTextures textures;
  std::optional<CloudTexture> clouds;  // with clouds on and a map
  gl::VertexArray empty;               // full-screen passes make their vertices from gl_VertexID
  std::vector<std::string> variants;   // each program's name with the defines that chose it
};

// Builds programs and names each variant in `names`: the fragment stage and its defines ("gbuffer+CUTOUT").
class VariantBuilder {
 public:
  VariantBuilder(const ShaderPreprocessor& shaders, PassShared& shared)
      : shaders_(shaders), shared_(shared) {}
  LinkedProgram operator()(const char* vertex, const char* fragment,
                           std::vector<ShaderDefine> extra = {}) const;

 private:
  const ShaderPreprocessor& shaders_;
  PassShared& shared_;
};

std::vector<ShaderDefine> with(std::vector<ShaderDefine> a, const std::vector<ShaderDefine>& b);
// The lit passes' variant: the specular lobe and the shadow filter.
std::vector<ShaderDefine> lightingDefines(const RendererOptions& options);
// Water and glass reflecting (render.reflections) and water's waves (render.water.waves).
std::vector<ShaderDefine> surfaceDefines(const RendererOptions& options);

// The G-buffer's geometry targets bound over its whole size, for opaque surfaces: depth tested (less)
// and written, back faces culled, no blending. The geometry pass and far terrain draw with it.
void bindForOpaqueGeometry(const GBuffer& gbuffer);

}  // namespace terrasol
