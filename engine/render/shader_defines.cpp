#include "render/shader_defines.h"

#include <sstream>

#include "assets/labpbr.h"
#include "core/tint.h"
#include "mesh/mesh_data.h"
#include "render/gbuffer_layout.h"
#include "render/gl_slots.h"
#include "render/shadow_map.h"

namespace terrasol {
namespace {

std::string vec3Literal(float x, float y, float z) {
  std::ostringstream out;
  out.precision(9);
  out << "vec3(" << x << ", " << y << ", " << z << ")";
  return out.str();
}

// "vec3[N](vec3(...), ...)" from N vectors picked out of the face table.
template <class Pick>
std::string faceArray(Pick pick) {
  std::string text = "vec3[10](";
  for (int f = 0; f < 10; ++f) {
    const float* v = pick(kFaceBases[f]);
    text += (f ? ", " : "") + vec3Literal(v[0], v[1], v[2]);
  }
  return text + ")";
}

std::string metalArray() {
  std::string text = "vec3[8](";
  for (int id = 230; id <= 237; ++id) {
    const glm::vec3 f0 = labpbr::metalF0(id);
    text += (id > 230 ? ", " : "") + vec3Literal(f0.x, f0.y, f0.z);
  }
  return text + ")";
}

// Tint ids and colours (core/tint.h) for lib/block_tint.glsl.
std::vector<ShaderDefine> tintDefines() {
  auto literal = [](glm::vec3 c) { return vec3Literal(c.r, c.g, c.b); };
  auto id = [](Tint t) { return std::to_string(static_cast<int>(t)); };
  return {{"TINT_GRASS", id(Tint::Grass)},
          {"TINT_FOLIAGE", id(Tint::Foliage)},
          {"TINT_WATER", id(Tint::Water)},
          {"TINT_BIRCH", id(Tint::Birch)},
          {"TINT_SPRUCE", id(Tint::Spruce)},
          {"WATER_COLD", literal(kWaterCold)},
          {"WATER_TEMPERATE", literal(kWaterTemperate)},
          {"WATER_WARM", literal(kWaterWarm)},
          {"WATER_TEMPERATE_FROM", std::to_string(kWaterTemperateFrom)},
          {"WATER_TEMPERATE_TO", std::to_string(kWaterTemperateTo)},
          {"BIRCH_FOLIAGE", literal(kBirchFoliage)},
          {"SPRUCE_FOLIAGE", literal(kSpruceFoliage)}};
}

}  // namespace

std::vector<ShaderDefine> gbufferDefines() {
  auto define = [](const char* name, int value) { return ShaderDefine{name, std::to_string(value)}; };
  return {define("GB_ALBEDO", gbuffer::kAlbedo), define("GB_NORMALS", gbuffer::kNormals),
          define("GB_SPECULAR", gbuffer::kSpecular), define("GB_LIGHT", gbuffer::kLight),
          define("GB_DEPTH_UNIT", gbuffer::kDepthUnit)};
}

int GBufferContents::bytesPerPixel() const {
  int bytes = 4;  // DEPTH32F
  for (int i = 0; i < gbuffer::kTargets; ++i) {
    switch (format(i)) {
      case GL_RGBA16F: bytes += 8; break;
      case GL_NONE: break;
      default: bytes += 4; break;  // RGBA8, RG16F
    }
  }
  return bytes;
}

std::vector<ShaderDefine> GBufferContents::defines() const {
  std::vector<ShaderDefine> defines;
  if (!surfaceNormals) defines.push_back({"NO_NORMAL_MAPS", "1"});
  if (!specular) defines.push_back({"NO_SPECULAR_MAPS", "1"});
  return defines;
}

std::vector<ShaderDefine> rendererDefines() {
  std::vector<ShaderDefine> defines = slotDefines();
  for (auto& d : gbufferDefines()) defines.push_back(std::move(d));
  defines.push_back({"FACE_NORMALS", faceArray([](const FaceBasis& b) { return b.normal; })});
  defines.push_back({"FACE_TANGENTS", faceArray([](const FaceBasis& b) { return b.tangent; })});
  defines.push_back({"FACE_UPS", faceArray([](const FaceBasis& b) { return b.up; })});
  defines.push_back({"LABPBR_METAL_F0", metalArray()});
  defines.push_back({"SHADOW_MAX_CASCADES", std::to_string(kMaxShadowCascades)});
  for (auto& d : tintDefines()) defines.push_back(std::move(d));
  return defines;
}

}  // namespace terrasol
