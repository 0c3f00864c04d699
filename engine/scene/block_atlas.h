#pragma once
// The atlas for a block registry: every face texture the blocks name and every texture their models
// use (a model block's blockstates and models, read through the pack stack), and the atlas texture id
// of each block face and model quad (what the mesher writes into vertices).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "assets/atlas.h"
#include "assets/model_bake.h"
#include "assets/resource_pack.h"
#include "core/cloud_layer.h"
#include "core/enum_names.h"
#include "core/tint_palette.h"
#include "mesh/mesher.h"
#include "world/block_registry.h"
#include "world/block_shapes.h"

namespace terrasol {

struct BlockAtlas {
  Atlas atlas;
  std::vector<std::array<std::uint16_t, 6>> faceTextures;  // per block id, Direction order
  std::vector<std::vector<ModelQuad>> modelQuads;          // per state of a model block
  std::vector<std::vector<ModelChoice>> modelChoices;      // per state picking among weighted models
  std::vector<PackProblem> problems;                       // never fatal: missing textures show as such
  // Minecraft's blocks drawn as the missing cube because no pack describes them (sorted by id).
  std::vector<std::string> placeholders;
  // Per state: the earlier state of its block drawn just as it (BlockModelBake::sameAs), or itself.
  std::vector<BlockId> sameAs;
  TintPalette tints;  // the packs' colormaps
  CloudMap clouds;    // and cloud layer (drawn with the blocks, read from the same stack)
  std::uint16_t textureOf(BlockId id, int face) const {
    return faceTextures[id][static_cast<std::size_t>(face)];
  }
};

// Every model block's states baked from a pack stack: what the atlas and the shapes are both made
// from, so a caller wanting both from one stack bakes once. Per state: its models' quads and boxes as
// picked at the origin, and the weighted models it picks among by position; a state drawn just as an
// earlier one of its block (a waterlogged twin, a sign's other rotation on the same model, a
// placeholder's every state) is that state's (`sameAs`), its own lists empty.
struct BakedChoice {
  int weight = 1;
  std::vector<BakedQuad> quads;
  std::vector<ShapeBox> boxes;
};
struct BlockModelBake {
  std::vector<std::vector<BakedQuad>> quads;
  std::vector<std::vector<ShapeBox>> boxes;
  std::vector<std::vector<BakedChoice>> choices;
  std::vector<BlockId> sameAs;
  std::vector<PackProblem> problems;
  std::vector<std::string> placeholders;  // as BlockAtlas::placeholders
};
BlockModelBake bakeBlockModels(const BlockRegistry& blocks, const PackStack& packs);

// The textures the atlas loads, each as its list of candidate names, sorted: every face texture the
// blocks name and every texture their baked models use.
std::vector<std::vector<std::string>> atlasTextureNames(const BlockRegistry& blocks,
                                                        const BlockModelBake& baked);

// A model block whose blockstates or models are missing or malformed is drawn as a cube of the
// missing texture, with the reason among the problems (as Minecraft does).
BlockAtlas buildBlockAtlas(const BlockRegistry& blocks, const PackStack& packs);
BlockAtlas buildBlockAtlas(const BlockRegistry& blocks, const PackStack& packs, const BlockModelBake& baked);

// The states' collision and targeting boxes: cubes whole, model blocks their models' elements (read
// from `packs`: give it the default pack alone, as a resource pack does not change how blocks collide).
BlockShapes blockShapesOf(const BlockRegistry& blocks, const PackStack& packs);
BlockShapes blockShapesOf(const BlockRegistry& blocks, const BlockModelBake& baked);
// Whether `packs` is the default pack alone: its bake then gives the shapes too.
bool isDefaultPackAlone(const PackStack& packs);
// The same from resourcepacks/default alone: what the game collides with.
BlockShapes defaultPackShapes(const BlockRegistry& blocks);

// How a block is drawn with a pack stack, for listings: by the stack's models (Model), by its own
// blocks.json shape from its textures (Derived: a cube, a cross, a torch, a liquid), nothing by design
// (air, barrier, light, structure_void), or as the placeholder where no pack describes it.
enum class BlockDrawing : std::uint8_t { Model, Derived, Nothing, Placeholder };
inline constexpr EnumNames<BlockDrawing, 4> kBlockDrawings{{"model", "derived", "nothing", "placeholder"}};
// Per block (BlockRegistry::block's index).
std::vector<BlockDrawing> blockDrawings(const BlockRegistry& blocks, const BlockAtlas& atlas);

// The mesher's table for `blocks` drawn with `atlas`'s textures and model quads.
BlockMeshTable meshTableOf(const BlockRegistry& blocks, const BlockAtlas& atlas);

}  // namespace terrasol
