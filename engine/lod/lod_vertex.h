#pragma once
// Far terrain's 12-byte vertex, shared by the mesher (lod/lod_mesh.h) and the renderer, which injects
// these constants into its shaders (LOD_*).

#include <cstdint>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace terrasol {

inline constexpr int kLodYSteps = 8;   // a vertex's height is in 1/8 block: water's surface lies at 7/8
inline constexpr int kLodXZSteps = 2;  // its place in 1/2 cell: a heightfield's vertices sit mid-cell

inline constexpr int kLodFaceShift = 24;
inline constexpr int kLodWaterShift = 27;
// The face field (3 bits): a Direction (0..5) for a terrace's quad, or this for a heightfield's
// vertex, whose normal is in cellX, cellZ instead.
inline constexpr std::uint32_t kLodFaceSmooth = 6;

struct LodVertex {
  // The corner, in 1/kLodXZSteps cell from the tile's minimum corner, and its height.
  std::int16_t x = 0, z = 0;
  std::int16_t y = 0;  // 1/kLodYSteps block
  // A terrace's corner: the cell whose height it follows, plus one (0 and kLodTileCells + 1 lie beyond
  // the tile's sides): where full detail covers that cell the renderer drops the vertex to the world's
  // floor, so a wall next to it reaches down to whatever full detail shows there. A heightfield's
  // vertex: the surface's normal, octahedral, [-1, 1] as 0..255.
  std::uint8_t cellX = 0, cellZ = 0;
  // sRGB red | green << 8 | blue << 16 | face << kLodFaceShift | water << kLodWaterShift.
  std::uint32_t material = 0;
};
static_assert(sizeof(LodVertex) == 12);

inline std::uint32_t lodMaterial(glm::vec3 srgb, std::uint32_t face, bool water) {
  const glm::uvec3 c(glm::clamp(srgb, 0.0f, 1.0f) * 255.0f + 0.5f);
  return c.r | c.g << 8 | c.b << 16 | face << kLodFaceShift |
         static_cast<std::uint32_t>(water) << kLodWaterShift;
}

}  // namespace terrasol
