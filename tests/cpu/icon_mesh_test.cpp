// What inventory icons draw (mesh/block_icon_mesh.h): which blocks get one, and that each has quads.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/paths.h"
#include "mesh/block_icon_mesh.h"
#include "scene/block_atlas.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

TEST(IconMesh, EveryPlaceableBlockHasAnIconWithQuads) {
  const BlockRegistry& blocks = testing::defaultBlocks();
  PackStack packs;
  packs.push(ResourcePack::open(resourcePackDir() / "default"));
  const BlockAtlas atlas = buildBlockAtlas(blocks, packs);
  const BlockMeshTable table = meshTableOf(blocks, atlas);
  const std::vector<BlockId> states = iconStates(blocks, atlas.placeholders);
  EXPECT_GE(states.size(), 150u);
  auto offered = [&](const char* name) {
    return std::find(states.begin(), states.end(), blocks.id(name)) != states.end();
  };
  EXPECT_TRUE(offered("torch") && offered("oak_stairs") && offered("water") && offered("short_grass"));
  EXPECT_FALSE(offered("wall_torch")) << "placed by holding a torch against a wall";
  EXPECT_FALSE(offered("air"));
  EXPECT_FALSE(offered("cave_air"));
  EXPECT_TRUE(atlas.placeholders.empty()) << "the default pack draws every block";
  const std::vector<std::string> undrawn{"stone"};
  const std::vector<BlockId> without = iconStates(blocks, undrawn);
  EXPECT_EQ(std::find(without.begin(), without.end(), blocks.id("stone")), without.end())
      << "no pack draws it";
  for (const BlockId s : states) {
    const SectionMesh mesh = iconMesh(table, blocks, s);
    EXPECT_GT(mesh.quads(), 0u) << blocks.stateName(s);
    // Lit by open sky all round: no corner darker than the sky's 15.
    for (const MeshData& layer : mesh.layers)
      for (const PackedVertex& v : layer.vertices) ASSERT_EQ(v.skyLight4(), 60) << blocks.stateName(s);
  }
}

}  // namespace
}  // namespace terrasol
