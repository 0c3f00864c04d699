#include "mesh/block_mesh_table.h"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>

#include "core/assert.h"
#include "core/model_units.h"

namespace terrasol {
namespace {

// A model quad's extent on its cullface's side (its bounding rectangle there, 1/16), and, where
// `coverage` is given (an opaque block), the part of a side it covers: a quad lying on the side,
// facing out of it.
void describeModelQuad(ModelQuad& q, FaceCoverage* coverage) {
  if (q.cullface < 0 && q.face >= 6) return;
  const int side = q.cullface >= 0 ? q.cullface : q.face;
  const int across = side / 2;                                 // West/East: x, Down/Up: y, North/South: z
  const int a = across == 0 ? 1 : 0, b = across == 2 ? 1 : 2;  // the side's axes, in x, y, z order
  int lo[3] = {32, 32, 32}, hi[3] = {0, 0, 0};
  for (const auto& c : q.corners32)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], c[static_cast<std::size_t>(i)]);
      hi[i] = std::max(hi[i], c[static_cast<std::size_t>(i)]);
    }
  q.rect = {lo[a] / 2, lo[b] / 2, (hi[a] + 1) / 2, (hi[b] + 1) / 2};
  const int plane = side % 2 == 1 ? 32 : 0;
  q.onSide = q.face == side && lo[across] == plane && hi[across] == plane;
  if (!coverage || !q.onSide) return;
  // Only whole 1/16 cells count as covered.
  coverage->add(static_cast<Direction>(side), {(lo[a] + 1) / 2, (lo[b] + 1) / 2, hi[a] / 2, hi[b] / 2});
}

MeshLayer layerOf(RenderLayer layer) {
  switch (layer) {
    case RenderLayer::Cutout:
      return MeshLayer::Cutout;
    case RenderLayer::Translucent:
      return MeshLayer::Translucent;
    default:
      return MeshLayer::Opaque;
  }
}

// Whether a model state's quads are exactly a cube's six faces as the mesher draws cubes (each on its
// side, culled there, untinted, textured the cube's way up), and if so its faces' textures: it is
// then drawn as a cube, merged with its like (a log standing up, a double slab).
bool plainCube(const std::vector<ModelQuad>& quads, std::array<std::uint16_t, 6>& textures) {
  if (quads.size() != 6) return false;
  unsigned seen = 0;
  for (const ModelQuad& q : quads) {
    if (q.face >= 6 || q.cullface != q.face || !q.onSide || q.tinted || (seen >> q.face & 1)) return false;
    seen |= 1u << q.face;
    const FaceBasis& f = kFaceBases[q.face];
    for (std::size_t c = 0; c < 4; ++c) {
      int s = 0, r = 0;
      for (std::size_t i = 0; i < 3; ++i) {
        s += static_cast<int>(f.tangent[i]) * (q.corners32[c][i] - 16);
        r += static_cast<int>(f.up[i]) * (q.corners32[c][i] - 16);
      }
      if (std::abs(s) != 16 || std::abs(r) != 16) return false;  // not a whole side
      if (q.uvs16[c][0] != (s > 0 ? kModelUnits : 0) || q.uvs16[c][1] != (r > 0 ? 0 : kModelUnits))
        return false;
    }
    textures[q.face] = q.texture;
  }
  return true;
}

}  // namespace

void occludeByOwnShape(std::vector<ModelQuad>& quads, std::span<const ShapeBox> boxes) {
  // A point just in front of the corner, stepped 1/32 towards each of the two cells beside it (away
  // from the quad's middle, along each of its axes), is tested against the boxes' insides.
  const auto inside = [&](const std::array<int, 3>& p32) {
    return std::any_of(boxes.begin(), boxes.end(), [&](const ShapeBox& b) {
      for (std::size_t i = 0; i < 3; ++i)
        if (p32[i] <= b.from[i] * 2 || p32[i] >= b.to[i] * 2) return false;
      return true;
    });
  };
  for (ModelQuad& q : quads) {
    q.ownOcclusion = {};
    if (!q.smooth) continue;
    const FaceBasis& basis = kFaceBases[q.face];
    std::array<int, 3> middle{};  // x4
    for (const auto& c : q.corners32)
      for (std::size_t i = 0; i < 3; ++i) middle[i] += c[i];
    for (std::size_t c = 0; c < 4; ++c) {
      // Per axis of the face, +-1: away from the quad's middle.
      int away[2];
      for (int k = 0; k < 2; ++k) {
        const float* axis = k == 0 ? basis.tangent : basis.up;
        int along = 0;
        for (std::size_t i = 0; i < 3; ++i)
          along += static_cast<int>(axis[i]) * (q.corners32[c][i] * 4 - middle[i]);
        away[k] = along > 0 ? 1 : -1;
      }
      int count = 0;
      for (int k = 0; k < 2; ++k) {
        // Out along one axis, in along the other: beside the corner, not on the quad's edge.
        std::array<int, 3> p = q.corners32[c];
        for (std::size_t i = 0; i < 3; ++i) {
          p[i] += static_cast<int>(basis.normal[i]) +
                  away[k] * static_cast<int>((k == 0 ? basis.tangent : basis.up)[i]) -
                  away[1 - k] * static_cast<int>((k == 0 ? basis.up : basis.tangent)[i]);
        }
        count += inside(p) ? 1 : 0;
      }
      q.ownOcclusion[c] = static_cast<std::uint8_t>(count);
    }
  }
}

BlockMeshTable::BlockMeshTable(const BlockRegistry& blocks,
                               const std::function<std::uint16_t(BlockId, int)>& textureOf,
                               const std::function<std::vector<ModelQuad>(BlockId)>& modelQuadsOf,
                               const std::function<std::vector<ModelChoice>(BlockId)>& modelChoicesOf,
                               const std::function<BlockId(BlockId)>& sameAsOf, TintPalette tints)
    : tints_(std::move(tints)) {
  entries_.resize(blocks.size());
  waterState_ = blocks.waterState();
  const auto liquidOf = [&](BlockId state) {
    return static_cast<std::uint16_t>(1 + blocks.blockIndex(state));
  };
  std::optional<std::vector<ModelQuad>> input;  // the previous model state's quads, as given
  for (BlockId id = 0; id < blocks.size(); ++id) {
    const BlockType& type = blocks[id];
    Entry& e = entries_[id];
    e.shape = type.shape;
    e.water = blocks.holdsWater()[id] != 0 && waterState_ != kAir && type.shape != BlockShape::Liquid;
    e.liquid = type.shape == BlockShape::Liquid ? liquidOf(id) : e.water ? liquidOf(waterState_) : 0;
    e.layer = layerOf(type.layer);
    e.opaque = type.isOpaqueCube();
    // Translucent blocks and clear cubes (glass: opacity 0) hide faces against themselves; leaves do not.
    e.cullSame = type.layer == RenderLayer::Translucent || type.shape == BlockShape::Liquid ||
                 (type.shape == BlockShape::Cube && type.opacity == 0);
    e.foliage = type.shape == BlockShape::Cube && type.layer == RenderLayer::Cutout && !e.cullSame;
    e.tint = type.tint;
    if (type.shape == BlockShape::Model) {
      if (const BlockId earlier = sameAsOf ? sameAsOf(id) : id; earlier != id) {
        const bool water = e.water;
        const std::uint16_t liquid = e.liquid;
        e = entries_[earlier];
        e.water = water;
        e.liquid = liquid;
        input.reset();  // not fetched: the next state compares with nothing
        continue;
      }
      if (modelQuadsOf) e.quads = modelQuadsOf(id);
      if (modelChoicesOf) e.choices = modelChoicesOf(id);
      // A state drawn as the one before it (its waterlogged twin) takes its entry, all but its water.
      const bool asBefore = id > 0 && blocks.blockIndex(id) == blocks.blockIndex(id - 1) &&
                            e.choices.empty() && entries_[id - 1].choices.empty() && input &&
                            e.quads == *input;
      input = e.quads;
      if (asBefore) {
        const bool water = e.water;
        const std::uint16_t liquid = e.liquid;
        e = entries_[id - 1];
        e.water = water;
        e.liquid = liquid;
        continue;
      }
      FaceCoverage* coverage = e.layer == MeshLayer::Opaque ? &e.coverage : nullptr;
      for (ModelQuad& q : e.quads) describeModelQuad(q, coverage);
      for (ModelChoice& c : e.choices) {
        for (ModelQuad& q : c.quads) describeModelQuad(q, nullptr);  // coverage is the origin pick's
        TERRASOL_ASSERT(c.weight >= 1, "mesh table: a model choice of weight " + std::to_string(c.weight));
        e.weights.push_back(c.weight);  // weightedPick's every weight >= 1 keeps its pick among the choices
      }
      for (int d = 0; d < 6; ++d) e.fullSides |= e.coverage.full(static_cast<Direction>(d)) ? 1u << d : 0u;
      if (!e.choices.empty() || !plainCube(e.quads, e.texture)) continue;
      e.shape = BlockShape::Cube;
      for (int f = 0; f < 6; ++f) {
        e.material[static_cast<std::size_t>(f)] = material(e, e.texture[static_cast<std::size_t>(f)], f);
      }
      continue;
    }
    for (int f = 0; f < 6; ++f) {
      e.texture[static_cast<std::size_t>(f)] = id == kAir ? 0 : textureOf(id, f);
      e.material[static_cast<std::size_t>(f)] = material(e, e.texture[static_cast<std::size_t>(f)], f);
    }
  }
}

}  // namespace terrasol
