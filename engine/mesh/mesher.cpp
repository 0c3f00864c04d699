#include "mesh/mesher.h"

namespace terrasol {
namespace {

struct Vec {
  int x, y, z;
};

// Per face (Direction order): the normal n and tangents t, b with t x b = n, so corners taken as
// (-,-) (+,-) (+,+) (-,+) in (t, b) run counter-clockwise seen from outside. u runs along t and v
// against b (v = 0 at the texture's top).
struct FaceFrame {
  Vec n, t, b;
};
constexpr FaceFrame kFaces[6] = {
    {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},   // West
    {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},   // East
    {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},   // Down
    {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},   // Up
    {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},  // North
    {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},    // South
};
constexpr int kCornerSigns[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

class Mesher {
 public:
  Mesher(const SectionSnapshot& s, const BlockMeshTable& table) : s_(s), table_(table) { mesh_.pos = s.pos; }

  SectionMesh run() {
    for (int y = 0; y < 16; ++y)
      for (int z = 0; z < 16; ++z)
        for (int x = 0; x < 16; ++x) {
          const BlockId id = block(x, y, z);
          if (id == kAir) continue;
          const auto& e = table_[id];
          switch (e.shape) {
            case BlockShape::Cube:
            case BlockShape::Liquid: cube(x, y, z, id, e); break;
            case BlockShape::Cross: cross(x, y, z, e); break;
            case BlockShape::Torch: torch(x, y, z, e); break;
            case BlockShape::None: break;
          }
        }
    return std::move(mesh_);
  }

 private:
  BlockId block(int x, int y, int z) const { return s_.blocks[static_cast<std::size_t>(SectionSnapshot::index(x, y, z))]; }
  bool opaque(int x, int y, int z) const { return table_[block(x, y, z)].opaque; }
  int blockLight(int x, int y, int z) const { return s_.blockLight[static_cast<std::size_t>(SectionSnapshot::index(x, y, z))]; }
  int skyLight(int x, int y, int z) const { return s_.skyLight[static_cast<std::size_t>(SectionSnapshot::index(x, y, z))]; }

  static std::uint32_t tintOf(const BlockMeshTable::Entry& e, int face) {
    // Grass blocks tint only their top; plants, leaves and water tint everything.
    if (e.tint == Tint::Grass && e.shape == BlockShape::Cube && face != static_cast<int>(Direction::Up)) return 0;
    return static_cast<std::uint32_t>(e.tint);
  }
  static std::uint32_t material(const BlockMeshTable::Entry& e, int texture, int face) {
    return static_cast<std::uint32_t>(texture) | static_cast<std::uint32_t>(face) << 16 | tintOf(e, face) << 20;
  }
  static std::uint32_t light4(int block4, int sky4, int ao) {
    return static_cast<std::uint32_t>(block4) | static_cast<std::uint32_t>(sky4) << 6 | static_cast<std::uint32_t>(ao) << 12;
  }
  static std::uint32_t uv(int u, int v) { return static_cast<std::uint32_t>(u) | static_cast<std::uint32_t>(v) << 5; }
  MeshData& layer(const BlockMeshTable::Entry& e) { return mesh_.layers[static_cast<std::size_t>(e.layer)]; }

  bool faceVisible(BlockId id, const BlockMeshTable::Entry& e, BlockId neighbour) const {
    const auto& n = table_[neighbour];
    if (n.opaque) return false;
    if (neighbour == id && e.cullSame) return false;
    return true;
  }

  void cube(int x, int y, int z, BlockId id, const BlockMeshTable::Entry& e) {
    const bool liquid = e.shape == BlockShape::Liquid;
    // A liquid's surface sits 2/16 lower unless more of the same liquid is above it.
    const int top32 = liquid && block(x, y + 1, z) != id ? 28 : 32;
    for (int d = 0; d < 6; ++d) {
      const Vec& n = kFaces[d].n;
      const BlockId neighbour = block(x + n.x, y + n.y, z + n.z);
      const bool loweredTop = d == static_cast<int>(Direction::Up) && top32 < 32;
      if (!faceVisible(id, e, neighbour) && !loweredTop) continue;
      face(x, y, z, d, e, top32);
    }
  }

  // One full-block face with smooth light and ambient occlusion at each corner.
  void face(int x, int y, int z, int d, const BlockMeshTable::Entry& e, int top32) {
    const FaceFrame& f = kFaces[d];
    const int fx = x + f.n.x, fy = y + f.n.y, fz = z + f.n.z;  // the cell in front of the face
    PackedVertex v[4];
    int ao[4];
    for (int c = 0; c < 4; ++c) {
      const int su = kCornerSigns[c][0], sv = kCornerSigns[c][1];
      const Vec a{su * f.t.x, su * f.t.y, su * f.t.z}, b{sv * f.b.x, sv * f.b.y, sv * f.b.z};
      const bool side1 = opaque(fx + a.x, fy + a.y, fz + a.z), side2 = opaque(fx + b.x, fy + b.y, fz + b.z);
      const bool corner = (side1 && side2) || opaque(fx + a.x + b.x, fy + a.y + b.y, fz + a.z + b.z);
      ao[c] = side1 && side2 ? 0 : 3 - (side1 + side2 + corner);
      // Smooth light: the front cell always counts (the face is visible, so it is not opaque).
      int blockSum = blockLight(fx, fy, fz), skySum = skyLight(fx, fy, fz), count = 1;
      if (!side1) blockSum += blockLight(fx + a.x, fy + a.y, fz + a.z), skySum += skyLight(fx + a.x, fy + a.y, fz + a.z), ++count;
      if (!side2) blockSum += blockLight(fx + b.x, fy + b.y, fz + b.z), skySum += skyLight(fx + b.x, fy + b.y, fz + b.z), ++count;
      if (!corner) {
        blockSum += blockLight(fx + a.x + b.x, fy + a.y + b.y, fz + a.z + b.z);
        skySum += skyLight(fx + a.x + b.x, fy + a.y + b.y, fz + a.z + b.z);
        ++count;
      }
      // Corner position in 1/32 block: centre + n/2 + t/2 + b/2.
      const int px = x * 32 + 16 + 16 * (f.n.x + a.x + b.x), pz = z * 32 + 16 + 16 * (f.n.z + a.z + b.z);
      int py = y * 32 + 16 + 16 * (f.n.y + a.y + b.y);
      if (py == y * 32 + 32) py = y * 32 + top32;  // a lowered liquid surface
      v[c] = {PackedVertex::packPosition(px, py, pz), material(e, e.texture[static_cast<std::size_t>(d)], d),
              light4((blockSum * 4 + count / 2) / count, (skySum * 4 + count / 2) / count, ao[c]),
              uv(su > 0 ? 16 : 0, sv > 0 ? 0 : 16)};
    }
    emit(layer(e), v, ao[0] + ao[2] < ao[1] + ao[3]);
  }

  // Appends a quad; `flip` splits it along corners 1-3 instead of 0-2.
  static void emit(MeshData& out, const PackedVertex v[4], bool flip) {
    for (int i = 0; i < 4; ++i) out.vertices.push_back(v[(i + (flip ? 1 : 0)) % 4]);
  }

  void flatQuad(MeshData& out, const std::array<Vec, 4>& corners32, const BlockMeshTable::Entry& e, int face,
                const std::array<std::array<int, 2>, 4>& uvs, std::uint32_t light) {
    PackedVertex v[4];
    for (int c = 0; c < 4; ++c) {
      v[c] = {PackedVertex::packPosition(corners32[c].x, corners32[c].y, corners32[c].z),
              material(e, e.texture[0], face), light, uv(uvs[c][0], uvs[c][1])};
    }
    emit(out, v, false);
  }

  std::uint32_t ownLight(int x, int y, int z) const { return light4(blockLight(x, y, z) * 4, skyLight(x, y, z) * 4, 3); }

  // Two diagonal planes, each seen from both sides (faces 6..9).
  void cross(int x, int y, int z, const BlockMeshTable::Entry& e) {
    const int x0 = x * 32 + 5, x1 = x * 32 + 27, y0 = y * 32, y1 = y * 32 + 32, z0 = z * 32 + 5, z1 = z * 32 + 27;
    const std::uint32_t light = ownLight(x, y, z);
    const std::array<std::array<int, 2>, 4> uvs = {{{0, 16}, {16, 16}, {16, 0}, {0, 0}}};
    const std::array<std::array<int, 2>, 4> back = {{{16, 16}, {0, 16}, {0, 0}, {16, 0}}};
    MeshData& out = layer(e);
    flatQuad(out, {{{x0, y0, z0}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z0}}}, e, 6, uvs, light);
    flatQuad(out, {{{x1, y0, z1}, {x0, y0, z0}, {x0, y1, z0}, {x1, y1, z1}}}, e, 7, back, light);
    flatQuad(out, {{{x0, y0, z1}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z1}}}, e, 8, uvs, light);
    flatQuad(out, {{{x1, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x1, y1, z0}}}, e, 9, back, light);
  }

  // Minecraft's torch: a 2/16 x 10/16 x 2/16 stick, sides textured from u 7..9, v 6..16, top 7..9, 6..8.
  void torch(int x, int y, int z, const BlockMeshTable::Entry& e) {
    const int x0 = x * 32 + 14, x1 = x * 32 + 18, y0 = y * 32, y1 = y * 32 + 20, z0 = z * 32 + 14, z1 = z * 32 + 18;
    const std::uint32_t light = ownLight(x, y, z);
    const std::array<std::array<int, 2>, 4> side = {{{7, 16}, {9, 16}, {9, 6}, {7, 6}}};
    const std::array<std::array<int, 2>, 4> top = {{{7, 8}, {9, 8}, {9, 6}, {7, 6}}};
    MeshData& out = layer(e);
    flatQuad(out, {{{x0, y0, z1}, {x0, y0, z0}, {x0, y1, z0}, {x0, y1, z1}}}, e, 0, side, light);  // West
    flatQuad(out, {{{x1, y0, z0}, {x1, y0, z1}, {x1, y1, z1}, {x1, y1, z0}}}, e, 1, side, light);  // East
    flatQuad(out, {{{x1, y0, z0}, {x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}}}, e, 4, side, light);  // North
    flatQuad(out, {{{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}}, e, 5, side, light);  // South
    flatQuad(out, {{{x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}, {x0, y1, z0}}}, e, 3, top, light);   // Up
  }

  const SectionSnapshot& s_;
  const BlockMeshTable& table_;
  SectionMesh mesh_;
};

MeshLayer layerOf(RenderLayer layer) {
  switch (layer) {
    case RenderLayer::Cutout: return MeshLayer::Cutout;
    case RenderLayer::Translucent: return MeshLayer::Translucent;
    default: return MeshLayer::Opaque;
  }
}

}  // namespace

BlockMeshTable::BlockMeshTable(const BlockRegistry& blocks, const std::function<std::uint16_t(BlockId, int)>& textureOf) {
  entries_.resize(blocks.size());
  for (BlockId id = 0; id < blocks.size(); ++id) {
    const BlockType& type = blocks[id];
    Entry& e = entries_[id];
    e.shape = type.shape;
    e.layer = layerOf(type.layer);
    e.opaque = type.isOpaqueCube();
    // Translucent blocks and clear cubes (glass: opacity 0) hide faces against themselves; leaves do not.
    e.cullSame = type.layer == RenderLayer::Translucent || type.shape == BlockShape::Liquid ||
                 (type.shape == BlockShape::Cube && type.opacity == 0);
    e.tint = type.tint;
    for (int f = 0; f < 6; ++f) e.texture[static_cast<std::size_t>(f)] = id == kAir ? 0 : textureOf(id, f);
  }
}

SectionMesh meshSection(const SectionSnapshot& snapshot, const BlockMeshTable& table) {
  return Mesher(snapshot, table).run();
}

}  // namespace terrasol
