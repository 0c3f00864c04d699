#pragma once
// A world region's meshed blocks as a glTF 2.0 binary: the mesher's quads whose block lies in the
// region, positions relative to the region's minimum corner, the atlas's albedo as the base colour
// texture (embedded PNG), biome tint and corner AO as vertex colours, one primitive per render layer
// (OPAQUE, MASK for cutout, BLEND for translucent). Opens in Blender or any glTF viewer.

#include <filesystem>
#include <glm/vec3.hpp>
#include <vector>

#include "mesh/mesher.h"
#include "scene/block_atlas.h"

namespace terrasol {

struct Region {
  glm::ivec3 min{0}, max{0};  // inclusive corners, min <= max
  bool contains(glm::ivec3 p) const {
    return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y && p.z <= max.z;
  }
};

// The block a quad shows a face of (the cell just behind the face's centre).
glm::ivec3 quadBlock(const SectionPos& section, const PackedVertex* quad);

// Meshes of every section overlapping the region (the world around it loaded and lit).
std::vector<SectionMesh> meshRegion(const World& world, const Region& region, const BlockMeshTable& table);

struct ExportStats {
  std::size_t quads = 0, vertices = 0, triangles = 0;
};

// Writes `meshes` (sections covering the region) clipped to `region`. Throws Error naming the file.
ExportStats exportRegion(const std::vector<SectionMesh>& meshes, const Region& region,
                         const BlockAtlas& atlas, const std::filesystem::path& file);

}  // namespace terrasol
