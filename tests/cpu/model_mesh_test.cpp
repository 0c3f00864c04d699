// Model blocks through the mesher: each state's baked quads from the default pack's blockstates and
// models (scene/block_atlas.h), left out against opaque cubes across their cullface.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "assets/block_model.h"
#include "assets/block_states.h"
#include "assets/model_bake.h"
#include "core/paths.h"
#include "scene/block_atlas.h"
#include "support/mesh_world.h"
#include "support/pack_builder.h"

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
  EXPECT_EQ(quads("stone_slab[type=top,waterlogged=false]"), 6u);
  EXPECT_EQ(quads("stone_slab[type=double,waterlogged=false]"), 6u);
  EXPECT_EQ(quads("oak_stairs"), 11u);
  EXPECT_EQ(quads("oak_stairs[facing=north,half=bottom,shape=inner_left,waterlogged=false]"), 15u);
  EXPECT_EQ(quads("oak_stairs[facing=north,half=top,shape=outer_right,waterlogged=false]"), 11u);
  for (BlockId s = 0; s < blocks.size(); ++s) {
    // A wall with no post and no sides is nothing, as in Minecraft (its neighbours never leave it so).
    const auto values = blocks.stateValues(s);
    const bool bareWall = blocks[s].connects == Connects::Wall && values.at("up") == "false" &&
                          values.at("north") == "none" && values.at("east") == "none" &&
                          values.at("south") == "none" && values.at("west") == "none";
    // Growths on faces (vines, lichen) holding none are nothing too; a bubble column is its water.
    const auto bare = [&](const char* side) { return !values.contains(side) || values.at(side) == "false"; };
    const bool bareGrowth = values.contains("north") && bare("north") && bare("east") && bare("south") &&
                            bare("west") && bare("up") && bare("down");
    const bool justWater = blocks[s].name == "bubble_column";
    if (blocks[s].shape == BlockShape::Model && !bareWall && !bareGrowth && !justWater) {
      EXPECT_FALSE(atlas_->modelQuads[s].empty()) << blocks.stateName(s);
    }
  }
  // A bottom slab lies in the lower half of its cell; a top slab in the upper.
  for (const ModelQuad& q : atlas_->modelQuads[blocks.id("stone_slab")]) {
    for (const auto& c : q.corners32) EXPECT_LE(c[1], 16);
  }
  for (const ModelQuad& q : atlas_->modelQuads[blocks.id("stone_slab[type=top,waterlogged=false]")]) {
    for (const auto& c : q.corners32) EXPECT_GE(c[1], 16);
  }
  for (const PackProblem& p : atlas_->problems) ADD_FAILURE() << p.message;
}

TEST_F(ModelMesh, QuadsAgainstAnOpaqueCubeAcrossTheirCullfaceAreLeftOut) {
  ModelWorld w(*atlas_);
  // Counted in the section of y 64..79: the stone below (y 63) lies in the one beneath.
  w.set({3, 64, 3}, "stone_slab");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 6u) << "a slab in the air";
  w.set({3, 63, 3}, "stone");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 5u) << "on stone: its bottom goes";
  w.set({3, 65, 3}, "stone");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 5u + 6u) << "a bottom slab's top is not against the block above";
  w.set({3, 64, 3}, "stone_slab[type=top,waterlogged=false]");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 5u + 5u)
      << "a top slab's top is, and hides the stone's bottom; the slab's bottom lies inside the cell";
  w.set({3, 64, 3}, "oak_stairs[facing=east,half=bottom,shape=straight,waterlogged=false]");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 9u + 6u) << "stairs lose their bottom and their back half's top";
  w.set({4, 64, 3}, "stone");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 7u + 6u + 5u)
      << "and both east faces against stone on the east, whose west face the stairs' back hides";
}

// Every state of every model block the default pack draws, meshed alone in the air, draws all its
// quads; walled in by stone on all six sides, exactly those without a cullface stay (an opaque cube
// hides every face culled against it). States holding water draw it too; the waterlogged tests count
// that.
TEST_F(ModelMesh, EveryStateDrawsItsQuadsAndStoneHidesItsCulledOnes) {
  const BlockRegistry& blocks = defaultBlocks();
  ModelWorld world(*atlas_);
  const BlockPos at{3, 64, 3};
  const std::set<std::string> placeholders(atlas_->placeholders.begin(), atlas_->placeholders.end());
  int states = 0;
  for (BlockId s = 0; s < blocks.size(); ++s) {
    if (blocks[s].shape != BlockShape::Model || blocks.holdsWater()[s] ||
        placeholders.contains(blocks[s].name))
      continue;
    ++states;
    const std::vector<ModelQuad>& quads = atlas_->modelQuads[s];
    const auto inner = static_cast<std::size_t>(
        std::count_if(quads.begin(), quads.end(), [](const ModelQuad& q) { return q.cullface < 0; }));
    const auto drawn = [&] {
      const SectionMesh mesh = world.mesh();
      std::size_t n = 0;
      for (const MeshData& layer : mesh.layers) {
        for (std::size_t q = 0; q < layer.quads(); ++q) {
          const PackedVertex* v = &layer.vertices[q * 4];
          if (v->role() == QuadRole::Merged) continue;
          bool inside = true, intoCell = false;
          for (int a = 0; a < 3; ++a) {
            const auto c = [&](int i) { return a == 0 ? v[i].x32() : a == 1 ? v[i].y32() : v[i].z32(); };
            const int lo = a == 1 ? 0 : 96;  // the cell's corner in the section, 1/32
            for (int i = 0; i < 4; ++i) inside = inside && c(i) >= lo && c(i) <= lo + 32;
            // A stone neighbour's face on the cell's side, facing into it.
            const bool onLow = c(0) == lo && c(1) == lo && c(2) == lo,
                       onHigh = c(0) == lo + 32 && c(1) == lo + 32 && c(2) == lo + 32;
            intoCell = intoCell || (onLow && v->face() == a * 2 + 1) || (onHigh && v->face() == a * 2);
          }
          n += inside && !intoCell;
        }
      }
      return n;
    };
    world.set(at, blocks.stateName(s));
    ASSERT_EQ(drawn(), quads.size()) << blocks.stateName(s) << " in the air";
    for (int d = 0; d < 6; ++d) {
      const BlockPos& o = kDirectionOffsets[d];
      world.set(at.offset(o.x, o.y, o.z), "stone");
    }
    ASSERT_EQ(drawn(), inner) << blocks.stateName(s) << " walled in";
    for (int d = 0; d < 6; ++d) {
      const BlockPos& o = kDirectionOffsets[d];
      world.set(at.offset(o.x, o.y, o.z), "air");
    }
  }
  EXPECT_GT(states, 400);
}

// Shaped neighbours hide what they cover: a face against a shape's whole side goes, one against part
// of a side stays unless it lies within that part.
TEST_F(ModelMesh, ShapedNeighboursHideTheFacesTheyCover) {
  const BlockRegistry& blocks = defaultBlocks();
  const ModelWorld world(*atlas_);
  const BlockMeshTable::Entry& doubleSlab =
      world.table[blocks.id("stone_slab[type=double,waterlogged=false]")];
  EXPECT_EQ(doubleSlab.fullSides, 0b111111);
  const BlockMeshTable::Entry& slab = world.table[blocks.id("stone_slab")];
  EXPECT_EQ(slab.fullSides, 1u << static_cast<int>(Direction::Down));
  EXPECT_TRUE(slab.coverage.covers(Direction::East, {0, 0, 8, 16}));
  const auto count = [&](std::initializer_list<std::pair<BlockPos, const char*>> cells) {
    ModelWorld w(*atlas_);
    for (const auto& [p, name] : cells) w.set(p, name);
    return w.quads(MeshLayer::Opaque);
  };
  EXPECT_EQ(count({{{3, 64, 3}, "stone_slab"}, {{4, 64, 3}, "stone_slab"}}), 5u + 5u)
      << "two bottom slabs hide each other's touching halves";
  EXPECT_EQ(count({{{3, 64, 3}, "stone_slab"}, {{4, 64, 3}, "stone_slab[type=top,waterlogged=false]"}}),
            6u + 6u)
      << "a bottom and a top slab do not meet";
  EXPECT_EQ(count({{{3, 64, 3}, "stone"}, {{4, 64, 3}, "stone_slab[type=double,waterlogged=false]"}}),
            5u + 5u)
      << "stone against a double slab, both ways";
  EXPECT_EQ(count({{{3, 64, 3}, "stone"}, {{4, 64, 3}, "stone_slab"}}), 6u + 5u)
      << "stone keeps its face against a bottom slab's open half";
  EXPECT_EQ(count({{{3, 64, 3}, "stone_slab"},
                   {{4, 64, 3}, "oak_stairs[facing=west,half=bottom,shape=straight,waterlogged=false]"}}),
            5u + 10u)
      << "a slab's side against the stairs' back; the stairs' back against the slab's lower half only";
}

// The vertices of the quads facing `face` whose corners all satisfy `where` (section positions, 1/32).
template <class Where>
std::vector<PackedVertex> verticesOf(const SectionMesh& mesh, Direction face, Where&& where) {
  std::vector<PackedVertex> found;
  const PackedVertices& v = mesh.layers[static_cast<std::size_t>(MeshLayer::Opaque)].vertices;
  for (std::size_t q = 0; q + 3 < v.size(); q += 4) {
    if (v[q].face() != static_cast<int>(face) || v[q].role() == QuadRole::Merged) continue;
    if (std::all_of(v.begin() + static_cast<long>(q), v.begin() + static_cast<long>(q) + 4, where))
      found.insert(found.end(), v.begin() + static_cast<long>(q), v.begin() + static_cast<long>(q) + 4);
  }
  return found;
}

// Vanilla's smooth light on partial faces: a stair's own shape darkens the corner where its step
// meets its riser, and a slab's side takes the occlusion of the full face's corners interpolated at
// its vertices.
TEST_F(ModelMesh, ModelFacesGetSmoothLightAndAmbientOcclusion) {
  ModelWorld stairs(*atlas_);
  stairs.set(
      {3, 64, 3},
      "oak_stairs[facing=east,half=bottom,shape=straight,waterlogged=false]");  // the step on the west half,
                                                                                // the riser at x = 8/16
  const SectionMesh mesh = stairs.mesh();
  const auto inCell = [](const PackedVertex& v) { return v.x32() / 32 == 3 || v.x32() == 128; };
  const std::vector<PackedVertex> step =
      verticesOf(mesh, Direction::Up, [&](const PackedVertex& v) { return inCell(v) && v.y32() == 16; });
  ASSERT_EQ(step.size(), 4u);
  for (const PackedVertex& v : step) EXPECT_EQ(v.ao(), v.x32() == 3 * 32 + 16 ? 2 : 3) << v.x32();
  const std::vector<PackedVertex> riser =
      verticesOf(mesh, Direction::West, [&](const PackedVertex& v) { return v.x32() == 3 * 32 + 16; });
  ASSERT_EQ(riser.size(), 4u);
  for (const PackedVertex& v : riser) EXPECT_EQ(v.ao(), v.y32() == 16 ? 2 : 3) << v.y32();
  // The step, inside the stairs' cell, is lit from there: the sky's full light comes down through the
  // stairs' open top half and stops at their closed bottom, so their cell has sky light 15, as the
  // three others around each corner. Their average x4 is 60.
  for (const PackedVertex& v : step) EXPECT_EQ(v.skyLight4(), 60);

  // A bottom slab's west side, under a wall of stone one block up and to the west: the full face's
  // top corners there see two open cells of four (ao 1), its bottom corners all four (ao 3), so the
  // slab's side, half as high, has ao 2 at its top and 3 at its bottom.
  ModelWorld slab(*atlas_);
  slab.set({3, 64, 3}, "stone_slab");
  for (int z = 1; z <= 5; ++z) slab.set({2, 65, z}, "stone");
  const std::vector<PackedVertex> side =
      verticesOf(slab.mesh(), Direction::West, [](const PackedVertex& v) { return v.x32() == 3 * 32; });
  ASSERT_EQ(side.size(), 4u);
  for (const PackedVertex& v : side) EXPECT_EQ(v.ao(), v.y32() == 16 ? 2 : 3) << v.y32();
}

// Light sides come from the models' boxes: a bottom slab's bottom, a stair's bottom and back. The
// shapes the world tests write by hand (they read no models) agree with the models.
TEST(ModelShapes, LightSidesFollowTheModelsAndTheTestsHandShapes) {
  const BlockRegistry& blocks = defaultBlocks();
  const BlockShapes shapes = defaultPackShapes(blocks);
  const auto sides = [&](const char* state) { return shapes.lightSides()[blocks.id(state)]; };
  const auto bit = [](Direction d) { return 1 << static_cast<int>(d); };
  EXPECT_EQ(sides("stone_slab"), bit(Direction::Down));
  EXPECT_EQ(sides("stone_slab[type=top,waterlogged=false]"), bit(Direction::Up));
  EXPECT_EQ(sides("stone_slab[type=double,waterlogged=false]"), 0x3F);
  EXPECT_EQ(sides("oak_stairs[facing=east,half=bottom,shape=straight,waterlogged=false]"),
            bit(Direction::Down) | bit(Direction::East));
  EXPECT_EQ(sides("oak_stairs[facing=north,half=top,shape=straight,waterlogged=false]"),
            bit(Direction::Up) | bit(Direction::North));
  EXPECT_EQ(sides("oak_stairs[facing=north,half=bottom,shape=outer_left,waterlogged=false]"),
            bit(Direction::Down));
  EXPECT_EQ(sides("stone"), 0) << "cubes stop light by their opacity";
  for (BlockId s = 0; s < blocks.size(); ++s) {
    if (!testing::handShapes().boxes(s).empty()) {
      EXPECT_EQ(testing::handShapes().lightSides()[s], shapes.lightSides()[s]) << blocks.stateName(s);
    }
  }
}

// States that pick alike share one bake (BlockModelBake::sameAs): every state's boxes, read back
// through its earliest twin, are the boxes its own blockstates pick for it, state by state; and one
// bake of the default pack alone gives the shapes too.
TEST(ModelShapes, EveryStateHasTheBoxesItsBlockstatesPick) {
  const BlockRegistry& blocks = defaultBlocks();
  const PackStack packs = defaultPack();
  EXPECT_TRUE(isDefaultPackAlone(packs));
  const BlockModelBake bake = bakeBlockModels(blocks, packs);
  const BlockShapes shapes = blockShapesOf(blocks, bake);
  ModelLibrary library(packs);
  std::size_t shared = 0, checked = 0;
  for (std::size_t b = 0; b < blocks.blockCount(); ++b) {
    const BlockType& type = blocks.block(b);
    if (type.shape != BlockShape::Model) continue;
    const BlockStates states = BlockStates::load(packs, type.name);
    for (std::uint16_t i = 0; i < type.stateCount; ++i) {
      const auto s = static_cast<BlockId>(type.firstState + i);
      shared += bake.sameAs[s] != s;
      // Every 7th state: the whole table would take a minute.
      if (i % 7 != 0 && i + 1 != type.stateCount) continue;
      std::vector<ShapeBox> expected;
      for (const ModelPlacement& p : states.select(blocks.stateValues(s), {}))
        for (const std::array<float, 6>& box : placedBoxes(library.model(p.model), p)) {
          const auto at = [&](int k) {
            return static_cast<int>(std::lround(box[static_cast<std::size_t>(k)]));
          };
          expected.push_back({{at(0), at(1), at(2)}, {at(3), at(4), at(5)}});
        }
      ASSERT_EQ(shapes.boxes(s), expected) << blocks.stateName(s);
      ++checked;
    }
  }
  EXPECT_GT(checked, 4000u);
  EXPECT_GT(shared, 15000u) << "most states pick as an earlier one";
}

// A resource pack overriding one vanilla model: a pane's post 1/16 thick instead of 2/16. The atlas,
// and so the mesh, follow the pack; collision stays the default pack's (as in Minecraft, a pack does
// not change how blocks collide).
TEST(ModelMeshPack, APackOverridingAModelChangesTheMesh) {
  testing::PackBuilder thin("thin_pane");
  thin.asset("models/block/template_glass_pane_post.json", R"({"ambientocclusion": false,
      "textures": {"particle": "#pane"},
      "elements": [{"from": [7.5, 0, 7.5], "to": [8.5, 16, 8.5], "faces": {
        "down": {"texture": "#edge", "cullface": "down"}, "up": {"texture": "#edge", "cullface": "up"},
        "north": {"texture": "#pane"}, "south": {"texture": "#pane"},
        "west": {"texture": "#pane"}, "east": {"texture": "#pane"}}}]})");
  PackStack packs = defaultPack();
  packs.push(ResourcePack::open(thin.dir()));
  const BlockRegistry& blocks = defaultBlocks();
  const BlockId post = blocks.id("glass_pane");  // nothing joined: the post and four no-side faces
  const auto xExtent = [&](const BlockAtlas& atlas) {
    int lo = 32, hi = 0;
    for (const ModelQuad& q : atlas.modelQuads[post])
      if (q.face == static_cast<int>(Direction::Up))
        for (const auto& c : q.corners32) lo = std::min(lo, c[0]), hi = std::max(hi, c[0]);
    return std::pair(lo, hi);
  };
  const BlockAtlas vanilla = buildBlockAtlas(blocks, defaultPack()),
                   overridden = buildBlockAtlas(blocks, packs);
  EXPECT_EQ(xExtent(vanilla), std::pair(14, 18));
  EXPECT_EQ(xExtent(overridden), std::pair(15, 17));
  // Meshed: the post's top in the pack's place.
  ModelWorld world(overridden);
  world.set({3, 64, 3}, "glass_pane");
  bool found = false;
  const SectionMesh mesh = world.mesh();
  const PackedVertices& v = mesh.layers[static_cast<std::size_t>(MeshLayer::Cutout)].vertices;
  for (const PackedVertex& p : v)
    found = found || (p.face() == static_cast<int>(Direction::Up) && p.x32() == 3 * 32 + 15);
  EXPECT_TRUE(found);
  const BlockShapes collision = defaultPackShapes(blocks);
  ASSERT_FALSE(collision.boxes(post).empty());
  for (const ShapeBox& b : collision.boxes(post)) {
    EXPECT_EQ(b, (ShapeBox{{7, 0, 7}, {9, 16, 9}})) << "the default pack's post (and its four no-side faces)";
  }
}

// A variant listing weighted models is picked per cell by the cell's position: the mesher's pick is
// the blockstate reader's (BlockStates::select), the same on every meshing, and the weights show.
TEST(ModelMeshPack, WeightedModelsArePickedPerCellByPosition) {
  testing::PackBuilder pack("weighted_slabs");
  pack.asset("blockstates/stone_slab.json", R"({"variants": {
      "type=bottom": [{"model": "block/stone_slab"}, {"model": "block/oak_slab", "weight": 3}],
      "type=top": {"model": "block/stone_slab_top"}, "type=double": {"model": "block/stone"}}})");
  PackStack packs = defaultPack();
  packs.push(ResourcePack::open(pack.dir()));
  const BlockRegistry& blocks = defaultBlocks();
  const BlockAtlas atlas = buildBlockAtlas(blocks, packs);
  ASSERT_EQ(atlas.modelChoices[blocks.id("stone_slab")].size(), 2u);
  // In the file's order: the stone slab, then the oak one.
  const std::vector<ModelChoice>& choices = atlas.modelChoices[blocks.id("stone_slab")];
  const std::uint16_t stone = choices[0].quads.at(0).texture, oak = choices[1].quads.at(0).texture;
  ASSERT_NE(oak, stone);
  ModelWorld world(atlas);
  for (int z = 0; z < 16; ++z)
    for (int x = 0; x < 16; ++x) world.set({x, 64, z}, "stone_slab");
  const BlockStates states = BlockStates::load(packs, "stone_slab");
  const SectionMesh first = world.mesh(), second = world.mesh();
  EXPECT_EQ(first.layers[0].vertices, second.layers[0].vertices) << "the same picks every time";
  int oaks = 0, agree = 0;
  for (const PackedVertex* q = first.layers[0].vertices.data();
       q < first.layers[0].vertices.data() + first.layers[0].vertices.size(); q += 4) {
    if (q->face() != static_cast<int>(Direction::Up)) continue;
    const int x = std::min({q[0].x32(), q[1].x32(), q[2].x32()}) / 32,
              z = std::min({q[0].z32(), q[1].z32(), q[2].z32()}) / 32;
    const std::string expected =
        states.select(blocks.stateValues(blocks.id("stone_slab")), {x, 64, z}).at(0).model;
    agree += (q->texture() == oak) == (expected == "block/oak_slab");
    oaks += q->texture() == oak;
  }
  EXPECT_EQ(agree, 256);
  EXPECT_GT(oaks, 256 * 3 / 4 - 40);
  EXPECT_LT(oaks, 256 * 3 / 4 + 40);
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
