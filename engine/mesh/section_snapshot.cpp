#include "mesh/section_snapshot.h"

#include <algorithm>

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

// Copies `count` cells along x, from local (x0, y, z) of `chunk`, to `out` starting at index `dst`.
// Outside the world or without a chunk: air, no light (sky 15 above the world).
void copyRun(const Chunk* chunk, int y, int z, int x0, int count, const std::uint8_t* opaqueCube,
             SectionSnapshot& out, int dst) {
  const auto d = static_cast<std::size_t>(dst);
  if (!chunk || !inWorldHeight(y)) {
    std::fill_n(&out.blocks[d], count, kAir);
    std::fill_n(&out.opaque[d], count, std::uint8_t{0});
    std::fill_n(&out.light[d], count, SectionSnapshot::lightTerm(false, 0, y >= kMaxY ? 15 : 0));
    return;
  }
  const int s = sectionOf(y), first = Section::index(x0, y & 15, z);
  const Section& section = chunk->section(s);
  if (const auto* dense = section.blocks()) {
    std::copy_n(dense->data() + first, count, &out.blocks[d]);
  } else {
    std::fill_n(&out.blocks[d], count, section.uniformBlock());
  }
  for (int i = 0; i < count; ++i) out.opaque[d + static_cast<std::size_t>(i)] = opaqueCube[out.blocks[d + static_cast<std::size_t>(i)]];
  const ChunkLight& light = chunk->light();
  const NibbleArray& block = light.block[static_cast<std::size_t>(s)];
  const NibbleArray& sky = light.sky[static_cast<std::size_t>(s)];
  for (int i = 0; i < count; ++i) {
    const auto at = d + static_cast<std::size_t>(i);
    out.light[at] = light.lit ? SectionSnapshot::lightTerm(out.opaque[at], block.get(first + i), sky.get(first + i))
                              : SectionSnapshot::lightTerm(out.opaque[at], 0, 0);
  }
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
    for (int dx = -1; dx <= 1; ++dx) columns[dz + 1][dx + 1] = world.chunk({pos.x + dx, pos.z + dz});
  const std::uint8_t* opaqueCube = world.blocks().opaqueCubes().data();
  const int y0 = kMinY + pos.section * 16;
  for (int ly = -1; ly <= 16; ++ly) {
    const int y = y0 + ly;
    for (int lz = -1; lz <= 16; ++lz) {
      // Each row is three runs: one cell from the west chunk, 16 from this column, one from the east.
      const int row = SectionSnapshot::index(-1, ly, lz);
      copyRun(columns[(lz + 16) / 16][0], y, lz & 15, 15, 1, opaqueCube, out, row);
      copyRun(columns[(lz + 16) / 16][1], y, lz & 15, 0, 16, opaqueCube, out, row + 1);
      copyRun(columns[(lz + 16) / 16][2], y, lz & 15, 0, 1, opaqueCube, out, row + 17);
    }
  }
  return CaptureResult::Captured;
}

}  // namespace terrasol
