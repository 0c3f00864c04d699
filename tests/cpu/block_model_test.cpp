// Minecraft's block model and blockstates formats (assets/block_model.h, assets/block_states.h,
// assets/model_bake.h): parent chains, texture references, elements and their faces, variants and
// multipart conditions, weighted picks, placement rotations, and every kind of bad input named.

#include "assets/block_model.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <set>

#include "assets/block_states.h"
#include "assets/model_bake.h"
#include "assets/resource_pack.h"
#include "core/error.h"
#include "core/json_check.h"
#include "core/paths.h"
#include "support/pack_builder.h"

namespace terrasol {
namespace {

using testing::PackBuilder;

// Minecraft's own parents, as the default pack writes them.
PackBuilder vanillaParents(const std::string& name) {
  PackBuilder pack(name);
  pack.asset("models/block/block.json", R"({"ambientocclusion": true, "display": {"gui": {}}})")
      .asset("models/block/cube.json",
             R"({"parent": "block/block", "elements": [{"from": [0, 0, 0], "to": [16, 16, 16],
          "faces": {"down": {"texture": "#down", "cullface": "down"}, "up": {"texture": "#up", "cullface": "up"},
                    "north": {"texture": "#north", "cullface": "north"}, "south": {"texture": "#south", "cullface": "south"},
                    "west": {"texture": "#west", "cullface": "west"}, "east": {"texture": "#east", "cullface": "east"}}}]})")
      .asset("models/block/cube_all.json",
             R"({"parent": "block/cube", "textures": {"particle": "#all", "down": "#all",
          "up": "#all", "north": "#all", "south": "#all", "west": "#all", "east": "#all"}})")
      .asset("models/block/slab.json",
             R"({"parent": "block/block", "elements": [{"from": [0, 0, 0], "to": [16, 8, 16],
          "faces": {"down": {"uv": [0, 0, 16, 16], "texture": "#bottom", "cullface": "down"},
                    "up": {"uv": [0, 0, 16, 16], "texture": "#top"},
                    "north": {"uv": [0, 8, 16, 16], "texture": "#side", "cullface": "north"},
                    "south": {"uv": [0, 8, 16, 16], "texture": "#side", "cullface": "south"},
                    "west": {"uv": [0, 8, 16, 16], "texture": "#side", "cullface": "west"},
                    "east": {"uv": [0, 8, 16, 16], "texture": "#side", "cullface": "east"}}}]})")
      .asset("models/block/stone.json",
             R"({"parent": "minecraft:block/cube_all", "textures": {"all": "minecraft:block/stone"}})")
      .asset(
          "models/block/stone_slab.json",
          R"({"parent": "block/slab", "textures": {"bottom": "block/stone", "top": "block/stone", "side": "block/stone"}})");
  return pack;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(BlockModel, ParentChainsAndTextureReferencesResolve) {
  PackBuilder pack = vanillaParents("models_chain");
  const PackStack libraryPacks = testing::stackOf({pack.dir()});
  ModelLibrary library(libraryPacks);
  const BlockModel& stone = library.model("minecraft:block/stone");
  EXPECT_EQ(stone.name, "block/stone");
  EXPECT_TRUE(stone.ambientOcclusion);
  ASSERT_EQ(stone.elements.size(), 1u) << "elements come from block/cube, two parents up";
  for (const auto& face : stone.elements[0].faces) {
    ASSERT_TRUE(face);
    EXPECT_EQ(face->texture, "block/stone") << "#north -> #all -> minecraft:block/stone";
    EXPECT_TRUE(face->cullface);
  }
  // Default uv: the element's extent on the face, as seen from outside.
  EXPECT_EQ(stone.elements[0].faces[static_cast<int>(ModelFace::North)]->uv, glm::vec4(0, 0, 16, 16));
  const BlockModel& slab = library.model("block/stone_slab");
  EXPECT_EQ(slab.elements[0].to, glm::vec3(16, 8, 16));
  EXPECT_FALSE(slab.elements[0].faces[static_cast<int>(ModelFace::Up)]->cullface) << "a slab's top is open";
  EXPECT_TRUE(library.missingTextures().empty());
}

TEST(BlockModel, ChildrenOverrideTexturesElementsAndAmbientOcclusion) {
  PackBuilder pack = vanillaParents("models_override");
  pack.asset(
          "models/block/glowing.json",
          R"({"parent": "block/stone", "ambientocclusion": false, "textures": {"all": "block/glowstone"}})")
      .asset("models/block/post.json",
             R"({"parent": "block/stone", "elements": [{"from": [6, 0, 6], "to": [10, 16, 10],
          "shade": false, "faces": {"up": {"texture": "#all", "tintindex": 0, "rotation": 90}}}]})");
  const PackStack libraryPacks = testing::stackOf({pack.dir()});
  ModelLibrary library(libraryPacks);
  const BlockModel& glowing = library.model("block/glowing");
  EXPECT_FALSE(glowing.ambientOcclusion);
  EXPECT_EQ(glowing.elements[0].faces[0]->texture, "block/glowstone");
  const BlockModel& post = library.model("block/post");
  ASSERT_EQ(post.elements.size(), 1u);
  const ModelElement& e = post.elements[0];
  EXPECT_FALSE(e.shade);
  EXPECT_FALSE(e.faces[static_cast<int>(ModelFace::North)]) << "only the faces it lists";
  const ElementFace& up = *e.faces[static_cast<int>(ModelFace::Up)];
  EXPECT_EQ(up.texture, "block/stone");
  EXPECT_EQ(up.tintIndex, 0);
  EXPECT_EQ(up.rotation, 90);
  EXPECT_EQ(up.uv, glm::vec4(6, 6, 10, 10));
}

TEST(BlockModel, AHigherPackOverridesAModel) {
  PackBuilder base = vanillaParents("models_base");
  PackBuilder thin("models_thin");
  thin.asset("models/block/slab.json",
             R"({"parent": "block/block", "elements": [{"from": [0, 0, 0], "to": [16, 2, 16],
      "faces": {"up": {"texture": "#top"}}}]})");
  const PackStack libraryPacks = testing::stackOf({base.dir(), thin.dir()});
  ModelLibrary library(libraryPacks);
  EXPECT_EQ(library.model("block/stone_slab").elements[0].to.y, 2.0f);
  const PackStack alonePacks = testing::stackOf({base.dir()});
  ModelLibrary alone(alonePacks);
  EXPECT_EQ(alone.model("block/stone_slab").elements[0].to.y, 8.0f);
}

TEST(BlockModel, AnUndefinedTextureIsMissingWithOneWarning) {
  PackBuilder pack = vanillaParents("models_missing");
  pack.asset("models/block/half.json", R"({"parent": "block/cube_all"})")
      .asset("models/block/loop.json",
             R"({"parent": "block/cube_all", "textures": {"all": "#other", "other": "#all"}})");
  const PackStack libraryPacks = testing::stackOf({pack.dir()});
  ModelLibrary library(libraryPacks);
  for (const auto& face : library.model("block/half").elements[0].faces)
    EXPECT_EQ(face->texture, kMissingTexture);
  for (const auto& face : library.model("block/loop").elements[0].faces)
    EXPECT_EQ(face->texture, kMissingTexture);
  // Each model's references once (six faces each), however often it is asked for.
  EXPECT_EQ(library.missingTextures().size(), 12u);
  library.model("block/half");
  EXPECT_EQ(library.missingTextures().size(), 12u);
}

TEST(BlockModel, BadModelsNameTheFileTheKeyOrTheChain) {
  PackBuilder pack = vanillaParents("models_bad");
  pack.asset("models/block/syntax.json", "{\"parent\": \"block/cube\",\n  \"textures\": {]}")
      .asset("models/block/orphan.json", R"({"parent": "block/nowhere"})")
      .asset("models/block/grandchild.json", R"({"parent": "block/orphan"})")
      .asset("models/block/a.json", R"({"parent": "block/b"})")
      .asset("models/block/b.json", R"({"parent": "block/a"})")
      .asset("models/block/far.json", R"({"elements": [{"from": [0, 0, 0], "to": [16, 40, 16]}]})")
      .asset("models/block/inside_out.json", R"({"elements": [{"from": [8, 0, 0], "to": [4, 16, 16]}]})")
      .asset("models/block/angle.json", R"({"elements": [{"from": [0, 0, 0], "to": [16, 16, 16],
          "rotation": {"origin": [8, 8, 8], "axis": "y", "angle": 30}}]})")
      .asset("models/block/axis.json", R"({"elements": [{"from": [0, 0, 0], "to": [16, 16, 16],
          "rotation": {"origin": [8, 8, 8], "axis": "w", "angle": 45}}]})")
      .asset("models/block/face.json", R"({"elements": [{"from": [0, 0, 0], "to": [16, 16, 16],
          "faces": {"top": {"texture": "#all"}}}]})")
      .asset("models/block/facerot.json", R"({"elements": [{"from": [0, 0, 0], "to": [16, 16, 16],
          "faces": {"up": {"texture": "#all", "rotation": 45}}}]})")
      .asset("models/block/notexture.json", R"({"elements": [{"from": [0, 0, 0], "to": [16, 16, 16],
          "faces": {"up": {"uv": [0, 0, 16]}}}]})")
      .asset("models/block/array.json", "[1, 2]");
  const PackStack libraryPacks = testing::stackOf({pack.dir()});
  ModelLibrary library(libraryPacks);
  const auto error = [&](const std::string& name) { return errorOf([&] { library.model(name); }); };
  EXPECT_TRUE(contains(error("block/syntax"), "syntax.json:2:")) << error("block/syntax");
  EXPECT_TRUE(contains(error("block/grandchild"), "block/grandchild -> block/orphan -> block/nowhere"))
      << error("block/grandchild");
  EXPECT_TRUE(contains(error("block/grandchild"), "no pack has the model block/nowhere"));
  EXPECT_TRUE(contains(error("block/a"), "parent cycle: block/a -> block/b -> block/a")) << error("block/a");
  EXPECT_TRUE(contains(error("block/far"), "far.json: elements[0].to[1]:")) << error("block/far");
  EXPECT_TRUE(contains(error("block/inside_out"), "elements[0]: \"from\" must not exceed"))
      << error("block/inside_out");
  EXPECT_TRUE(
      contains(error("block/angle"), "elements[0].rotation.angle: expected -45, -22.5, 0, 22.5 or 45"))
      << error("block/angle");
  EXPECT_TRUE(contains(error("block/axis"), "elements[0].rotation.axis:")) << error("block/axis");
  EXPECT_TRUE(contains(error("block/face"), "elements[0].faces.top:")) << error("block/face");
  EXPECT_TRUE(contains(error("block/facerot"), "faces.up.rotation: expected 0, 90, 180 or 270"))
      << error("block/facerot");
  EXPECT_TRUE(contains(error("block/notexture"), "faces.up.uv: expected an array of 4"))
      << error("block/notexture");
  EXPECT_TRUE(contains(error("block/array"), "array.json: expected a JSON object")) << error("block/array");
  EXPECT_TRUE(contains(error("block/absent"), "no pack has the model block/absent")) << error("block/absent");
}

BlockStates statesOf(const std::string& text) {
  return BlockStates::parse(json_check::parseJson(text, "test.json"), "test.json");
}

TEST(BlockStates, VariantsPickTheStateThatMatches) {
  const BlockStates stairs = statesOf(R"({"variants": {
      "facing=east,half=bottom": {"model": "minecraft:block/oak_stairs"},
      "facing=north,half=bottom": {"model": "block/oak_stairs", "y": 270, "uvlock": true},
      "facing=east,half=top": {"model": "block/oak_stairs", "x": 180}}})");
  const std::vector<ModelPlacement> north =
      stairs.select({{"facing", "north"}, {"half", "bottom"}, {"shape", "straight"}}, {});
  ASSERT_EQ(north.size(), 1u);
  EXPECT_EQ(north[0], (ModelPlacement{"block/oak_stairs", 0, 270, true, 1}));
  EXPECT_EQ(stairs.select({{"facing", "east"}, {"half", "top"}}, {})[0].x, 180);
  EXPECT_TRUE(stairs.select({{"facing", "west"}, {"half", "top"}}, {}).empty())
      << "no variant: nothing drawn";
  const BlockStates plain = statesOf(R"({"variants": {"": {"model": "block/stone"}}})");
  EXPECT_EQ(plain.select({}, {})[0].model, "block/stone");
  EXPECT_EQ(plain.select({{"anything", "1"}}, {})[0].model, "block/stone");
  EXPECT_EQ(plain.models(), std::vector<std::string>{"block/stone"});
}

// The properties a blockstates file names, in variant keys and in multipart conditions at any depth:
// states alike in these pick the same models (the atlas picks once for them).
TEST(BlockStates, NameTheirPropertiesSoTwinsPickOnce) {
  EXPECT_EQ(statesOf(R"({"variants": {"facing=east,half=bottom": {"model": "block/a"},
                                      "facing=north,half=top": {"model": "block/a"}}})")
                .properties(),
            (std::set<std::string>{"facing", "half"}));
  EXPECT_EQ(statesOf(R"({"multipart": [{"apply": {"model": "block/post"}},
                                       {"when": {"north": "true"}, "apply": {"model": "block/side"}},
                                       {"when": {"OR": [{"up": "true"}, {"AND": [{"east": "low"}]}]},
                                        "apply": {"model": "block/side"}}]})")
                .properties(),
            (std::set<std::string>{"north", "up", "east"}));
  EXPECT_TRUE(statesOf(R"({"variants": {"": {"model": "block/a"}}})").properties().empty());
}

TEST(BlockStates, WeightedPicksAreStableByPositionAndFollowTheWeights) {
  const BlockStates grass = statesOf(R"({"variants": {"": [
      {"model": "block/a"}, {"model": "block/b", "y": 90}, {"model": "block/c", "weight": 2}]}})");
  int counts[3] = {0, 0, 0};
  for (int x = 0; x < 40; ++x)
    for (int z = 0; z < 40; ++z) {
      const std::string model = grass.select({}, {x, 64, z})[0].model;
      EXPECT_EQ(model, grass.select({}, {x, 64, z})[0].model) << "the same block, the same pick";
      ++counts[model.back() - 'a'];
    }
  // 1600 picks at 1 : 1 : 2.
  EXPECT_NEAR(counts[0], 400, 80);
  EXPECT_NEAR(counts[1], 400, 80);
  EXPECT_NEAR(counts[2], 800, 100);
}

TEST(BlockStates, MultipartAppliesEveryPartWhoseConditionHolds) {
  const BlockStates fence = statesOf(R"({"multipart": [
      {"apply": {"model": "block/fence_post"}},
      {"when": {"north": "true"}, "apply": {"model": "block/fence_side", "uvlock": true}},
      {"when": {"east": true}, "apply": {"model": "block/fence_side", "y": 90, "uvlock": true}},
      {"when": {"OR": [{"north": "true", "east": "true"}, {"south": "low|tall"}]}, "apply": {"model": "block/either"}},
      {"when": {"AND": [{"north": "true"}, {"east": "true"}]}, "apply": {"model": "block/corner"}}]})");
  const auto models = [&](const StateValues& s) {
    std::vector<std::string> out;
    for (const ModelPlacement& p : fence.select(s, {})) {
      out.push_back(p.y ? json_check::join({p.model, "@", std::to_string(p.y)}) : p.model);
    }
    return out;
  };
  EXPECT_EQ(models({{"north", "false"}, {"east", "false"}, {"south", "none"}}),
            std::vector<std::string>{"block/fence_post"});
  EXPECT_EQ(models({{"north", "true"}, {"east", "false"}, {"south", "none"}}),
            (std::vector<std::string>{"block/fence_post", "block/fence_side"}));
  EXPECT_EQ(models({{"north", "true"}, {"east", "true"}, {"south", "none"}}),
            (std::vector<std::string>{"block/fence_post", "block/fence_side", "block/fence_side@90",
                                      "block/either", "block/corner"}));
  EXPECT_EQ(models({{"north", "false"}, {"east", "false"}, {"south", "tall"}}),
            (std::vector<std::string>{"block/fence_post", "block/either"}));
  EXPECT_EQ(fence.models().size(), 4u);
}

TEST(BlockStates, BadBlockstatesNameTheKey) {
  const auto error = [](const std::string& text) { return errorOf([&] { statesOf(text); }); };
  EXPECT_TRUE(contains(error(R"({})"), "test.json: expected \"variants\" or \"multipart\"")) << error("{}");
  EXPECT_TRUE(contains(error(R"({"variants": {"facing": {"model": "a"}}})"),
                       "variants.facing: expected property=value"));
  EXPECT_TRUE(contains(error(R"({"variants": {"": {"model": "a", "y": 45}}})"),
                       "variants..y: expected 0, 90, 180 or 270"))
      << error(R"({"variants": {"": {"model": "a", "y": 45}}})");
  EXPECT_TRUE(contains(error(R"({"variants": {"": {"x": 90}}})"), "needs a \"model\""));
  EXPECT_TRUE(contains(error(R"({"variants": {"": []}})"), "a model or a non-empty list"));
  EXPECT_TRUE(contains(error(R"({"variants": {"": {"model": "a", "weight": 0}}})"), "weight"));
  EXPECT_TRUE(contains(error(R"({"multipart": [{"when": {"north": "true"}}]})"),
                       "multipart[0]: a part needs \"apply\""));
  EXPECT_TRUE(contains(error(R"({"multipart": [{"when": {"OR": {"a": "b"}}, "apply": {"model": "a"}}]})"),
                       "multipart[0].when.OR: expected an array"));
  EXPECT_TRUE(contains(error(R"({"multipart": [{"when": {"north": [1]}, "apply": {"model": "a"}}]})"),
                       "multipart[0].when.north: expected a string"));
}

// The corners of every baked quad wind counter-clockwise seen from the front.
void expectFrontFacing(const std::vector<BakedQuad>& quads) {
  for (const BakedQuad& q : quads) {
    const glm::vec3 n = glm::cross(q.corners[1] - q.corners[0], q.corners[2] - q.corners[0]);
    EXPECT_GT(glm::dot(n, q.normal), 0.0f) << kModelFaceNames[static_cast<int>(q.face)];
  }
}

TEST(ModelBake, ACubeIsSixFacesOfTheUnitBox) {
  PackBuilder pack = vanillaParents("bake_cube");
  const PackStack libraryPacks = testing::stackOf({pack.dir()});
  ModelLibrary library(libraryPacks);
  const std::vector<BakedQuad> quads = bakeModel(library.model("block/stone"), {});
  ASSERT_EQ(quads.size(), 6u);
  expectFrontFacing(quads);
  for (const BakedQuad& q : quads) {
    EXPECT_EQ(q.cullface, q.face);
    EXPECT_EQ(q.normal, faceNormal(q.face));
    for (const glm::vec3 c : q.corners) {
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(c, glm::vec3(0.0f))) &&
                  glm::all(glm::lessThanEqual(c, glm::vec3(1.0f))));
    }
    EXPECT_EQ(q.uvs[0], glm::vec2(0, 0));
    EXPECT_EQ(q.uvs[2], glm::vec2(1, 1));
  }
  // The north face (z = 0) seen from the north: the texture's top left at the top east corner.
  const BakedQuad& north = quads[static_cast<int>(ModelFace::North)];
  EXPECT_EQ(north.corners[0], glm::vec3(1, 1, 0));
  EXPECT_EQ(north.corners[2], glm::vec3(0, 0, 0));
}

TEST(ModelBake, PlacementTurnsGeometryCullfacesAndLocksUvs) {
  PackBuilder pack = vanillaParents("bake_turn");
  pack.asset("models/block/front.json",
             R"({"parent": "block/block", "elements": [{"from": [0, 0, 0], "to": [16, 16, 4],
      "faces": {"north": {"texture": "#f", "cullface": "north"}, "up": {"texture": "#f", "cullface": "up"}}}],
      "textures": {"f": "block/furnace_front"}})");
  const PackStack libraryPacks = testing::stackOf({pack.dir()});
  ModelLibrary library(libraryPacks);
  const BlockModel& front = library.model("block/front");
  // y = 90 takes north to east (Minecraft turns clockwise seen from above).
  const std::vector<BakedQuad> east = bakeModel(front, {"block/front", 0, 90, false, 1});
  expectFrontFacing(east);
  EXPECT_EQ(east[1].face, ModelFace::East);
  EXPECT_EQ(east[1].cullface, ModelFace::East);
  EXPECT_NEAR(east[1].corners[0].x, 1.0f, 1e-6f) << "the slab of the front now lies along x = 12..16";
  EXPECT_EQ(east[0].face, ModelFace::Up) << "up stays up";
  // x = 90 takes up to north, north to down.
  const std::vector<BakedQuad> down = bakeModel(front, {"block/front", 90, 0, false, 1});
  expectFrontFacing(down);
  EXPECT_EQ(down[0].face, ModelFace::North);
  EXPECT_EQ(down[1].face, ModelFace::Down);
  EXPECT_EQ(down[1].cullface, ModelFace::Down);
  // A half slab's top turned by y = 90: without uvlock its uvs turn with it, with uvlock they are
  // where the world puts them (u along x, v along z on an up face).
  const BlockModel& slab = library.model("block/stone_slab");
  const std::vector<BakedQuad> turned = bakeModel(slab, {"block/stone_slab", 0, 90, false, 1});
  const std::vector<BakedQuad> locked = bakeModel(slab, {"block/stone_slab", 0, 90, true, 1});
  const BakedQuad& top = turned[1];
  const BakedQuad& lockedTop = locked[1];
  ASSERT_EQ(lockedTop.face, ModelFace::Up);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(top.corners[i], lockedTop.corners[i]);
    EXPECT_NEAR(lockedTop.uvs[i].x, lockedTop.corners[i].x, 1e-6f);
    EXPECT_NEAR(lockedTop.uvs[i].y, lockedTop.corners[i].z, 1e-6f);
  }
  EXPECT_NE(top.uvs[0], lockedTop.uvs[0]);
}

TEST(ModelBake, FaceRotationAndTurnedElements) {
  PackBuilder pack = vanillaParents("bake_rot");
  pack.asset("models/block/cross.json", R"({"ambientocclusion": false, "textures": {"cross": "block/poppy"},
      "elements": [{"from": [0.8, 0, 8], "to": [15.2, 16, 8], "shade": false,
                    "rotation": {"origin": [8, 8, 8], "axis": "y", "angle": 45, "rescale": true},
                    "faces": {"north": {"uv": [0, 0, 16, 16], "texture": "#cross"}}}]})")
      .asset("models/block/spun.json", R"({"textures": {"t": "block/stone"}, "elements": [{"from": [0, 0, 0],
          "to": [16, 16, 16], "faces": {"up": {"texture": "#t", "rotation": 90}}}]})");
  const PackStack libraryPacks = testing::stackOf({pack.dir()});
  ModelLibrary library(libraryPacks);
  const std::vector<BakedQuad> cross = bakeModel(library.model("block/cross"), {});
  ASSERT_EQ(cross.size(), 1u);
  expectFrontFacing(cross);
  EXPECT_FALSE(cross[0].ambientOcclusion);
  EXPECT_FALSE(cross[0].shade);
  EXPECT_NEAR(std::abs(cross[0].normal.x), std::sqrt(0.5f), 1e-5f) << "turned 45 degrees";
  // Rescaled: the 14.4-wide plane spans the diagonal, corner to corner (14.4 * sqrt 2 / 16 = 1.27).
  EXPECT_NEAR(glm::distance(cross[0].corners[0], cross[0].corners[3]), 14.4f * std::sqrt(2.0f) / 16.0f,
              1e-4f);
  const std::vector<BakedQuad> spun = bakeModel(library.model("block/spun"), {});
  // Turned a quarter clockwise: the corner that showed the texture's top left shows its bottom left.
  EXPECT_EQ(spun[0].uvs[0], glm::vec2(0, 1));
  EXPECT_EQ(spun[0].uvs[3], glm::vec2(0, 0));
}

// The default pack's parent models (written for Terrasol in Minecraft's format): each loads and bakes
// with the textures a child gives it, into the faces its shape has, each inside its cell but for the
// wall torch leaning out of it.
TEST(BlockModel, TheDefaultPackShipsTheParentsShapedBlocksNeed) {
  PackBuilder children("default_children");
  const std::map<std::string, std::pair<std::string, std::size_t>> kChildren = {
      // child: {parent, faces}
      {"t_cube", {"cube_all", 6}},
      {"t_column", {"cube_column", 6}},
      {"t_bottom_top", {"cube_bottom_top", 6}},
      {"t_orientable", {"orientable", 6}},
      {"t_cross", {"cross", 4}},
      {"t_slab", {"slab", 6}},
      {"t_slab_top", {"slab_top", 6}},
      {"t_stairs", {"stairs", 11}},
      {"t_inner_stairs", {"inner_stairs", 15}},
      {"t_outer_stairs", {"outer_stairs", 11}},
      {"t_fence_post", {"fence_post", 6}},
      {"t_fence_side", {"fence_side", 10}},
      {"t_pane_post", {"template_glass_pane_post", 2}},
      {"t_pane_side", {"template_glass_pane_side", 5}},
      {"t_pane_noside", {"template_glass_pane_noside", 1}},
      {"t_wall_post", {"template_wall_post", 6}},
      {"t_wall_side", {"template_wall_side", 5}},
      {"t_wall_tall", {"template_wall_side_tall", 5}},
      {"t_door_bl", {"door_bottom_left", 6}},
      {"t_door_br", {"door_bottom_right", 6}},
      {"t_door_tl", {"door_top_left", 6}},
      {"t_door_tr", {"door_top_right", 6}},
      {"t_trap_bottom", {"template_trapdoor_bottom", 6}},
      {"t_trap_top", {"template_trapdoor_top", 6}},
      {"t_trap_open", {"template_trapdoor_open", 6}},
      {"t_ladder", {"ladder", 2}},
      {"t_carpet", {"carpet", 6}},
      {"t_snow2", {"snow_height2", 6}},
      {"t_snow14", {"snow_height14", 6}},
      {"t_farmland", {"template_farmland", 6}},
      {"t_torch", {"template_torch", 6}},
      {"t_wall_torch", {"template_torch_wall", 6}}};
  const std::string everyReference =
      R"("textures": {"all": "block/stone", "end": "block/stone", "side": "block/stone",
      "bottom": "block/stone", "top": "block/stone", "front": "block/stone", "cross": "block/poppy",
      "texture": "block/stone", "pane": "block/glass", "edge": "block/glass", "wall": "block/stone",
      "wool": "block/stone", "dirt": "block/dirt", "torch": "block/torch"})";
  for (const auto& [child, parent] : kChildren) {
    children.asset("models/block/" + child + ".json",
                   R"({"parent": "block/)" + parent.first + R"(", )" + everyReference + "}");
  }
  const PackStack packs = testing::stackOf({resourcePackDir() / "default", children.dir()});
  ModelLibrary library(packs);
  for (const auto& [child, parent] : kChildren) {
    const std::vector<BakedQuad> quads = bakeModel(library.model("block/" + child), {});
    EXPECT_EQ(quads.size(), parent.second) << parent.first;
    expectFrontFacing(quads);
    for (const BakedQuad& q : quads) {
      EXPECT_NE(q.texture, kMissingTexture) << parent.first;
      if (parent.first == "template_torch_wall") continue;
      for (const glm::vec3 c : q.corners) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(c, glm::vec3(-1e-5f))) &&
                    glm::all(glm::lessThanEqual(c, glm::vec3(1.0f + 1e-5f))))
            << parent.first << " " << c.x << " " << c.y << " " << c.z;
      }
    }
  }
  EXPECT_TRUE(library.missingTextures().empty());
}

TEST(BlockStates, PositionSeedIsMinecrafts) {
  // Mth.getSeed(0, 0, 0) is 0; neighbours differ.
  EXPECT_EQ(positionSeed({0, 0, 0}), 0);
  EXPECT_NE(positionSeed({1, 64, 0}), positionSeed({0, 64, 1}));
  EXPECT_EQ(positionSeed({-5, 70, 12}), positionSeed({-5, 70, 12}));
}

}  // namespace
}  // namespace terrasol
