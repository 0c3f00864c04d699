#include "light/light_engine.h"

#include <algorithm>

#include "light/light_frame.h"
#include "light/propagator.h"
#include "light/section_solver.h"
#include "light/sky_columns.h"

namespace terrasol {

using light::Cell;
using light::computeSkyTops;
using light::fillOpenSky;
using light::kAllDirections;
using light::kHorizontal;
using light::Propagator;
using light::spreadTops;

namespace {

const NibbleArray& layerOf(const ChunkLight& light, LightChannel channel, int section) {
  return channel == LightChannel::Block ? light.block[static_cast<std::size_t>(section)]
                                        : light.sky[static_cast<std::size_t>(section)];
}

// The cell of a chunk's face in direction `d`, at position (a, y) along the face.
BlockPos faceCell(ChunkPos pos, int d, int a, int y, int beyond) {
  const int x = d == 0 ? -beyond : d == 1 ? kLastCell + beyond : a;
  const int z = d == 4 ? -beyond : d == 5 ? kLastCell + beyond : a;
  return {pos.minBlockX() + x, y, pos.minBlockZ() + z};
}

// Where a block ends the open sky column (light::kStopsAt, kStopsBelow): it has opacity or light does
// not cross its top, so it stays out of the sky's reach; or, clear with only its bottom closed (a snow
// layer, a carpet), the sky's full light enters it from above and goes no lower, as in Minecraft.
std::vector<std::uint8_t> columnStops(const std::vector<std::uint8_t>& opacity,
                                      const std::vector<std::uint8_t>& sides) {
  constexpr unsigned kDown = 1u << static_cast<int>(Direction::Down),
                     kUp = 1u << static_cast<int>(Direction::Up);
  std::vector<std::uint8_t> stops(opacity.size());
  for (std::size_t b = 0; b < stops.size(); ++b) {
    stops[b] = opacity[b] > 0 || (sides[b] & kUp) ? light::kStopsAt
               : (sides[b] & kDown)               ? light::kStopsBelow
                                                  : 0;
  }
  return stops;
}

// Per block id: 1 for an emitter, 2 for a block whose shape takes part in light (ChunkLight's counts).
std::vector<std::uint8_t> specialCells(const std::vector<std::uint8_t>& emission,
                                       const light::LightFaces& faces) {
  std::vector<std::uint8_t> kinds(emission.size());
  for (std::size_t b = 0; b < kinds.size(); ++b) {
    kinds[b] = (emission[b] > 0 ? 1 : 0) | (faces.shaped(static_cast<BlockId>(b)) ? 2 : 0);
  }
  return kinds;
}

// Whether two blocks take part in light through their shapes alike.
bool sameFaces(const light::LightFaces& faces, BlockId a, BlockId b) {
  return std::equal(faces.faces.begin() + a * 6, faces.faces.begin() + a * 6 + 6,
                    faces.faces.begin() + b * 6);
}

}  // namespace

LightEngine::LightEngine(World& world)
    : world_(world),
      faces_(world),
      columnStop_(columnStops(world.blocks().opacities(), faces_.full)),
      attenuation_(light::attenuations(world.blocks().opacities())),
      flood_(light::floodAttenuations(attenuation_, faces_)),
      emission_(world.blocks().emissions().data()),
      special_(specialCells(world.blocks().emissions(), faces_)),
      frame_(std::make_unique<light::LightFrame>()),
      solver_(std::make_unique<light::SectionSolver>()) {}

LightEngine::~LightEngine() = default;

light::Propagator LightEngine::propagator(const light::ChunkWindow& window, LightChannel channel) {
  return light::Propagator(*frame_, window, channel, flood_.data(), faces_, emission_, decrease_, increase_,
                           stats_, changed_);
}

std::uint8_t LightEngine::lightAt(const BlockPos& pos, LightChannel channel) const {
  if (pos.y >= kMaxY) return channel == LightChannel::Sky ? kMaxLight : 0;
  if (pos.y < kMinY) return 0;
  const Chunk* c = world_.chunk(ChunkPos::of(pos));
  if (!c || !c->light().lit) return 0;
  return layerOf(c->light(), channel, sectionOf(pos.y))
      .get(Section::index(localOf(pos.x), localOf(pos.y), localOf(pos.z)));
}

std::vector<SectionPos> LightEngine::takeChangedSections() {
  return changed_.take();
}

void LightEngine::chunkLoaded(ChunkPos pos) {
  Chunk* chunk = world_.chunk(pos);
  if (!chunk) return;
  ChunkLight& light = chunk->light();
  computeSkyTops(*chunk, columnStop_.data(), light);
  for (auto& block : light.block) block.fill(0);
  fillOpenSky(light);
  light.lit = true;
  for (int s = 0; s < kSectionCount; ++s) changed_.add(pos.x, s, pos.z);

  const light::ChunkWindow window(world_, {pos.x - 1 - kReach, pos.z - 1 - kReach},
                                  {pos.x + 1 + kReach, pos.z + 1 + kReach});
  for (const LightChannel channel : {LightChannel::Block, LightChannel::Sky}) {
    Propagator p = propagator(window, channel);
    if (channel == LightChannel::Block) {
      seedEmitters(p, *chunk);
    } else {
      seedOpenSky(p, *chunk);
    }
    seedFromNeighbours(p, pos, channel);
    p.run();
  }
}

// Every emitter starts at its emission; the per-section counts of emitters and shaped cells are
// rebuilt on the way.
void LightEngine::seedEmitters(light::Propagator& p, Chunk& chunk) {
  const int x0 = chunk.pos().minBlockX(), z0 = chunk.pos().minBlockZ();
  Cell cell;
  for (int s = 0; s < kSectionCount; ++s) {
    const Section& section = chunk.section(s);
    if (!countSpecialCells(chunk, s)) continue;
    for (int i = 0; i < Section::kVolume; ++i) {
      const std::uint8_t e = emission_[section.at(i)];
      if (e == 0) continue;
      const int x = x0 + Section::xOf(i), y = sectionMinY(s) + Section::yOf(i), z = z0 + Section::zOf(i);
      p.locate(x, y, z, cell);
      p.setLight(cell, e);
      p.increase(x, y, z, e, kAllDirections);
    }
  }
}

bool LightEngine::countSpecialCells(Chunk& chunk, int s) const {
  const Section& section = chunk.section(s);
  ChunkLight& light = chunk.light();
  std::uint16_t emitters = 0, shaped = 0;
  if (!section.isUniform()) {
    for (const BlockId b : *section.blocks()) {
      const std::uint8_t kind = special_[b];
      emitters += kind & 1;
      shaped += kind >> 1;
    }
  } else if (special_[section.uniformBlock()] != 0) {
    const std::uint8_t kind = special_[section.uniformBlock()];
    emitters = static_cast<std::uint16_t>((kind & 1) * Section::kVolume);
    shaped = static_cast<std::uint16_t>((kind >> 1) * Section::kVolume);
  }
  light.emitters[static_cast<std::size_t>(s)] = emitters;
  light.shaped[static_cast<std::size_t>(s)] = shaped;
  return emitters > 0;
}

// Open-sky cells next to a darker cell spread sky light from there; a block in the top layer of the
// world is lit from the sky above it.
void LightEngine::seedOpenSky(light::Propagator& p, const Chunk& chunk) {
  const ChunkLight& light = chunk.light();
  const int x0 = chunk.pos().minBlockX(), z0 = chunk.pos().minBlockZ();
  const auto tops = spreadTops(world_, chunk);
  Cell cell;
  for (int i = 0; i < kChunkArea; ++i) {
    const int x = x0 + (i & kLastCell), z = z0 + (i >> kChunkShift),
              top = light.skyTop[static_cast<std::size_t>(i)];
    for (int y = top + 1; y <= std::min(tops[static_cast<std::size_t>(i)], kMaxY - 1); ++y) {
      p.increase(x, y, z, kMaxLight, kAllDirections);
    }
    if (top == kMaxY - 1 && p.locate(x, top, z, cell)) {
      const std::uint8_t level = p.source(cell);
      p.setLight(cell, level);
      p.increase(x, top, z, level, kAllDirections);
    }
  }
}

// Light already in the four neighbours flows in across the chunk's borders.
void LightEngine::seedFromNeighbours(light::Propagator& p, ChunkPos pos, LightChannel channel) {
  for (const int d : kHorizontal) {
    const BlockPos& o = kDirectionOffsets[d];
    const Chunk* neighbour = world_.chunk({pos.x + o.x, pos.z + o.z});
    if (!neighbour || !neighbour->light().lit) continue;
    const auto toward = static_cast<std::uint8_t>(light::faceBit(light::opposite(d)));
    for (int s = 0; s < kSectionCount; ++s) {
      const NibbleArray& layer = layerOf(neighbour->light(), channel, s);
      if (layer.isUniform() && layer.uniformLevel() <= 1) continue;
      for (int ly = 0; ly < kChunkSize; ++ly)
        for (int a = 0; a < kChunkSize; ++a) {
          const BlockPos c = faceCell(pos, d, a, sectionMinY(s) + ly, 1);
          const std::uint8_t level = layer.get(Section::index(localOf(c.x), ly, localOf(c.z)));
          if (level > 1) p.increase(c.x, c.y, c.z, level, toward);
        }
    }
  }
}

void LightEngine::chunkUnloading(ChunkPos pos) {
  Chunk* chunk = world_.chunk(pos);
  if (!chunk || !chunk->light().lit) return;
  // Propagate as if the chunk were already gone: every light level on its faces is removed from the
  // neighbours, which then refill from their own sources.
  const light::ChunkWindow window(world_, {pos.x - 1 - kReach, pos.z - 1 - kReach},
                                  {pos.x + 1 + kReach, pos.z + 1 + kReach}, chunk);
  for (const LightChannel channel : {LightChannel::Block, LightChannel::Sky}) {
    Propagator p = propagator(window, channel);
    for (const int d : kHorizontal) {
      const BlockPos& o = kDirectionOffsets[d];
      const Chunk* neighbour = world_.chunk({pos.x + o.x, pos.z + o.z});
      if (!neighbour || !neighbour->light().lit) continue;
      for (int s = 0; s < kSectionCount; ++s) {
        const NibbleArray& layer = layerOf(chunk->light(), channel, s);
        if (layer.isUniform() && layer.uniformLevel() == 0) continue;
        for (int ly = 0; ly < kChunkSize; ++ly)
          for (int a = 0; a < kChunkSize; ++a) {
            const BlockPos c = faceCell(pos, d, a, sectionMinY(s) + ly, 0);
            const std::uint8_t level = layer.get(Section::index(localOf(c.x), ly, localOf(c.z)));
            if (level > 0) p.decrease(c.x, c.y, c.z, level, static_cast<std::uint8_t>(light::faceBit(d)));
          }
      }
    }
    p.run();
  }
  chunk->light().lit = false;
}

void LightEngine::blockChanged(const BlockChange& change) {
  const BlockPos& at = change.pos;
  const auto opacity = world_.blocks().opacities().data();
  const bool sameLight = opacity[change.before] == opacity[change.after] &&
                         emission_[change.before] == emission_[change.after] &&
                         sameFaces(faces_, change.before, change.after);
  Chunk* chunk = world_.chunk(ChunkPos::of(at));
  if (sameLight || !chunk || !chunk->light().lit) return;

  ChunkLight& light = chunk->light();
  const int oldTop = light.skyTop[static_cast<std::size_t>(columnIndex(localOf(at.x), localOf(at.z)))];
  const int newTop = updateSkyTop(*chunk, change);
  auto& emitters = light.emitters[static_cast<std::size_t>(sectionOf(at.y))];
  emitters =
      static_cast<std::uint16_t>(emitters - (emission_[change.before] > 0) + (emission_[change.after] > 0));
  auto& shaped = light.shaped[static_cast<std::size_t>(sectionOf(at.y))];
  shaped = static_cast<std::uint16_t>(shaped - faces_.shaped(change.before) + faces_.shaped(change.after));

  const ChunkPos here = ChunkPos::of(at);
  const light::ChunkWindow window(world_, {here.x - kReach, here.z - kReach},
                                  {here.x + kReach, here.z + kReach});
  // Sky light only sees opacity and shapes: a new or removed emitter leaves it alone.
  const bool skyToo =
      opacity[change.before] != opacity[change.after] || !sameFaces(faces_, change.before, change.after);
  for (const LightChannel channel : {LightChannel::Block, LightChannel::Sky}) {
    if (channel == LightChannel::Sky && !skyToo) continue;
    Propagator p = propagator(window, channel);
    seedChangedCell(p, at, !sameFaces(faces_, change.before, change.after));
    if (channel == LightChannel::Sky) seedSkyColumn(p, at, oldTop, newTop);
    p.run();
  }
}

// The column's highest block that ends the open sky after the change (ChunkLight::skyTop), stored and
// returned.
int LightEngine::updateSkyTop(Chunk& chunk, const BlockChange& change) {
  const BlockPos& at = change.pos;
  auto& top = chunk.light().skyTop[static_cast<std::size_t>(columnIndex(localOf(at.x), localOf(at.z)))];
  int newTop = top;
  const std::uint8_t stop = columnStop_[change.after];
  if (stop && light::skyTopUnder(stop, at.y) > top) {
    newTop = light::skyTopUnder(stop, at.y);
  } else if (at.y == top || at.y == top + 1) {
    // The block that ended the column may have gone: look down from it for the next.
    newTop = kMinY - 1;
    for (int y = top + 1; y >= kMinY; --y) {
      if (const std::uint8_t s = columnStop_[chunk.get(localOf(at.x), y, localOf(at.z))]) {
        newTop = light::skyTopUnder(s, y);
        break;
      }
    }
  }
  top = static_cast<std::int16_t>(newTop);
  return newTop;
}

// The changed cell takes its own new level (removing light it can no longer hold), and its neighbours
// offer theirs, since it may now let more light in. A cell whose light sides changed takes back what
// it gave even where its own level stays (the sky's full light in a snow layer becoming stairs): the
// light may no longer leave it on every side.
void LightEngine::seedChangedCell(light::Propagator& p, const BlockPos& at, bool reshaped) {
  Cell cell;
  p.locate(at.x, at.y, at.z, cell);
  const std::uint8_t before = p.light(cell), own = p.source(cell);
  if (own != before) p.setLight(cell, own);
  if (before > own || (reshaped && before > 0)) p.decrease(at.x, at.y, at.z, before, kAllDirections);
  if (own > 0) p.increase(at.x, at.y, at.z, own, kAllDirections);
  for (int d = 0; d < 6; ++d) {
    const BlockPos n = at.offset(kDirectionOffsets[d].x, kDirectionOffsets[d].y, kDirectionOffsets[d].z);
    Cell near;
    if (!p.locate(n.x, n.y, n.z, near)) continue;
    const std::uint8_t level = p.light(near);
    if (level > 1)
      p.increase(n.x, n.y, n.z, level, static_cast<std::uint8_t>(light::faceBit(light::opposite(d))));
  }
}

// The open sky column got longer (its cells gain their own kMaxLight) or shorter (they lose it).
void LightEngine::seedSkyColumn(light::Propagator& p, const BlockPos& at, int oldTop, int newTop) {
  Cell cell;
  for (int y = newTop + 1; y <= oldTop && y < kMaxY; ++y) {
    if (y == at.y || !p.locate(at.x, y, at.z, cell)) continue;
    p.setLight(cell, kMaxLight);
    p.increase(at.x, y, at.z, kMaxLight, kAllDirections);
  }
  for (int y = oldTop + 1; y <= newTop; ++y) {
    if (y == at.y || !p.locate(at.x, y, at.z, cell)) continue;
    const std::uint8_t level = p.light(cell);
    if (level == 0) continue;
    p.setLight(cell, 0);
    p.decrease(at.x, y, at.z, level, kAllDirections);
  }
}

}  // namespace terrasol
