#include "mesh/mesher.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <utility>

#include "core/model_units.h"
#include "core/position_random.h"
#include "mesh/face_merge.h"
#include "mesh/mesh_tables.h"
#include "mesh/model_light.h"
#include "mesh/vertex_tints.h"
#include "world/liquid.h"

namespace terrasol {
namespace {

using namespace mesh_tables;

// A row's cells along x, one bit each, in a row mask (bit x + 1) shifted down by one.
constexpr std::uint32_t kRowCells = (1u << kChunkSize) - 1;

class Mesher {
 public:
  Mesher(const SectionSnapshot& s, const BlockMeshTable& table) : s_(s), table_(table) {
    mesh_.pos = s.pos;
    // Sections near each other look alike: room for what the last one needed avoids regrowing.
    for (int l = 0; l < kMeshLayers; ++l) {
      const auto i = static_cast<std::size_t>(l);
      writers_[i].out = &mesh_.layers[i].vertices;
      writers_[i].out->resize(lastSize_[i] * 5 / 4 + 64);
    }
  }

  SectionMesh run() {
    buildOpaqueRows();
    for (int y = 0; y < kChunkSize; ++y)
      for (int z = 0; z < kChunkSize; ++z) {
        // Opaque cubes by bit arithmetic on the row masks: a face shows where the neighbour is not opaque.
        const std::uint32_t self = row(y, z) >> 1 & kRowCells;
        const std::uint32_t visible[6] = {
            self & ~(row(y, z) & kRowCells),          self & ~(row(y, z) >> 2 & kRowCells),
            self & ~(row(y - 1, z) >> 1 & kRowCells), self & ~(row(y + 1, z) >> 1 & kRowCells),
            self & ~(row(y, z - 1) >> 1 & kRowCells), self & ~(row(y, z + 1) >> 1 & kRowCells),
        };
        std::uint32_t models = 0;  // opaque model blocks not drawn as cubes (a log on its side)
        forEachDirection([&](auto d) {
          for (std::uint32_t bits = visible[d]; bits != 0; bits &= bits - 1) {
            const int x = std::countr_zero(bits);
            const int here = SectionSnapshot::index(x, y, z);
            if (coveredFrom<d>(here + kNeighbour[d])) continue;
            const BlockMeshTable::Entry& e = table_[s_.blocks[static_cast<std::size_t>(here)]];
            if (e.shape == BlockShape::Model) [[unlikely]] {
              models |= 1u << x;
              continue;
            }
            face<d>(x, y, z, e, 32, here + kNeighbour[d]);
          }
        });
        for (; models != 0; models &= models - 1) {
          const int x = std::countr_zero(models);
          model(x, y, z, table_[block(x, y, z)]);
        }
        // Everything else that is not air, cell by cell.
        for (std::uint32_t bits = ~self & kRowCells; bits != 0; bits &= bits - 1) {
          const int x = std::countr_zero(bits);
          const BlockId id = block(x, y, z);
          if (id == kAir) continue;
          const auto& e = table_[id];
          switch (e.shape) {
            case BlockShape::Cube:
            case BlockShape::Liquid:
              cube(x, y, z, id, e);
              break;
            case BlockShape::Cross:
              cross(x, y, z, e);
              break;
            case BlockShape::Torch:
              torch(x, y, z, e);
              break;
            case BlockShape::Model:
              model(x, y, z, e);
              break;
            case BlockShape::None:
              break;
          }
          if (e.water) [[unlikely]]
            cube(x, y, z, table_.waterState(), table_[table_.waterState()]);
        }
      }
    for (int l = 0; l < kMeshLayers; ++l) {
      const auto i = static_cast<std::size_t>(l);
      writers_[i].out->resize(writers_[i].used);
      lastSize_[i] = writers_[i].used;
    }
    return std::move(mesh_);
  }

 private:
  // Row masks of opaque cells, bit x + 1 for x in -1..16, for y and z in -1..16.
  void buildOpaqueRows() {
    static_assert(kChunkSize == 16, "a row is two groups of eight cells and the halo's two");
    // Eight 0/1 bytes to eight bits at once: the multiply gathers each byte's bit into the top byte.
    const auto bits8 = [](const std::uint8_t* bytes) {
      std::uint64_t word;
      std::memcpy(&word, bytes, 8);
      return static_cast<std::uint32_t>((word * 0x0102040810204080ull) >> 56);
    };
    for (int y = -1; y <= kChunkSize; ++y)
      for (int z = -1; z <= kChunkSize; ++z) {
        const std::uint8_t* cells = &s_.opaque[static_cast<std::size_t>(SectionSnapshot::index(-1, y, z))];
        rows_[static_cast<std::size_t>((y + 1) * SectionSnapshot::kSide + z + 1)] =
            bits8(cells) | bits8(cells + 8) << 8 | static_cast<std::uint32_t>(cells[16]) << 16 |
            static_cast<std::uint32_t>(cells[17]) << 17;
      }
  }
  std::uint32_t row(int y, int z) const {
    return rows_[static_cast<std::size_t>((y + 1) * SectionSnapshot::kSide + z + 1)];
  }

  BlockId block(int x, int y, int z) const {
    return s_.blocks[static_cast<std::size_t>(SectionSnapshot::index(x, y, z))];
  }
  bool opaqueAt(int i) const { return s_.opaque[static_cast<std::size_t>(i)] != 0; }

  // Appends quads to a layer's vertices, which are grown ahead (uninitialised) and cut to size at
  // the end: a quad costs a compare, not a resize.
  struct LayerWriter {
    PackedVertices* out;
    std::size_t used = 0;
    PackedVertex* quad() {
      if (used + 4 > out->size()) out->resize(std::max(out->size() * 2, used + 4));
      PackedVertex* q = out->data() + used;
      used += 4;
      return q;
    }
  };
  LayerWriter& layer(const BlockMeshTable::Entry& e) { return writers_[static_cast<std::size_t>(e.layer)]; }

  bool faceVisible(BlockId id, const BlockMeshTable::Entry& e, int neighbourIndex) const {
    if (opaqueAt(neighbourIndex)) return false;
    const BlockId neighbour = s_.blocks[static_cast<std::size_t>(neighbourIndex)];
    if (e.shape == BlockShape::Liquid) return table_[neighbour].liquid != e.liquid;
    return !(e.cullSame && neighbour == id);
  }

  // Whether the block at `neighbour` (a model block) covers the whole side facing a face in direction D.
  template <int D>
  bool coveredFrom(int neighbour) const {
    constexpr int kFacing = D ^ 1;  // the neighbour's side that touches the face
    return (table_[s_.blocks[static_cast<std::size_t>(neighbour)]].fullSides >> kFacing) & 1u;
  }

  void cube(int x, int y, int z, BlockId id, const BlockMeshTable::Entry& e) {
    const bool liquid = e.shape == BlockShape::Liquid;
    // A liquid's surface sits 2/16 lower unless more of the same liquid is above it.
    const int top32 =
        liquid && table_[block(x, y + 1, z)].liquid != e.liquid ? 32 - kLiquidSurfaceDrop32 : 32;
    const int here = SectionSnapshot::index(x, y, z);
    forEachDirection([&](auto d) {
      const bool loweredTop = d == static_cast<int>(Direction::Up) && top32 < 32;
      const bool visible = faceVisible(id, e, here + kNeighbour[d]) &&
                           !coveredFrom<d>(here + kNeighbour[d]) && !(e.foliage && deepInFoliage<d>(x, y, z));
      if (!visible && !loweredTop) return;
      // A lowered surface under an opaque block is lit from the liquid's own cell, not the dark block.
      face<d>(x, y, z, e, top32, visible ? here + kNeighbour[d] : here);
    });
  }

  // Leaves keep the faces between them, seen through each other's holes, but only near the crown's
  // surface: a face into a leaf block with leaves (or an opaque cube) beyond it would be seen through
  // at least two alpha-tested faces, which hide nearly all of it, so it is left out for the camera and
  // the shadow map alike. Inside a forest's crowns most leaf faces are such. Looks no further than the
  // snapshot, so a section's mesh still depends only on the cells next to it.
  template <int D>
  bool deepInFoliage(int x, int y, int z) const {
    constexpr Vec n = kFaces[D].n;
    const int bx = x + 2 * n.x, by = y + 2 * n.y, bz = z + 2 * n.z;
    if (std::min({bx, by, bz}) < -1 || std::max({bx, by, bz}) > kChunkSize) return false;  // beyond the halo
    const int next = SectionSnapshot::index(x + n.x, y + n.y, z + n.z);
    const int far = SectionSnapshot::index(bx, by, bz);
    return table_[s_.blocks[static_cast<std::size_t>(next)]].foliage &&
           (opaqueAt(far) || table_[s_.blocks[static_cast<std::size_t>(far)]].foliage);
  }

  // f(std::integral_constant<int, d>) for each Direction d: per-face code with constant tables.
  template <class F>
  static void forEachDirection(F&& f) {
    [&]<int... D>(std::integer_sequence<int, D...>) {
      (f(std::integral_constant<int, D>{}), ...);
    }
    (std::make_integer_sequence<int, 6>{});
  }

  // The light fields of a full face's four corners in Direction d, lit from the cell `front`. Each
  // corner sums the light terms of the four cells around it in front of the face: the front cell
  // always counts (the face is visible, so it is not opaque), an opaque cell adds 0, and the diagonal
  // is left out when both sides are opaque. The open cells then number exactly ao + 1 (3 - opaque
  // ones, or 1 when both sides are walled), so the sum less one count is the vertex's light field:
  // both sums, and the count less one as its ambient occlusion.
  void cornerLight(const std::array<CornerCells, 4>& corners, int front, std::uint32_t (&corner)[4]) const {
    const std::uint32_t* light = s_.light.data() + front;
    const std::uint32_t own = light[0] - SectionSnapshot::kOpen;
    for (int c = 0; c < 4; ++c) {
      const CornerCells& k = corners[static_cast<std::size_t>(c)];
      const std::uint32_t t1 = light[k.side1], t2 = light[k.side2], t3 = light[k.diagonal];
      corner[c] = own + t1 + t2 + ((t1 | t2) != 0 ? t3 : 0);
    }
  }

  // One full-block face in Direction D with smooth light and ambient occlusion at each corner.
  // `front`: the snapshot cell the face looks into, whose surroundings light its corners.
  template <int D>
  void face(int x, int y, int z, const BlockMeshTable::Entry& e, int top32, int front) {
    std::uint32_t corner[4];
    cornerLight(kCorners[D], front, corner);
    const std::uint32_t base = PackedVertex::packPosition(x * 32, y * 32, z * 32);
    const std::uint32_t lowered = static_cast<std::uint32_t>(32 - top32) << 10;
    PackedVertex* q = layer(e).quad();
    // Split along the diagonal whose corners are the brighter pair: corners 1-3 instead of 0-2.
    if ((corner[0] >> 12) + (corner[2] >> 12) < (corner[1] >> 12) + (corner[3] >> 12)) {
      quad<D, 1>(q, base, lowered, e.material[D], corner);
    } else {
      quad<D, 0>(q, base, lowered, e.material[D], corner);
    }
  }

  // The four vertices of a face, starting at corner First (which picks the quad's diagonal).
  template <int D, int First>
  static void quad(PackedVertex* q, std::uint32_t base, std::uint32_t lowered, std::uint32_t material,
                   const std::uint32_t (&light)[4]) {
    for (int i = 0; i < 4; ++i) {
      const int c = (i + First) & 3;
      const CornerCells& k = kCorners[D][c];
      q[i] = {base + k.position - (k.top ? lowered : 0), material, light[c], k.uv};
    }
  }

  void flatQuad(LayerWriter& out, const std::array<Vec, 4>& corners32, const BlockMeshTable::Entry& e,
                int face, const std::array<std::array<int, 2>, 4>& uvs, std::uint32_t light) {
    PackedVertex v[4];
    for (int c = 0; c < 4; ++c) {
      v[c] = {PackedVertex::packPosition(corners32[c].x, corners32[c].y, corners32[c].z),
              BlockMeshTable::material(e, e.texture[0], face), light,
              PackedVertex::packUv(uvs[c][0], uvs[c][1])};
    }
    std::copy_n(v, 4, out.quad());
  }

  // A vertex lit flat by one cell, as a face corner with four open cells of that light.
  std::uint32_t cellLight(int index) const {
    return s_.light[static_cast<std::size_t>(index)] * 4 - SectionSnapshot::kOpen;
  }
  // A plant or torch is lit by its own cell.
  std::uint32_t ownLight(int x, int y, int z) const { return cellLight(SectionSnapshot::index(x, y, z)); }

  // Two diagonal planes, each seen from both sides (faces 6..9).
  void cross(int x, int y, int z, const BlockMeshTable::Entry& e) {
    const int x0 = x * 32 + 5, x1 = x * 32 + 27, y0 = y * 32, y1 = y * 32 + 32, z0 = z * 32 + 5,
              z1 = z * 32 + 27;
    const std::uint32_t light = ownLight(x, y, z);
    constexpr int u = kModelUnits;
    const std::array<std::array<int, 2>, 4> uvs = {{{0, u}, {u, u}, {u, 0}, {0, 0}}};
    const std::array<std::array<int, 2>, 4> back = {{{u, u}, {0, u}, {0, 0}, {u, 0}}};
    auto& out = layer(e);
    flatQuad(out, {{{x0, y0, z0}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z0}}}, e, 6, uvs, light);
    flatQuad(out, {{{x1, y0, z1}, {x0, y0, z0}, {x0, y1, z0}, {x1, y1, z1}}}, e, 7, back, light);
    flatQuad(out, {{{x0, y0, z1}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z1}}}, e, 8, uvs, light);
    flatQuad(out, {{{x1, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x1, y1, z0}}}, e, 9, back, light);
  }

  // Minecraft's torch: a 2/16 x 10/16 x 2/16 stick, sides textured from u 7..9, v 6..16, top 7..9, 6..8.
  void torch(int x, int y, int z, const BlockMeshTable::Entry& e) {
    const int x0 = x * 32 + 14, x1 = x * 32 + 18, y0 = y * 32, y1 = y * 32 + 20, z0 = z * 32 + 14,
              z1 = z * 32 + 18;
    const std::uint32_t light = ownLight(x, y, z);
    const std::array<std::array<int, 2>, 4> side = {{{7, 16}, {9, 16}, {9, 6}, {7, 6}}};
    const std::array<std::array<int, 2>, 4> top = {{{7, 8}, {9, 8}, {9, 6}, {7, 6}}};
    auto& out = layer(e);
    flatQuad(out, {{{x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}}}, e, 0, side, light);  // West
    flatQuad(out, {{{x1, y0, z1}, {x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}}}, e, 1, side, light);  // East
    flatQuad(out, {{{x1, y0, z0}, {x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}}}, e, 4, side, light);  // North
    flatQuad(out, {{{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}}, e, 5, side, light);  // South
    flatQuad(out, {{{x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}, {x0, y1, z0}}}, e, 3, top, light);   // Up
  }

  // A model block's quads. Left out against an opaque cube across the cullface, or a neighbour's
  // shape covering the quad there. Axis-aligned faces get smooth light and ambient occlusion, the
  // full face's corners interpolated at each vertex (vanilla's partial faces); the others are lit
  // flat by the cell they face: the neighbour across their cullface, else their own cell.
  void model(int x, int y, int z, const BlockMeshTable::Entry& e) {
    const int here = SectionSnapshot::index(x, y, z);
    auto& out = layer(e);
    // A state picking among weighted models does so by its cell's position, the same every time.
    const std::vector<ModelQuad>& quads =
        e.choices.empty()
            ? e.quads
            : e.choices[weightedPick(e.weights,
                                     positionSeed({s_.pos.x * kChunkSize + x, s_.pos.minBlockY() + y,
                                                   s_.pos.z * kChunkSize + z}))]
                  .quads;
    for (const ModelQuad& m : quads) {
      int lit = here;
      if (m.cullface >= 0) {
        const int neighbour = here + kNeighbour[static_cast<std::size_t>(m.cullface)];
        if (opaqueAt(neighbour) || hiddenBy(table_[s_.blocks[static_cast<std::size_t>(neighbour)]].coverage,
                                            static_cast<Direction>(m.cullface), m.rect)) {
          continue;
        }
        lit = neighbour;
      }
      std::uint32_t light[4];
      if (m.smooth) {
        smoothLight(m, here, light);
      } else {
        std::fill_n(light, 4, cellLight(lit));
      }
      const std::uint32_t mat =
          PackedVertex::packMaterial(m.texture, m.face, m.tinted ? static_cast<int>(e.tint) : 0);
      // The brighter diagonal splits the quad, as for full faces.
      const int first = (light[0] >> 12) + (light[2] >> 12) < (light[1] >> 12) + (light[3] >> 12) ? 1 : 0;
      PackedVertex* q = out.quad();
      for (int i = 0; i < 4; ++i) {
        const auto c = static_cast<std::size_t>((i + first) & 3);
        q[i] = {PackedVertex::packPosition(x * 32 + m.corners32[c][0], y * 32 + m.corners32[c][1],
                                           z * 32 + m.corners32[c][2]),
                mat, light[c], PackedVertex::packUv(m.uvs16[c][0], m.uvs16[c][1])};
      }
    }
  }

  // A model quad's vertex light: the corners of the full face in its direction (lit from the cell
  // beyond when the quad lies on its cell's side, else from its own cell) weighted by where the vertex
  // sits on that face. Averages and occlusion are interpolated, the block's own shape darkens its
  // inner corners, and the result is stored back as sums over ao + 1 cells.
  void smoothLight(const ModelQuad& m, int here, std::uint32_t (&light)[4]) const {
    const int d = m.face;
    int front = m.onSide ? here + kNeighbour[static_cast<std::size_t>(d)] : here;
    if (opaqueAt(front)) front = here;
    std::uint32_t corner[4];
    cornerLight(kCorners[static_cast<std::size_t>(d)], front, corner);
    interpolateModelLight(m, corner, light);
  }

  const SectionSnapshot& s_;
  const BlockMeshTable& table_;
  SectionMesh mesh_;
  std::array<LayerWriter, kMeshLayers> writers_;
  std::array<std::uint32_t, SectionSnapshot::kSide * SectionSnapshot::kSide> rows_;
  // Per thread: vertices per layer in the last section meshed.
  static thread_local std::array<std::size_t, kMeshLayers> lastSize_;
};

thread_local std::array<std::size_t, kMeshLayers> Mesher::lastSize_{};

}  // namespace

SectionMesh meshSection(const SectionSnapshot& snapshot, const BlockMeshTable& table) {
  SectionMesh mesh = Mesher(snapshot, table).run();
  const bool uniform = std::all_of(snapshot.tints.begin(), snapshot.tints.end(),
                                   [&](const ColumnTint& t) { return t == snapshot.tints[0]; });
  for (auto& layer : mesh.layers) {
    // Merging compares whole vertices, so varying tints go in first; a uniform one goes in after, on
    // the fewer merged vertices, and merges the same.
    if (uniform) {
      mergeFaces(layer.vertices);
      applyUniformTint(layer.vertices, snapshot.tints[0], table.tints());
    } else {
      applyTints(layer.vertices, snapshot, table.tints());
      mergeFaces(layer.vertices);
    }
  }
  return mesh;
}

}  // namespace terrasol
