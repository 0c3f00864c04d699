#include "pack_render/pack_textures.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/srgb.h"
#include "render/gl_slots.h"

namespace terrasol {
namespace {

constexpr int kPackUnits = 24;  // OptiFine's 0..23

gl::Sampler samplerFor(bool compare, bool nearest) {
  gl::Sampler s = gl::Sampler::create();
  const GLint filter = nearest ? GL_NEAREST : GL_LINEAR;
  glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, filter);
  glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, filter);
  glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  if (compare) {
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  }
  return s;
}

GLuint levelsOf(const BlockTextures& blocks) {
  GLint levels = 1;
  glGetTextureParameteriv(blocks.atlas().albedo(), GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
  return static_cast<GLuint>(std::max(levels, 1));
}

}  // namespace

GLuint packUnit(int optifineUnit) {
  return static_cast<GLuint>(slots::kUnitPackBase + optifineUnit);
}

PackTextures::PackTextures(const BlockTextures& blocks, const PackSettings& settings,
                           const std::vector<glm::vec2>& entityIds, const std::optional<Image>& noiseImage)
    : blocks_(blocks),
      settings_(settings),
      atlas_(gl::TextureView::create(GL_TEXTURE_2D, blocks.atlas().albedo(), GL_RGBA8, 0u, levelsOf(blocks),
                                     0u, 1u)),
      lightmap_(packTexture(GL_RGBA8, glm::ivec2(Lightmap::kSize), 1, GL_LINEAR)),
      entities_(gl::Buffer::create()),
      compareLinear_(samplerFor(true, false)),
      compareNearest_(samplerFor(true, true)),
      nearest_(samplerFor(false, true)),
      linear_(samplerFor(false, false)),
      empty_(gl::VertexArray::create()) {
  // The atlas as packs sample it: its sRGB texels as stored, not decoded.
  glTextureParameteri(atlas_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR);
  glTextureParameteri(atlas_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  if (noiseImage) {
    noise_ = packTexture(GL_RGBA8, {noiseImage->width, noiseImage->height}, 1, GL_LINEAR, GL_REPEAT);
    glTextureSubImage2D(noise_.id(), 0, 0, 0, noiseImage->width, noiseImage->height, GL_RGBA,
                        GL_UNSIGNED_BYTE, noiseImage->rgba.data());
  } else {
    // Random RGB, the same every run (Iris fills it from a seeded generator too).
    const int size = std::clamp(settings.noiseTextureResolution, 1, 4096);
    noise_ = packTexture(GL_RGB8, glm::ivec2(size), 1, GL_LINEAR, GL_REPEAT);
    std::vector<std::uint8_t> texels(static_cast<std::size_t>(size * size * 3));
    std::mt19937 random(0);
    for (std::uint8_t& t : texels) t = static_cast<std::uint8_t>(random() & 0xff);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(noise_.id(), 0, 0, 0, size, size, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  }
  std::vector<glm::vec2> ids = entityIds;
  if (ids.empty()) ids.push_back(glm::vec2(-1.0f));
  glNamedBufferStorage(entities_.id(), static_cast<GLsizeiptr>(ids.size() * sizeof(glm::vec2)), ids.data(),
                       0);
}

void PackTextures::updateLightmap(const Lightmap& lightmap) {
  std::vector<std::uint8_t> texels;
  for (const glm::vec3& c : lightmap.texels) {
    for (int i = 0; i < 3; ++i)
      texels.push_back(static_cast<std::uint8_t>(std::lround(linearToSrgb(c[i]) * 255.0f)));
    texels.push_back(255);
  }
  glTextureSubImage2D(lightmap_.id(), 0, 0, 0, Lightmap::kSize, Lightmap::kSize, GL_RGBA, GL_UNSIGNED_BYTE,
                      texels.data());
}

void PackTextures::bind(const PackGlProgram& program, GLuint drawn, const PackTargets& targets,
                        const PackShadowMaps& shadow) const {
  for (const PackSampler& s : program.samplers()) {
    if (s.texture == PackTexture::Texture && drawn == 0) continue;  // bound by the draw
    GLuint texture = 0, sampler = 0;
    switch (s.texture) {
      case PackTexture::Texture:
        texture = drawn;
        break;
      case PackTexture::Lightmap:
        texture = lightmap_.id();
        break;
      case PackTexture::Normals:
        texture = blocks_.atlas().normal();
        break;
      case PackTexture::Specular:
        texture = blocks_.atlas().specular();
        break;
      case PackTexture::ShadowTex0:
      case PackTexture::ShadowTex1: {
        const int i = s.texture == PackTexture::ShadowTex0 ? 0 : 1;
        texture = shadow.depth(i);
        const bool nearest = settings_.shadowtexNearest[static_cast<std::size_t>(i)] ||
                             (s.shadow && !settings_.shadowHardwareFiltering);
        sampler = s.shadow ? (nearest ? compareNearest_.id() : compareLinear_.id())
                           : (nearest ? nearest_.id() : linear_.id());
        break;
      }
      case PackTexture::ShadowColor0:
      case PackTexture::ShadowColor1: {
        const int i = s.texture == PackTexture::ShadowColor0 ? 0 : 1;
        texture = shadow.colour(i);
        sampler = settings_.shadowcolorNearest[static_cast<std::size_t>(i)] ? nearest_.id() : linear_.id();
        break;
      }
      case PackTexture::DepthTex0:
        texture = targets.depth(0);
        break;
      case PackTexture::DepthTex1:
      case PackTexture::DepthTex2:
        texture = targets.depth(1);
        break;
      case PackTexture::Noise:
        texture = noise_.id();
        break;
      case PackTexture::ColorTex:
        texture = targets.has(s.buffer) ? targets.main(s.buffer) : 0;
        break;
    }
    glBindTextureUnit(packUnit(s.unit), texture);
    glBindSampler(packUnit(s.unit), sampler);
  }
}

void PackTextures::unbindSamplers() const {
  for (int unit = 0; unit < kPackUnits; ++unit) glBindSampler(packUnit(unit), 0);
}

}  // namespace terrasol
