#pragma once
// One program of a shader pack on the GL context: its stages rewritten (shaderpack/glsl_rewriter.h)
// around the vertex reader of what it draws (blocks, the sky, a full-screen quad), compiled and
// linked, its samplers bound to OptiFine's texture units by name, and every other uniform it declares
// looked up once so each frame's values (shaderpack/pack_frame_uniforms.h) are set by location.
// GL thread only.

#include <array>
#include <glm/mat4x4.hpp>
#include <optional>
#include <string>
#include <vector>

#include "assets/shader_source.h"
#include "render/gl/program.h"
#include "render/section_draw.h"
#include "shaderpack/pack_directives.h"
#include "shaderpack/pack_frame_uniforms.h"
#include "shaderpack/shader_pack.h"

namespace terrasol {

// What a program draws, which picks its vertex reader and its texture units.
enum class PackInput { Block, Sky, Screen };

// OptiFine's texture units (shaders.txt): what each sampler name reads.
enum class PackTexture {
  Texture,  // the draw's own: the block atlas, or the sun's or moon's
  Lightmap,
  Normals,
  Specular,
  ShadowTex0,
  ShadowTex1,
  ShadowColor0,
  ShadowColor1,
  DepthTex0,
  DepthTex1,
  DepthTex2,
  Noise,
  ColorTex,  // + buffer
};

struct PackSampler {
  std::string name;
  int unit = 0;
  PackTexture texture = PackTexture::Texture;
  int buffer = 0;       // ColorTex: which
  bool shadow = false;  // declared sampler2DShadow: compares depth
};

// Vanilla's shade of a face by its direction (mesh/mesh_data.h's face ids: west, east, down, up,
// north, south, then the cross planes, unshaded), which packs get in gl_Color with oldLighting.
inline constexpr std::array<float, 10> kVanillaFaceShade = {0.6f, 0.6f, 0.5f, 1.0f, 0.8f,
                                                            0.8f, 1.0f, 1.0f, 1.0f, 1.0f};

// The GLSL that reads `input`'s vertices into the rewrite's tsol_* inputs (shaders/pack/*_input.glsl),
// with the renderer's defines, without its #version line.
PreprocessedShader packVertexReader(const ShaderPreprocessor& shaders, PackInput input);

// The sampler a name reads in a program drawing `input`; nothing for a name OptiFine does not bind.
std::optional<PackSampler> packSamplerNamed(const std::string& name, PackInput input);

struct PackProgramSource {
  const ShaderPack* pack = nullptr;
  PackProgram files;  // resolved (it may be a fallback's)
  PackInput input = PackInput::Block;
  bool alphaTest = false;
  std::vector<ShaderDefine> macros;            // packMacros() and the stage's
  const PreprocessedShader* reader = nullptr;  // the vertex reader for `input` (no #version)
};

// The fixed-function matrices a pack's stages read (gl_ModelViewMatrix, ...).
struct PackMatrices {
  glm::mat4 modelView{1.0f}, projection{1.0f};
  glm::mat4 texture0{1.0f}, texture1{1.0f};
};

class PackGlProgram {
 public:
  // Throws Error (ShaderError for the driver's) naming the pack's file and line.
  explicit PackGlProgram(const PackProgramSource& source);

  const std::string& name() const { return name_; }  // the files' program
  GLuint id() const { return linked_.id(); }
  const ProgramDirectives& directives() const { return directives_; }
  // The colour buffers it writes, output by output.
  const std::vector<int>& drawBuffers() const { return drawBuffers_; }
  const std::vector<PackSampler>& samplers() const { return samplers_; }
  // Uniforms it declares that nothing sets (neither OptiFine's nor the pack's custom ones).
  const std::vector<std::string>& unknownUniforms() const { return unknown_; }
  const SectionUniforms& section() const { return section_; }

  // The frame's values, by name; names the program does not use cost nothing.
  void setUniforms(const PackUniforms& uniforms);
  void setMatrices(const PackMatrices& m) const;
  void setAlphaTest(float ref) const;
  void setOldLighting(bool on) const;
  void setRenderStage(int stage) const;

 private:
  struct Slot {
    std::string name;
    GLint location;
    GLenum type;
  };
  std::string name_;
  LinkedProgram linked_;
  ProgramDirectives directives_;
  std::vector<int> drawBuffers_;
  std::vector<PackSampler> samplers_;
  std::vector<Slot> slots_;
  std::vector<std::string> unknown_;
  SectionUniforms section_;
  GLint modelView_ = -1, projection_ = -1, mvp_ = -1, modelViewInverse_ = -1, projectionInverse_ = -1,
        normal_ = -1, texture_ = -1, alphaTest_ = -1, renderStage_ = -1;
};

}  // namespace terrasol
