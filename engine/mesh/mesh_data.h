#pragma once
// What the mesher produces: plain vertex arrays per render layer, ready to upload.
//
// Every face is a quad of 4 vertices; the renderer draws quads with one shared index pattern
// (0 1 2, 0 2 3), so the vertex order also picks the quad's diagonal.

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <utility>
#include <vector>

#include "world/coords.h"

namespace terrasol {

// Which passes draw a quad. Merged quads (mesh/face_merge.h) stand in for the faces they join in the
// camera's passes only: the shadow pass warps every vertex, and a large quad's straight edges would
// not follow its warped faces' edges, so it keeps drawing those faces.
enum class QuadRole : std::uint8_t { Both = 0, Faces = 1, Merged = 2 };  // Faces: light's view only
inline constexpr int kQuadRoles = 3;

// One field of a packed 32-bit word: `bits` wide, starting at bit `shift`.
struct BitField {
  int shift;
  int bits;
  constexpr std::uint32_t mask() const { return (1u << bits) - 1u; }  // before shifting
  constexpr std::uint32_t pack(int value) const { return static_cast<std::uint32_t>(value) << shift; }
  constexpr int get(std::uint32_t word) const { return static_cast<int>((word >> shift) & mask()); }
  constexpr std::uint32_t replace(std::uint32_t word, int value) const {
    return (word & ~(mask() << shift)) | pack(value);
  }
};

// One vertex in 16 bytes:
//   position: x | y << 10 | z << 20, in 1/32 block from the section's minimum corner (0..512 each)
//   material: texture id (16 bits) | face (4 bits) << 16 | Tint (3 bits) << 20 | QuadRole (2 bits) << 23
//             face 0..5 = Direction (normal along an axis), 6..9 = the diagonal planes of cross plants
//   light:    block light sum (6 bits) | sky light sum (6 bits) << 6 | ambient occlusion 0..3 (2 bits) << 12
//             | tint red (8 bits) << 14 | tint green (8 bits) << 22
//             smooth light sums the open cells among the four around a corner, and there are always
//             ao + 1 of them (see the mesher), so the shader divides by that: sums are 0..60.
//             The tint colour (sRGB, core/tint_palette.h; blue in uv) is the columns' at the vertex,
//             interpolated between column centres; 0 on untinted vertices
//   uv:       u | v << 9 | tint blue (8 bits) << 18; u and v in 1/16 of the texture (0..256: merged
//             faces repeat it, mesh/face_merge.h), v = 0 at the texture's top row
// The fields and scales below are the layout's only statement: lib/block_vertex.glsl reads them as
// injected #defines (render/shader_defines.cpp), and a GL test unpacks packed vertices in GLSL.
struct PackedVertex {
  std::uint32_t position;
  std::uint32_t material;
  std::uint32_t light;
  std::uint32_t uv;

  static constexpr BitField kX{0, 10}, kY{10, 10}, kZ{20, 10};                          // position
  static constexpr BitField kTexture{0, 16}, kFace{16, 4}, kTint{20, 3}, kRole{23, 2};  // material
  static constexpr BitField kBlockLight{0, 6}, kSkyLight{6, 6}, kAo{12, 2};             // light
  // A tinted vertex's sRGB colour (TintPalette::rgb): red and green in light, blue in uv.
  static constexpr BitField kTintRed{14, 8}, kTintGreen{22, 8};    // light
  static constexpr BitField kU{0, 9}, kV{9, 9}, kTintBlue{18, 8};  // uv
  static constexpr std::uint32_t kUvBits = kU.mask() << kU.shift | kV.mask() << kV.shift;
  // A tint colour's bits in the light and uv words, packed once for many vertices.
  struct TintBits {
    std::uint32_t light = 0, uv = 0;
  };
  static constexpr TintBits packTint(glm::u8vec3 c) {
    return {kTintRed.pack(c.x) | kTintGreen.pack(c.y), kTintBlue.pack(c.z)};
  }
  static constexpr int kPositionSteps = 32;  // per block
  static constexpr int kUvSteps = 16;        // per texture
  static constexpr int kCellLight = 15;      // the brightest level one cell adds to a light sum

  static constexpr std::uint32_t packPosition(int x32, int y32, int z32) {
    return kX.pack(x32) | kY.pack(y32) | kZ.pack(z32);
  }
  static constexpr std::uint32_t packMaterial(int texture, int face, int tint) {
    return kTexture.pack(texture) | kFace.pack(face) | kTint.pack(tint);
  }
  static constexpr std::uint32_t packUv(int u, int v) { return kU.pack(u) | kV.pack(v); }
  int x32() const { return kX.get(position); }
  int y32() const { return kY.get(position); }
  int z32() const { return kZ.get(position); }
  int texture() const { return kTexture.get(material); }
  int face() const { return kFace.get(material); }
  int tint() const { return kTint.get(material); }
  QuadRole role() const { return static_cast<QuadRole>(kRole.get(material)); }
  void setRole(QuadRole r) {
    material = (material & ~(kRole.mask() << kRole.shift)) | kRole.pack(static_cast<int>(r));
  }
  int ao() const { return kAo.get(light); }
  glm::u8vec3 tintRgb() const { return {kTintRed.get(light), kTintGreen.get(light), kTintBlue.get(uv)}; }
  void setTint(TintBits bits) {
    constexpr TintBits kMask = packTint(glm::u8vec3(255));
    light = (light & ~kMask.light) | bits.light;
    uv = (uv & ~kMask.uv) | bits.uv;
  }
  void setTintRgb(glm::u8vec3 c) { setTint(packTint(c)); }
  int cellsLit() const { return ao() + 1; }  // how many cells the light sums add up
  // The averages x4, rounded: 0..60.
  int blockLight4() const { return (kBlockLight.get(light) * 4 + cellsLit() / 2) / cellsLit(); }
  int skyLight4() const { return (kSkyLight.get(light) * 4 + cellsLit() / 2) / cellsLit(); }
  int u() const { return kU.get(uv); }
  int v() const { return kV.get(uv); }
  friend bool operator==(const PackedVertex&, const PackedVertex&) = default;
};
static_assert(sizeof(PackedVertex) == 16, "the G-buffer pass expects 16-byte vertices");

// Per face id (0..5 Direction order, 6..9 the cross planes): the outward normal, the tangent (the
// direction u grows in) and "up" (the direction v shrinks in: texture up), so the normal map's
// tangent space is mat3(tangent, up, normal). normal = tangent x up, except on the back faces of the
// cross planes (7, 9): like vanilla they show the front's texture mirrored. The renderer builds its
// TBN from this table (injected into GLSL); a mesher test checks every emitted quad against it.
struct FaceBasis {
  float normal[3], tangent[3], up[3];
};
inline constexpr float kHalfSqrt2 = 0.70710678f;
inline constexpr FaceBasis kFaceBases[10] = {
    {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},                                        // West
    {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},                                        // East
    {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},                                        // Down
    {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},                                        // Up
    {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},                                       // North
    {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},                                         // South
    {{-kHalfSqrt2, 0, kHalfSqrt2}, {kHalfSqrt2, 0, kHalfSqrt2}, {0, 1, 0}},    // cross plane x=z, front
    {{kHalfSqrt2, 0, -kHalfSqrt2}, {kHalfSqrt2, 0, kHalfSqrt2}, {0, 1, 0}},    // and its back
    {{kHalfSqrt2, 0, kHalfSqrt2}, {kHalfSqrt2, 0, -kHalfSqrt2}, {0, 1, 0}},    // cross plane x=-z, front
    {{-kHalfSqrt2, 0, -kHalfSqrt2}, {kHalfSqrt2, 0, -kHalfSqrt2}, {0, 1, 0}},  // and its back
};

// The corners of a full face quad in the order the mesher writes them: their side along the tangent (u)
// and along up, (-,-) (+,-) (+,+) (-,+), counter-clockwise seen from outside.
inline constexpr int kCornerSigns[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

enum class MeshLayer : std::uint8_t { Opaque, Cutout, Translucent };
inline constexpr int kMeshLayers = 3;

// Grows without zeroing: the mesher writes every vertex it adds, so resize() need not clear them first.
template <class T>
struct UninitialisedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitialisedAllocator<U>;
  };
  UninitialisedAllocator() = default;
  template <class U>
  UninitialisedAllocator(const UninitialisedAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
using PackedVertices = std::vector<PackedVertex, UninitialisedAllocator<PackedVertex>>;

struct MeshData {
  PackedVertices vertices;  // 4 per quad
  std::size_t quads() const { return vertices.size() / 4; }
  // The block faces, one quad each as the light's view draws them: all quads but the merged ones.
  std::size_t faces() const {
    std::size_t n = 0;
    for (std::size_t q = 0; q < quads(); ++q) n += vertices[q * 4].role() != QuadRole::Merged ? 1 : 0;
    return n;
  }
};

// Which pairs of a section's six faces (Direction order) are joined by cells that are not opaque cubes:
// bit a * 6 + b is set, with b * 6 + a, when faces a and b are (section_visibility.h computes it).
using FaceLinks = std::uint64_t;
inline constexpr FaceLinks kAllFacesLinked = (FaceLinks{1} << 36) - 1;
inline constexpr FaceLinks kNoFacesLinked = 0;
constexpr bool linked(FaceLinks links, int a, int b) {
  return (links >> (a * 6 + b)) & 1u;
}

struct SectionMesh {
  SectionPos pos;
  std::array<MeshData, kMeshLayers> layers;
  FaceLinks faceLinks = kAllFacesLinked;  // all, when unknown
  std::size_t quads() const { return layers[0].quads() + layers[1].quads() + layers[2].quads(); }
  bool empty() const { return quads() == 0; }
};

}  // namespace terrasol
