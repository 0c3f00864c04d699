#pragma once
// The G-buffer, declared once. C++ allocates it from these constants and GLSL sees them only as
// injected #defines (gbufferDefines()), so the two can never disagree.
//
//   target  format          r                 g                 b                 a
//   0       RGBA8           square root of linear albedo x vertex AO                 material AO (_n blue)
//   1       RGBA16F         surface normal, octahedral xy       vertex normal, octahedral xy
//   2       RGBA8           raw LabPBR specular (_s): smoothness, F0/metal id, porosity/SSS, emission
//   3       RGBA8           block light 0..1      sky light 0..1    vertex AO 0..1   unused
//   depth   DEPTH32F        hardware depth (1 = nothing drawn: sky)
//
// The albedo's square root (shaders/lib/gbuffer_albedo.glsl) keeps dark shades apart as sRGB would,
// for far less than sRGB's exact curve costs a CPU rasterizer on every write and read.
// Normals are in world space (y up). Light levels are the mesher's smooth averages / 15.
// When no loaded pack has normal maps (NO_NORMAL_MAPS) the surface normal is the vertex normal, so
// target 1 shrinks to RG16F holding only that; when none has specular maps (NO_SPECULAR_MAPS) target 2
// is not made at all (GBufferContents).

#include <epoxy/gl.h>

#include <array>
#include <vector>

#include "assets/shader_source.h"

namespace terrasol::gbuffer {

inline constexpr int kAlbedo = 0;
inline constexpr int kNormals = 1;
inline constexpr int kSpecular = 2;
inline constexpr int kLight = 3;
inline constexpr int kTargets = 4;

inline constexpr std::array<GLenum, kTargets> kFormats = {GL_RGBA8, GL_RGBA16F, GL_RGBA8, GL_RGBA8};
inline constexpr GLenum kVertexNormalOnlyFormat = GL_RG16F;  // target 1 without normal maps
inline constexpr GLenum kDepthFormat = GL_DEPTH_COMPONENT32F;

// Texture units the lighting and debug passes read the targets from (depth after the colour targets).
inline constexpr int kDepthUnit = kTargets;

}  // namespace terrasol::gbuffer

namespace terrasol {

// What a scene's G-buffer holds: only the data some loaded pack can fill.
struct GBufferContents {
  bool surfaceNormals = true;  // a normal-mapped normal besides the vertex normal
  bool specular = true;        // the _s target

  GLenum format(int target) const {
    if (target == gbuffer::kNormals && !surfaceNormals) return gbuffer::kVertexNormalOnlyFormat;
    if (target == gbuffer::kSpecular && !specular) return GL_NONE;
    return gbuffer::kFormats[static_cast<std::size_t>(target)];
  }
  int bytesPerPixel() const;  // colour targets and depth
  // NO_NORMAL_MAPS / NO_SPECULAR_MAPS for what is left out; the shaders' one switch for both.
  std::vector<ShaderDefine> defines() const;
};

// GB_ALBEDO, GB_NORMALS, GB_SPECULAR, GB_LIGHT (output locations and texture units), GB_DEPTH_UNIT.
std::vector<ShaderDefine> gbufferDefines();

}  // namespace terrasol
