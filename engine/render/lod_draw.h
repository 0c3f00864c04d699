#pragma once
// Far terrain's tiles drawn by a pass (the G-buffer's or the shadow map's): those whose box lies in a
// frustum, each through its own vertices with the uniforms lod.vert reads. GL thread only.

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>

#include "render/frustum.h"
#include "render/gl/program.h"
#include "render/gl/uniforms.h"
#include "render/lod_meshes.h"

namespace terrasol {

// lod.vert's per-tile uniforms.
struct LodTileUniforms {
  LodTileUniforms() = default;
  explicit LodTileUniforms(const LinkedProgram& p)
      : tileOffset(p, "u_tileOffset"),
        cellBlocks(p, "u_cellBlocks"),
        maskOffset(p, "u_maskOffset"),
        masked(p, "u_masked") {}
  gl::Uniform<glm::vec3> tileOffset;  // the tile's minimum corner at y 0, from the camera
  gl::Uniform<int> cellBlocks;
  gl::Uniform<glm::ivec2> maskOffset;  // the tile's minimum corner, in blocks from the mask's
  gl::Uniform<bool> masked;            // the tile reaches into full detail
};

struct LodDrawCounts {
  int drawn = 0, culled = 0;
  std::int64_t triangles = 0;
};

// With `facing`, terraces' walls turned away from the camera (at the origin of camera-relative space)
// for a whole tile are left out; without, every face is drawn (the light's view, culling nothing).
// The program, with `u`, is bound.
LodDrawCounts drawLodTiles(const LodMeshes& lod, const FrustumPlanes& frustum, glm::dvec3 camera,
                           const LodTileUniforms& u, bool facing);

}  // namespace terrasol
