// terrasol-export's library: a region's meshed blocks written as .glb reload through the glTF loader
// with the mesher's vertex count, one primitive per render layer and the atlas as their texture.

#include <gtest/gtest.h>

#include "assets/gltf_model.h"
#include "core/paths.h"
#include "region_export.h"
#include "scene/scene_world.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

struct Exported {
  std::size_t mesherQuads = 0;
  ExportStats stats;
  Model model;
};

Exported exportOf(const Region& region, const std::string& name) {
  const SceneFile scene = parseScene(R"({
      "world": { "generator": "flat", "seed": 1, "edits": [
        { "set": [3, 64, 3], "block": "stone" },
        { "set": [5, 64, 3], "block": "glass" },
        { "fill": [7, 64, 3, 8, 64, 4], "block": "water" },
        { "set": [10, 64, 3], "block": "torch" },
        { "set": [12, 64, 3], "block": "short_grass" },
        { "set": [3, 65, 8], "block": "oak_leaves" } ] },
      "render": { "view_distance": 1 },
      "camera": { "position": [8, 70, 8], "look_at": [8, 64, 0] } })",
                                     "export.json");
  const BlockRegistry& blocks = testing::defaultBlocks();
  PackStack packs;
  packs.push(ResourcePack::open(resourcePackDir() / "default"));
  BlockAtlas atlas = buildBlockAtlas(blocks, packs);
  const BlockMeshTable table(
      blocks, [&](BlockId id, int face) { return atlas.textureOf(id, face); }, {}, {}, {}, atlas.tints);
  const SceneWorld world(scene, blocks);
  const std::vector<SectionMesh> meshes = meshRegion(world.world(), region, table);
  Exported out;
  for (const SectionMesh& m : meshes) out.mesherQuads += m.quads();
  // A folder per export: ctest runs these tests in parallel, and scratchDir empties its folder.
  const auto file = testing::scratchDir("export-" + name) / (name + ".glb");
  out.stats = exportRegion(meshes, region, atlas, file);
  out.model = loadModel(file);
  return out;
}

TEST(RegionExport, AWholeSectionReloadsWithTheMeshersVertexCount) {
  // Section (0, 8, 0): every face the mesher made there belongs to a block inside it.
  const Exported e = exportOf({{0, 64, 0}, {15, 79, 15}}, "section");
  EXPECT_GT(e.mesherQuads, 0u);
  EXPECT_EQ(e.stats.quads, e.mesherQuads);
  EXPECT_EQ(e.model.vertexCount(), 4 * e.mesherQuads);
  ASSERT_EQ(e.model.meshes.size(), 3u) << "opaque, cutout and translucent";
  ASSERT_EQ(e.model.materials.size(), 3u);
  EXPECT_EQ(e.model.materials[0].alphaMode, AlphaMode::Opaque);
  EXPECT_EQ(e.model.materials[1].alphaMode, AlphaMode::Mask);
  EXPECT_EQ(e.model.materials[2].alphaMode, AlphaMode::Blend);
  ASSERT_EQ(e.model.images.size(), 1u);
  EXPECT_GT(e.model.images[0].width, 0);
  for (const ModelMaterial& m : e.model.materials) EXPECT_EQ(m.baseColorImage, 0);
  EXPECT_GE(e.model.min.x, 0.0f);
  EXPECT_LE(e.model.max.x, 16.0f);
  std::size_t indices = 0;
  for (const ModelMesh& m : e.model.meshes) indices += m.indices.size();
  EXPECT_EQ(indices, 6 * e.mesherQuads);
}

TEST(RegionExport, ARegionKeepsOnlyTheFacesOfItsBlocks) {
  // The lone stone block: its top and four sides (the floor hides its bottom).
  const Exported stone = exportOf({{3, 64, 3}, {3, 64, 3}}, "stone");
  EXPECT_EQ(stone.stats.quads, 5u);
  EXPECT_EQ(stone.model.vertexCount(), 20u);
  ASSERT_EQ(stone.model.meshes.size(), 1u);
  EXPECT_EQ(stone.model.min, glm::vec3(0.0f)) << "positions from the region's corner";
  EXPECT_EQ(stone.model.max, glm::vec3(1.0f));
  // The floor under it: only the top faces of the 3 x 3 patch show.
  const Exported floor = exportOf({{0, 63, 0}, {2, 63, 2}}, "floor");
  EXPECT_EQ(floor.stats.quads, 9u);
}

}  // namespace
}  // namespace terrasol
