#include "mesh/section_snapshot.h"

namespace terrasol {
namespace {

// True when every cell of `section`'s layer facing direction `d` (the face it shows towards the
// section we are meshing) is an opaque cube. Uniform sections answer without looking at cells.
bool faceIsOpaque(const Section& section, const BlockRegistry& blocks, int d) {
  if (section.isUniform()) return blocks[section.uniformBlock()].isOpaqueCube();
  for (int a = 0; a < 16; ++a)
    for (int b = 0; b < 16; ++b) {
      // The layer of `section` that touches ours: its opposite side in direction d.
      const int x = d == 0 ? 15 : d == 1 ? 0 : a;
      const int y = d == 2 ? 15 : d == 3 ? 0 : (d < 2 ? a : b);
      const int z = d == 4 ? 15 : d == 5 ? 0 : b;
      if (!blocks[section.get(x, y, z)].isOpaqueCube()) return false;
    }
  return true;
}

bool buried(const World& world, const Chunk& chunk, SectionPos pos) {
  const BlockRegistry& blocks = world.blocks();
  for (int d = 0; d < 6; ++d) {
    const BlockPos& o = kDirectionOffsets[d];
    const int s = pos.section + o.y;
    if (s < 0) continue;                       // below the world: never seen
    if (s >= kSectionCount) return false;      // open to the sky above the world
    const Chunk* neighbour = o.x == 0 && o.z == 0 ? &chunk : world.chunk({pos.x + o.x, pos.z + o.z});
    if (!neighbour || !faceIsOpaque(neighbour->section(s), blocks, d)) return false;
  }
  return true;
}

}  // namespace

CaptureResult captureSection(const World& world, SectionPos pos, SectionSnapshot& out) {
  const Chunk* chunk = world.chunk({pos.x, pos.z});
  if (!chunk) return CaptureResult::Empty;
  const Section& section = chunk->section(pos.section);
  if (section.isAllAir()) return CaptureResult::Empty;
  if (section.isUniform() && world.blocks()[section.uniformBlock()].isOpaqueCube() && buried(world, *chunk, pos)) {
    return CaptureResult::Buried;
  }

  out.pos = pos;
  const Chunk* columns[3][3];
  for (int dz = -1; dz <= 1; ++dz)
    for (int dx = -1; dx <= 1; ++dx) {
      const Chunk* c = world.chunk({pos.x + dx, pos.z + dz});
      columns[dz + 1][dx + 1] = c;
    }
  const int y0 = kMinY + pos.section * 16;
  const std::uint8_t* opaqueCube = world.blocks().opaqueCubes().data();
  for (int ly = -1; ly <= 16; ++ly) {
    const int y = y0 + ly;
    for (int lz = -1; lz <= 16; ++lz)
      for (int lx = -1; lx <= 16; ++lx) {
        const int i = SectionSnapshot::index(lx, ly, lz);
        const Chunk* c = columns[(lz + 16) / 16][(lx + 16) / 16];
        if (!c || !inWorldHeight(y)) {
          out.blocks[static_cast<std::size_t>(i)] = kAir;
          out.opaque[static_cast<std::size_t>(i)] = 0;
          out.blockLight[static_cast<std::size_t>(i)] = 0;
          out.skyLight[static_cast<std::size_t>(i)] = y >= kMaxY ? 15 : 0;
          continue;
        }
        const int cx = lx & 15, cz = lz & 15;
        const BlockId id = c->get(cx, y, cz);
        out.blocks[static_cast<std::size_t>(i)] = id;
        out.opaque[static_cast<std::size_t>(i)] = opaqueCube[id];
        const ChunkLight& light = c->light();
        const int s = sectionOf(y), cell = Section::index(cx, y & 15, cz);
        out.blockLight[static_cast<std::size_t>(i)] = light.lit ? light.block[static_cast<std::size_t>(s)].get(cell) : 0;
        out.skyLight[static_cast<std::size_t>(i)] = light.lit ? light.sky[static_cast<std::size_t>(s)].get(cell) : 0;
      }
  }
  return CaptureResult::Captured;
}

}  // namespace terrasol
