#pragma once
// What the mesher knows of each block state, looked up once per state: its shape, layer and culling
// rules, its cube faces' textures, and a model block's quads and the parts of its cell's sides they
// cover.

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "core/tint_palette.h"
#include "mesh/mesh_data.h"
#include "world/block_registry.h"
#include "world/face_coverage.h"

namespace terrasol {

// One quad of a model block's state, baked (assets/model_bake.h) and given its atlas texture.
struct ModelQuad {
  std::array<std::array<int, 3>, 4> corners32;  // within the cell, 1/32 block, 0..32, counter-clockwise
  std::array<std::array<int, 2>, 4> uvs16;      // 1/16 of the texture
  std::uint16_t texture = 0;
  std::uint8_t face = 3;      // kFaceBases' index nearest its normal: 0..5 a Direction, 6..9 a diagonal
  std::int8_t cullface = -1;  // Direction: left out where the neighbour on that side covers `rect`; -1 never
  bool tinted = false;        // takes the block's tint (its model's tintindex)
  bool smooth = false;        // smooth light and ambient occlusion (an axis-aligned face of a model with AO)
  // Per corner, how many of the two cells beside it, seen along the face, the block's own shape
  // fills (0..2): a stair's step darkens where it meets the riser (occludeByOwnShape).
  std::array<std::uint8_t, 4> ownOcclusion{};
  // Filled in by BlockMeshTable: its extent on the cullface's side (1/16), and whether it lies on its
  // cell's side (lit from the cell beyond, as vanilla lights a face flush with the block's bounds).
  SideRect rect;
  bool onSide = false;
  friend bool operator==(const ModelQuad&, const ModelQuad&) = default;
};

// One of the weighted models a state picks among by position (core/position_random.h), as quads.
struct ModelChoice {
  int weight = 1;
  std::vector<ModelQuad> quads;
};

// Fills each quad's ownOcclusion from the boxes (1/16) of the models the state is drawn with.
void occludeByOwnShape(std::vector<ModelQuad>& quads, std::span<const ShapeBox> boxes);

// Per-block facts the mesher needs, looked up once per block id.
class BlockMeshTable {
 public:
  // `textureOf(block, face)` is the texture id for a face (Direction order; cross plants and torches
  // use face 0), e.g. the index of its texture in the atlas; `modelQuadsOf(state)` a model block's
  // quads.
  // `modelChoicesOf(state)`: the weighted models a state picks among per cell, when it does (its quads
  // are then the origin's pick, for coverage).
  // `sameAsOf(state)`: an earlier state of its block drawn just as it (its entry is copied, all but its
  // water), or the state itself. `tints`: the pack's colours for tinted vertices.
  BlockMeshTable(const BlockRegistry& blocks, const std::function<std::uint16_t(BlockId, int)>& textureOf,
                 const std::function<std::vector<ModelQuad>(BlockId)>& modelQuadsOf = {},
                 const std::function<std::vector<ModelChoice>(BlockId)>& modelChoicesOf = {},
                 const std::function<BlockId(BlockId)>& sameAsOf = {}, TintPalette tints = {});

  struct Entry {
    BlockShape shape;
    MeshLayer layer;
    bool opaque;    // an opaque cube: hides neighbours' faces, darkens corners
    bool cullSame;  // hides faces against the same block
    bool foliage;   // a see-through cube that keeps its faces against others of its kind: leaves
    bool water;     // the cell holds water besides the block (waterlogged): drawn as waterState()'s
    // The liquid a cell of it holds, 1 + the liquid block's index (water's for a waterlogged one), 0
    // for none: a liquid's faces are hidden against the same liquid, whatever its level.
    std::uint16_t liquid;
    Tint tint;
    std::array<std::uint16_t, 6> texture;
    std::array<std::uint32_t, 6> material;  // PackedVertex::material of each cube face
    std::vector<ModelQuad> quads;           // shape Model
    std::vector<ModelChoice> choices;       // picked per cell by position, when not empty
    std::vector<int> weights;               // the choices'
    // What an opaque model block covers of its cell's sides (from its quads lying on them), and the
    // sides it covers whole, as bits by Direction: neighbours' faces there are hidden.
    FaceCoverage coverage;
    std::uint8_t fullSides = 0;
  };
  const Entry& operator[](BlockId id) const { return entries_[id]; }
  // The water drawn in waterlogged cells (BlockRegistry::waterState).
  BlockId waterState() const { return waterState_; }
  const TintPalette& tints() const { return tints_; }

  // PackedVertex::material for a texture on face `face` (kFaceBases' index) of a block drawn as `e`.
  static std::uint32_t material(const Entry& e, int texture, int face) {
    // Grass blocks tint only their top; plants, leaves and water tint everything.
    const bool untinted =
        e.tint == Tint::Grass && e.shape == BlockShape::Cube && face != static_cast<int>(Direction::Up);
    return PackedVertex::packMaterial(texture, face, untinted ? 0 : static_cast<int>(e.tint));
  }

 private:
  std::vector<Entry> entries_;
  BlockId waterState_ = kAir;
  TintPalette tints_;
};

}  // namespace terrasol
