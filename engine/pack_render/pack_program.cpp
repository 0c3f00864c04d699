#include "pack_render/pack_program.h"

#include <algorithm>
#include <charconv>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <map>

#include "core/error.h"
#include "mesh/mesh_data.h"
#include "render/gl_slots.h"
#include "render/shader_defines.h"
#include "shaderpack/glsl_rewriter.h"

namespace terrasol {
namespace {

constexpr std::string_view kOldBufferNames[] = {"gcolor", "gdepth", "gnormal", "composite",
                                                "gaux1",  "gaux2",  "gaux3",   "gaux4"};

// colortexN or an old name: N.
std::optional<int> bufferNamed(const std::string& name) {
  for (int i = 0; i < 8; ++i)
    if (name == kOldBufferNames[i]) return i;
  if (!name.starts_with("colortex")) return std::nullopt;
  int n = -1;
  const auto [end, ec] = std::from_chars(name.data() + 8, name.data() + name.size(), n);
  if (ec != std::errc() || end != name.data() + name.size() || n < 0 || n >= kPackColorBuffers)
    return std::nullopt;
  return n;
}

// colortex0..15's units: 0..3 (composite only), 4..7 at 7..10, 8..15 at 16..23.
int bufferUnit(int buffer) {
  return buffer < 4 ? buffer : buffer < 8 ? buffer + 3 : buffer + 8;
}

bool isSampler(GLenum type) {
  switch (type) {
    case GL_SAMPLER_1D:
    case GL_SAMPLER_2D:
    case GL_SAMPLER_3D:
    case GL_SAMPLER_CUBE:
    case GL_SAMPLER_2D_SHADOW:
    case GL_SAMPLER_2D_RECT:
    case GL_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_2D:
    case GL_INT_SAMPLER_3D:
    case GL_UNSIGNED_INT_SAMPLER_3D:
    case GL_SAMPLER_2D_ARRAY:
      return true;
    default:
      return false;
  }
}

// Writes `value` to a uniform of GL type `type`, converting between numbers as packs declare them
// (a float worldTime, an int frameCounter as float, ...).
void upload(GLuint program, GLint at, GLenum type, const PackUniform& value) {
  const auto components = [&]() {
    glm::vec4 v(0.0f);
    std::visit(
        [&](const auto& x) {
          using T = std::decay_t<decltype(x)>;
          if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, int> || std::is_same_v<T, float>) {
            v.x = static_cast<float>(x);
          } else if constexpr (!std::is_same_v<T, glm::mat4>) {
            for (int i = 0; i < T::length(); ++i) v[i] = static_cast<float>(x[i]);
          }
        },
        value);
    return v;
  };
  if (const auto* m = std::get_if<glm::mat4>(&value)) {
    if (type == GL_FLOAT_MAT4) glProgramUniformMatrix4fv(program, at, 1, GL_FALSE, glm::value_ptr(*m));
    if (type == GL_FLOAT_MAT3) {
      const glm::mat3 m3(*m);
      glProgramUniformMatrix3fv(program, at, 1, GL_FALSE, glm::value_ptr(m3));
    }
    return;
  }
  const glm::vec4 v = components();
  const glm::ivec4 i(glm::round(v));
  switch (type) {
    case GL_FLOAT:
      glProgramUniform1f(program, at, v.x);
      break;
    case GL_FLOAT_VEC2:
      glProgramUniform2f(program, at, v.x, v.y);
      break;
    case GL_FLOAT_VEC3:
      glProgramUniform3f(program, at, v.x, v.y, v.z);
      break;
    case GL_FLOAT_VEC4:
      glProgramUniform4f(program, at, v.x, v.y, v.z, v.w);
      break;
    case GL_INT:
    case GL_BOOL:
      glProgramUniform1i(program, at, i.x);
      break;
    case GL_INT_VEC2:
    case GL_BOOL_VEC2:
      glProgramUniform2i(program, at, i.x, i.y);
      break;
    case GL_INT_VEC3:
    case GL_BOOL_VEC3:
      glProgramUniform3i(program, at, i.x, i.y, i.z);
      break;
    case GL_INT_VEC4:
    case GL_BOOL_VEC4:
      glProgramUniform4i(program, at, i.x, i.y, i.z, i.w);
      break;
    default:
      break;
  }
}

PreprocessedStage stageOf(GLenum stage, const PreprocessedShader& source, const ShaderPack& pack,
                          const std::string& path) {
  return {stage, &source, pack.displayName(path)};
}

}  // namespace

PreprocessedShader packVertexReader(const ShaderPreprocessor& shaders, PackInput input) {
  const char* file = input == PackInput::Block ? "pack/block_input.glsl"
                     : input == PackInput::Sky ? "pack/sky_input.glsl"
                                               : "pack/screen_input.glsl";
  std::vector<ShaderDefine> defines = rendererDefines();
  defines.push_back({"PACK_LIGHT_SCALE", std::to_string(PackedVertex::kCellLight * 16) + ".0"});
  std::string shade = "float[10](";
  for (std::size_t face = 0; face < kVanillaFaceShade.size(); ++face)
    shade += (face ? ", " : "") + std::to_string(kVanillaFaceShade[face]);
  defines.push_back({"PACK_FACE_SHADE", shade + ")"});
  PreprocessedShader source = shaders.process(file, defines);
  // Spliced into a pack's stage after its #version: drop ours.
  source.text.erase(0, source.text.find('\n') + 1);
  source.lines.erase(source.lines.begin());
  return source;
}

std::optional<PackSampler> packSamplerNamed(const std::string& name, PackInput input) {
  const bool screen = input == PackInput::Screen;
  using T = PackTexture;
  static const std::map<std::string, std::pair<T, int>, std::less<>> kFixed = {
      {"lightmap", {T::Lightmap, 1}},
      {"normals", {T::Normals, 2}},
      {"specular", {T::Specular, 3}},
      {"shadow", {T::ShadowTex0, 4}},
      {"watershadow", {T::ShadowTex0, 4}},
      {"shadowtex0", {T::ShadowTex0, 4}},
      {"shadowtex1", {T::ShadowTex1, 5}},
      {"depthtex0", {T::DepthTex0, 6}},
      {"depthtex1", {T::DepthTex1, 11}},
      {"shadowcolor", {T::ShadowColor0, 13}},
      {"shadowcolor0", {T::ShadowColor0, 13}},
      {"shadowcolor1", {T::ShadowColor1, 14}},
      {"noisetex", {T::Noise, 15}},
  };
  if (const std::optional<int> buffer = bufferNamed(name)) {
    // Gbuffers sample the atlas, not colortex0..3 (their units hold the atlas and the lightmap).
    if (!screen && *buffer < 4) return std::nullopt;
    return PackSampler{name, bufferUnit(*buffer), T::ColorTex, *buffer};
  }
  if (screen && (name == "texture" || name == "gtexture")) return PackSampler{name, 0, T::ColorTex, 0};
  if (!screen && (name == "texture" || name == "gtexture" || name == "tex"))
    return PackSampler{name, 0, T::Texture};
  if (screen && name == "gdepthtex") return PackSampler{name, 6, T::DepthTex0};
  if (screen && name == "depthtex2") return PackSampler{name, 12, T::DepthTex2};
  if (!screen && (name == "lightmap" || name == "normals" || name == "specular")) {
    const auto& [texture, unit] = kFixed.at(name);
    return PackSampler{name, unit, texture};
  }
  if (const auto it = kFixed.find(name); it != kFixed.end() && it->second.first != T::Lightmap &&
                                         it->second.first != T::Normals && it->second.first != T::Specular) {
    return PackSampler{name, it->second.second, it->second.first};
  }
  return std::nullopt;
}

PackGlProgram::PackGlProgram(const PackProgramSource& source) : name_(source.files.name) {
  const ShaderPack& pack = *source.pack;
  const PreprocessedShader vertexPack = pack.source(source.files.vertex, source.macros);
  const PreprocessedShader fragmentPack = pack.source(source.files.fragment, source.macros);
  directives_ = parseDirectives(fragmentPack);

  const RewrittenStage vertex = rewritePackStage(vertexPack, {PackStage::Vertex, source.reader, false});
  const RewrittenStage fragment =
      rewritePackStage(fragmentPack, {PackStage::Fragment, nullptr, source.alphaTest});
  std::optional<RewrittenStage> geometry;
  if (!source.files.geometry.empty()) {
    geometry = rewritePackStage(pack.source(source.files.geometry, source.macros), {PackStage::Geometry});
  }

  // The outputs: the directive's buffers, else as many as the stage writes from colortex0 on.
  if (directives_.drawBuffers) {
    drawBuffers_ = *directives_.drawBuffers;
  } else {
    int count = fragment.fragDataCount;
    for (const PackFragmentOutput& o : fragment.outputs) count = std::max(count, o.location + 1);
    count = std::clamp(count, 1, kPackMaxDrawBuffers);
    for (int i = 0; i < count; ++i) drawBuffers_.push_back(i);
  }

  std::vector<PreprocessedStage> stages{stageOf(GL_VERTEX_SHADER, vertex.source, pack, source.files.vertex)};
  if (geometry) stages.push_back(stageOf(GL_GEOMETRY_SHADER, geometry->source, pack, source.files.geometry));
  stages.push_back(stageOf(GL_FRAGMENT_SHADER, fragment.source, pack, source.files.fragment));
  linked_ = linkPreprocessed(stages, [&](GLuint program) {
    // Core-style outputs without a location: outColor<n> at n (OptiFine), else in declaration order.
    int next = 0;
    for (const PackFragmentOutput& o : fragment.outputs) {
      if (o.location >= 0) continue;
      int at = next++;
      if (o.name.starts_with("outColor"))
        std::from_chars(o.name.data() + 8, o.name.data() + o.name.size(), at);
      glBindFragDataLocation(program, static_cast<GLuint>(at), o.name.c_str());
    }
  });

  const GLuint program = linked_.id();
  GLint count = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
  for (GLint u = 0; u < count; ++u) {
    char buffer[256];
    GLsizei length = 0;
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(program, static_cast<GLuint>(u), sizeof buffer, &length, &size, &type, buffer);
    std::string uniform(buffer, static_cast<std::size_t>(length));
    if (uniform.ends_with("[0]")) uniform.resize(uniform.size() - 3);
    const GLint location = glGetUniformLocation(program, uniform.c_str());
    if (location < 0 || uniform.starts_with("tsol_") || uniform.starts_with("u_") ||
        uniform.starts_with("gl_"))
      continue;
    if (isSampler(type)) {
      std::optional<PackSampler> sampler = packSamplerNamed(uniform, source.input);
      if (!sampler) {
        unknown_.push_back(uniform);
        continue;
      }
      sampler->shadow = type == GL_SAMPLER_2D_SHADOW;
      glProgramUniform1i(program, location, slots::kUnitPackBase + sampler->unit);
      samplers_.push_back(*sampler);
    } else {
      slots_.push_back({uniform, location, type});
    }
  }
  const auto at = [&](const char* n) { return glGetUniformLocation(program, n); };
  modelView_ = at("tsol_ModelViewMatrix");
  projection_ = at("tsol_ProjectionMatrix");
  mvp_ = at("tsol_ModelViewProjectionMatrix");
  modelViewInverse_ = at("tsol_ModelViewMatrixInverse");
  projectionInverse_ = at("tsol_ProjectionMatrixInverse");
  normal_ = at("tsol_NormalMatrix");
  texture_ = at("tsol_TextureMatrix");
  alphaTest_ = at("tsol_alphaTestRef");
  renderStage_ = at("renderStage");
  if (source.input == PackInput::Block) section_ = SectionUniforms(linked_);
}

void PackGlProgram::setUniforms(const PackUniforms& uniforms) {
  std::erase_if(slots_, [&](const Slot& s) {
    const PackUniform* value = uniforms.find(s.name);
    if (!value && s.name != "renderStage") unknown_.push_back(s.name);
    return !value && s.name != "renderStage";
  });
  for (const Slot& s : slots_) {
    if (const PackUniform* value = uniforms.find(s.name)) upload(id(), s.location, s.type, *value);
  }
}

void PackGlProgram::setMatrices(const PackMatrices& m) const {
  const GLuint p = id();
  const glm::mat4 mvp = m.projection * m.modelView;
  const glm::mat3 normal = glm::inverseTranspose(glm::mat3(m.modelView));
  glProgramUniformMatrix4fv(p, modelView_, 1, GL_FALSE, glm::value_ptr(m.modelView));
  glProgramUniformMatrix4fv(p, projection_, 1, GL_FALSE, glm::value_ptr(m.projection));
  glProgramUniformMatrix4fv(p, mvp_, 1, GL_FALSE, glm::value_ptr(mvp));
  if (modelViewInverse_ >= 0) {
    const glm::mat4 inverse = glm::inverse(m.modelView);
    glProgramUniformMatrix4fv(p, modelViewInverse_, 1, GL_FALSE, glm::value_ptr(inverse));
  }
  if (projectionInverse_ >= 0) {
    const glm::mat4 inverse = glm::inverse(m.projection);
    glProgramUniformMatrix4fv(p, projectionInverse_, 1, GL_FALSE, glm::value_ptr(inverse));
  }
  glProgramUniformMatrix3fv(p, normal_, 1, GL_FALSE, glm::value_ptr(normal));
  const glm::mat4 textures[2] = {m.texture0, m.texture1};
  glProgramUniformMatrix4fv(p, texture_, 2, GL_FALSE, glm::value_ptr(textures[0]));
}

void PackGlProgram::setAlphaTest(float ref) const {
  glProgramUniform1f(id(), alphaTest_, ref);
}

void PackGlProgram::setOldLighting(bool on) const {
  glProgramUniform1i(id(), glGetUniformLocation(id(), "tsol_oldLighting"), on ? 1 : 0);
}

void PackGlProgram::setRenderStage(int stage) const {
  glProgramUniform1i(id(), renderStage_, stage);
}

}  // namespace terrasol
