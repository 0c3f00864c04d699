#include "render/shader_defines.h"

#include <cctype>
#include <charconv>
#include <sstream>
#include <string>
#include <utility>

#include "assets/labpbr.h"
#include "core/cloud_layer.h"
#include "core/day_cycle.h"
#include "core/luma.h"
#include "core/render_settings.h"
#include "core/tint.h"
#include "lod/lod_tile.h"
#include "lod/lod_vertex.h"
#include "mesh/mesh_data.h"
#include "render/gbuffer_layout.h"
#include "render/gl_slots.h"
#include "render/shadow_map.h"

namespace terrasol {
namespace {

// The shortest literal that reads back as `value` ("3.0", "0.2126"): the shader computes with the
// very float the C++ does.
std::string floatLiteral(float value) {
  char text[32];
  const std::string shortest(text, std::to_chars(text, text + sizeof text, value).ptr);
  return shortest.find_first_of(".e") == std::string::npos ? shortest + ".0" : shortest;
}

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

// Tint ids (core/tint.h) for lib/block_tint.glsl and the passes that single out water.
std::vector<ShaderDefine> tintDefines() {
  auto id = [](Tint t) { return std::to_string(static_cast<int>(t)); };
  return {{"TINT_NONE", id(Tint::None)}, {"TINT_WATER", id(Tint::Water)}};
}

// The packed vertex's fields and scales (mesh/mesh_data.h) for lib/block_vertex.glsl.
std::vector<ShaderDefine> vertexDefines() {
  using V = PackedVertex;
  const std::pair<const char*, BitField> fields[] = {{"X", V::kX},
                                                     {"Y", V::kY},
                                                     {"Z", V::kZ},  // position
                                                     {"TEXTURE", V::kTexture},
                                                     {"FACE", V::kFace},
                                                     {"TINT", V::kTint},
                                                     {"ROLE", V::kRole},  // material
                                                     {"BLOCK_LIGHT", V::kBlockLight},
                                                     {"SKY_LIGHT", V::kSkyLight},
                                                     {"AO", V::kAo},  // light
                                                     {"TINT_RED", V::kTintRed},
                                                     {"TINT_GREEN", V::kTintGreen},
                                                     {"TINT_BLUE", V::kTintBlue},
                                                     {"U", V::kU},
                                                     {"V", V::kV}};  // uv
  std::vector<ShaderDefine> defines;
  for (const auto& [name, f] : fields) {
    defines.push_back({"BV_" + std::string(name) + "_SHIFT", std::to_string(f.shift) + "u"});
    defines.push_back({"BV_" + std::string(name) + "_MASK", std::to_string(f.mask()) + "u"});
  }
  defines.push_back({"BV_POSITION_STEPS", floatLiteral(static_cast<float>(V::kPositionSteps))});
  defines.push_back({"BV_UV_STEPS", floatLiteral(static_cast<float>(V::kUvSteps))});
  defines.push_back({"BV_CELL_LIGHT", floatLiteral(static_cast<float>(V::kCellLight))});
  defines.push_back({"QUAD_ROLE_MERGED", std::to_string(static_cast<int>(QuadRole::Merged)) + "u"});
  return defines;
}

// DEBUG_VIEW_ALBEDO, ...: DebugView's values (core/render_settings.h) for debug_view.frag.
std::vector<ShaderDefine> debugViewDefines() {
  std::vector<ShaderDefine> defines;
  for (std::size_t i = 0; i < kDebugViews.size(); ++i) {
    std::string name = "DEBUG_VIEW_";
    for (const unsigned char c : kDebugViews[i]) name += static_cast<char>(std::toupper(c));
    defines.push_back({name, std::to_string(i)});
  }
  return defines;
}

// The cloud layer's shape and look (core/cloud_layer.h) for lib/clouds.glsl.
std::vector<ShaderDefine> cloudLayerDefines() {
  auto literal = [](double v) { return floatLiteral(static_cast<float>(v)); };
  return {{"CLOUD_THICKNESS", literal(kCloudThickness)},
          {"CLOUD_CELL", literal(kCloudCellBlocks)},
          {"CLOUD_ALPHA", literal(kCloudAlpha)},
          {"CLOUD_ALBEDO", literal(kCloudAlbedo)},
          {"CLOUD_SHADOW", literal(kCloudShadow)},
          {"CLOUD_RANGE", literal(kCloudRange)},
          {"CLOUD_VOLUME_THICKNESS", literal(kCloudVolumeThickness)},
          {"CLOUD_EXTINCTION", literal(kCloudExtinction)},
          {"CLOUD_VOLUME_SPAN", literal(kCloudVolumeSpan)},
          {"CLOUD_VOLUME_STEPS", std::to_string(kCloudVolumeSteps)},
          {"CLOUD_LIGHT_STEPS", std::to_string(kCloudLightSteps)}};
}

// Far terrain's vertex (lod/lod_vertex.h) for lod.vert.
std::vector<ShaderDefine> lodDefines() {
  return {{"LOD_Y_STEPS", std::to_string(kLodYSteps)},
          {"LOD_FLOOR_Y", std::to_string(kMinY)},
          {"LOD_XZ_STEPS", std::to_string(kLodXZSteps)},
          {"LOD_FACE_SMOOTH", std::to_string(kLodFaceSmooth) + "u"},
          {"LOD_FACE_SHIFT", std::to_string(kLodFaceShift)},
          {"LOD_WATER_SHIFT", std::to_string(kLodWaterShift)}};
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
      case GL_RGBA16F:
        bytes += 8;
        break;
      case GL_NONE:
        break;
      default:
        bytes += 4;
        break;  // RGBA8, RG16F
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
  for (auto& d : vertexDefines()) defines.push_back(std::move(d));
  for (auto& d : debugViewDefines()) defines.push_back(std::move(d));
  defines.push_back({"SKY_RADIANCE", floatLiteral(kSkyRadiance)});
  for (auto& d : cloudLayerDefines()) defines.push_back(std::move(d));
  for (auto& d : lodDefines()) defines.push_back(std::move(d));
  const glm::vec3 w = kLumaWeights;
  defines.push_back({"LUMA_WEIGHTS", "vec3(" + floatLiteral(w.r) + ", " + floatLiteral(w.g) + ", " +
                                         floatLiteral(w.b) + ")"});
  return defines;
}

}  // namespace terrasol
