// Model blocks through the mesher: each state's baked quads from the default pack's blockstates and
// models (scene/block_atlas.h), left out against opaque cubes across their cullface.

#include <gtest/gtest.h>

#include "core/paths.h"
#include "scene/block_atlas.h"
#include "support/mesh_world.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;

PackStack defaultPack() {
  PackStack packs;
  packs.push(ResourcePack::open(resourcePackDir() / "default"));
  return packs;
}

struct ModelWorld : testing::MeshWorld {
  explicit ModelWorld(const BlockAtlas& atlas) : testing::MeshWorld(meshTableOf(defaultBlocks(), atlas)) {}
};

class ModelMesh : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { atlas_ = new BlockAtlas(buildBlockAtlas(defaultBlocks(), defaultPack())); }
  static void TearDownTestSuite() { delete atlas_; }
  static const BlockAtlas* atlas_;
};
const BlockAtlas* ModelMesh::atlas_ = nullptr;

TEST_F(ModelMesh, EachStateHasItsModelsQuads) {
  const BlockRegistry& blocks = defaultBlocks();
  const auto quads = [&](const std::string& state) { return atlas_->modelQuads[blocks.id(state)].size(); };
  EXPECT_EQ(quads("stone_slab"), 6u);
  EXPECT_EQ(quads("stone_slab[type=top]"), 6u);
  EXPECT_EQ(quads("stone_slab[type=double]"), 6u);
  EXPECT_EQ(quads("oak_stairs"), 11u);
  EXPECT_EQ(quads("oak_stairs[shape=inner_left]"), 15u);
  EXPECT_EQ(quads("oak_stairs[shape=outer_right,half=top]"), 11u);
  for (BlockId s = 0; s < blocks.size(); ++s) {
    if (blocks[s].shape == BlockShape::Model) {
      EXPECT_FALSE(atlas_->modelQuads[s].empty()) << blocks.stateName(s);
    }
  }
  // A bottom slab lies in the lower half of its cell; a top slab in the upper.
  for (const ModelQuad& q : atlas_->modelQuads[blocks.id("stone_slab")]) {
    for (const auto& c : q.corners32) EXPECT_LE(c[1], 16);
  }
  for (const ModelQuad& q : atlas_->modelQuads[blocks.id("stone_slab[type=top]")]) {
    for (const auto& c : q.corners32) EXPECT_GE(c[1], 16);
  }
  for (const PackProblem& p : atlas_->problems) ADD_FAILURE() << p.message;
}

TEST_F(ModelMesh, QuadsAgainstAnOpaqueCubeAcrossTheirCullfaceAreLeftOut) {
  ModelWorld w(*atlas_);
  // Counted in the section of y 64..79: the stone below (y 63) lies in the one beneath. Nothing here
  // is an opaque cube but stone, so the stone keeps its faces against the shaped blocks.
  w.set({3, 64, 3}, "stone_slab");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 6u) << "a slab in the air";
  w.set({3, 63, 3}, "stone");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 5u) << "on stone: its bottom goes";
  w.set({3, 65, 3}, "stone");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 5u + 6u) << "a bottom slab's top is not against the block above";
  w.set({3, 64, 3}, "stone_slab[type=top]");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 5u + 6u) << "a top slab's top is; its bottom lies inside the cell";
  w.set({3, 64, 3}, "oak_stairs[facing=east]");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 9u + 6u) << "stairs lose their bottom and their back half's top";
  w.set({4, 64, 3}, "stone");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 7u + 6u + 6u) << "and both east faces against stone on the east";
}

// Without blockstates (a stack without the default pack) a model block is a cube of the missing
// texture, and the atlas says why; nothing throws.
TEST(ModelMeshMissing, ABlockWithoutBlockstatesIsAMissingCube) {
  const BlockAtlas atlas = buildBlockAtlas(defaultBlocks(), PackStack{});
  const std::vector<ModelQuad>& slab = atlas.modelQuads[defaultBlocks().id("stone_slab")];
  EXPECT_EQ(slab.size(), 6u);
  bool said = false;
  for (const PackProblem& p : atlas.problems)
    said = said || p.message.find("blockstates of stone_slab") != std::string::npos;
  EXPECT_TRUE(said);
}

}  // namespace
}  // namespace terrasol
