#pragma once
// Far terrain's 12-byte vertex, shared by the mesher (lod/lod_mesh.h) and the renderer, which injects
// these constants into its shaders (LOD_*).

#include <cstdint>

namespace terrasol {

inline constexpr int kLodYSteps = 8;  // a vertex's height is in 1/8 block: water's surface lies at 7/8

struct LodVertex {
  // The corner, in cells from the tile's minimum corner (0..kLodTileCells), and its height.
  std::int16_t x = 0, z = 0;
  std::int16_t y = 0;  // 1/kLodYSteps block
  // The cell whose height the vertex follows, plus one (0 and kLodTileCells + 1 lie beyond the
  // tile's sides): where full detail covers that cell the renderer drops the vertex to the world's
  // floor, so a wall next to it reaches down to whatever full detail shows there.
  std::uint8_t cellX = 0, cellZ = 0;
  // sRGB red | green << 8 | blue << 16 | face (Direction) << kLodFaceShift | water << kLodWaterShift.
  std::uint32_t material = 0;
};
static_assert(sizeof(LodVertex) == 12);

inline constexpr int kLodFaceShift = 24;
inline constexpr int kLodWaterShift = 27;

}  // namespace terrasol
