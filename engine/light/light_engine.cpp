#include "light/light_engine.h"

#include <algorithm>
#include <cstring>

#include "light/level_words.h"
#include "light/light_frame.h"
#include "light/propagator.h"
#include "light/section_solver.h"

namespace terrasol {

using light::Cell;
using light::kAllDirections;
using light::Propagator;
using light::SectionRef;

namespace {

constexpr int kReach = 2;  // chunks an update can reach beyond its seeds (see light_frame.h)
constexpr int kHorizontal[4] = {0, 1, 4, 5};  // West, East, North, South

// Highest block with opacity >= 1 in each column; uniform sections are skipped whole.
void computeSkyTops(const Chunk& chunk, const std::uint8_t* opacity, ChunkLight& light) {
  light.skyTop.fill(static_cast<std::int16_t>(kMinY - 1));
  std::array<bool, 256> done{};
  int remaining = 256;
  for (int s = kSectionCount - 1; s >= 0 && remaining > 0; --s) {
    const Section& section = chunk.section(s);
    if (section.isUniform()) {
      if (opacity[section.uniformBlock()] == 0) continue;
      for (std::size_t i = 0; i < 256; ++i) {
        if (!done[i]) light.skyTop[i] = static_cast<std::int16_t>(kMinY + s * 16 + 15);
      }
      break;
    }
    for (int ly = 15; ly >= 0; --ly)
      for (std::size_t i = 0; i < 256; ++i) {
        if (done[i] || opacity[section.at(ly * 256 + static_cast<int>(i))] == 0) continue;
        done[i] = true;
        light.skyTop[i] = static_cast<std::int16_t>(kMinY + s * 16 + ly);
        --remaining;
      }
  }
}

// Sky light 15 above each column's top, 0 elsewhere; whole sections stay uniform where they can.
void fillOpenSky(ChunkLight& light) {
  const auto [lowest, highest] = std::minmax_element(light.skyTop.begin(), light.skyTop.end());
  for (int s = 0; s < kSectionCount; ++s) {
    const int bottom = kMinY + s * 16;
    NibbleArray& sky = light.sky[static_cast<std::size_t>(s)];
    sky.fill(bottom > *highest ? 15 : 0);
    if (bottom > *highest || bottom + 15 <= *lowest) continue;
    for (int ly = 0; ly < 16; ++ly)
      for (std::size_t i = 0; i < 256; ++i) {
        if (bottom + ly > light.skyTop[i]) sky.set(ly * 256 + static_cast<int>(i), 15);
      }
  }
}

// For each column of a chunk: the highest sky top among its four horizontal neighbours (in this
// chunk or the next; unlit neighbours do not count, they take no light), at least its own top + 1.
// Open-sky cells up to that height border a darker cell, so sky light spreads from them.
std::array<int, 256> spreadTops(const World& world, const Chunk& chunk) {
  const ChunkPos pos = chunk.pos();
  const Chunk* around[4];
  for (int k = 0; k < 4; ++k) {
    const BlockPos& o = kDirectionOffsets[kHorizontal[k]];
    const Chunk* c = world.chunk({pos.x + o.x, pos.z + o.z});
    around[k] = c && c->light().lit ? c : nullptr;
  }
  std::array<int, 256> tops;
  for (int lz = 0; lz < 16; ++lz)
    for (int lx = 0; lx < 16; ++lx) {
      int highest = chunk.light().skyTop[static_cast<std::size_t>(lz * 16 + lx)] + 1;
      for (int k = 0; k < 4; ++k) {
        const BlockPos& o = kDirectionOffsets[kHorizontal[k]];
        const int nx = lx + o.x, nz = lz + o.z;
        const bool outside = nx < 0 || nx > 15 || nz < 0 || nz > 15;
        const Chunk* c = outside ? around[k] : &chunk;
        if (c) highest = std::max<int>(highest, c->light().skyTop[static_cast<std::size_t>((nz & 15) * 16 + (nx & 15))]);
      }
      tops[static_cast<std::size_t>(lz * 16 + lx)] = highest;
    }
  return tops;
}

const NibbleArray& layerOf(const ChunkLight& light, LightChannel channel, int section) {
  return channel == LightChannel::Block ? light.block[static_cast<std::size_t>(section)]
                                        : light.sky[static_cast<std::size_t>(section)];
}

// The cell of a chunk's face in direction `d`, at position (a, y) along the face.
BlockPos faceCell(ChunkPos pos, int d, int a, int y, int beyond) {
  const int x = d == 0 ? -beyond : d == 1 ? 15 + beyond : a;
  const int z = d == 4 ? -beyond : d == 5 ? 15 + beyond : a;
  return {pos.minBlockX() + x, y, pos.minBlockZ() + z};
}

}  // namespace

LightEngine::LightEngine(World& world)
    : world_(world),
      opacity_(world.blocks().opacities().data()),
      attenuation_(light::attenuations(world.blocks().opacities())),
      emission_(world.blocks().emissions().data()),
      frame_(std::make_unique<light::LightFrame>()),
      solver_(std::make_unique<light::SectionSolver>()) {}

LightEngine::~LightEngine() = default;

light::Propagator LightEngine::propagator(const light::ChunkWindow& window, LightChannel channel) {
  return light::Propagator(*frame_, window, channel, attenuation_.data(), emission_, decrease_, increase_,
                           stats_, changed_);
}

std::uint8_t LightEngine::lightAt(const BlockPos& pos, LightChannel channel) const {
  if (pos.y >= kMaxY) return channel == LightChannel::Sky ? 15 : 0;
  if (pos.y < kMinY) return 0;
  const Chunk* c = world_.chunk(ChunkPos::of(pos));
  if (!c || !c->light().lit) return 0;
  return layerOf(c->light(), channel, sectionOf(pos.y)).get(Section::index(localOf(pos.x), localOf(pos.y), localOf(pos.z)));
}

std::vector<SectionPos> LightEngine::takeChangedSections() {
  return changed_.take();
}

void LightEngine::chunkLoaded(ChunkPos pos) {
  Chunk* chunk = world_.chunk(pos);
  if (!chunk) return;
  ChunkLight& light = chunk->light();
  computeSkyTops(*chunk, opacity_, light);
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

// Every emitter starts at its emission; the per-section emitter counts are rebuilt on the way.
void LightEngine::seedEmitters(light::Propagator& p, Chunk& chunk) {
  ChunkLight& light = chunk.light();
  const int x0 = chunk.pos().minBlockX(), z0 = chunk.pos().minBlockZ();
  Cell cell;
  for (int s = 0; s < kSectionCount; ++s) {
    const Section& section = chunk.section(s);
    light.emitters[static_cast<std::size_t>(s)] = 0;
    if (section.isUniform() && emission_[section.uniformBlock()] == 0) continue;
    for (int i = 0; i < Section::kVolume; ++i) {
      const std::uint8_t e = emission_[section.at(i)];
      if (e == 0) continue;
      ++light.emitters[static_cast<std::size_t>(s)];
      const int x = x0 + (i & 15), y = kMinY + s * 16 + (i >> 8), z = z0 + ((i >> 4) & 15);
      p.locate(x, y, z, cell);
      p.setLight(cell, e);
      p.increase(x, y, z, e, kAllDirections);
    }
  }
}

// Open-sky cells next to a darker cell spread sky light from there; a block in the top layer of the
// world is lit from the sky above it.
void LightEngine::seedOpenSky(light::Propagator& p, const Chunk& chunk) {
  const ChunkLight& light = chunk.light();
  const int x0 = chunk.pos().minBlockX(), z0 = chunk.pos().minBlockZ();
  const auto tops = spreadTops(world_, chunk);
  Cell cell;
  for (int i = 0; i < 256; ++i) {
    const int x = x0 + (i & 15), z = z0 + (i >> 4), top = light.skyTop[static_cast<std::size_t>(i)];
    for (int y = top + 1; y <= std::min(tops[static_cast<std::size_t>(i)], kMaxY - 1); ++y) {
      p.increase(x, y, z, 15, kAllDirections);
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
    const auto toward = static_cast<std::uint8_t>(1 << light::opposite(d));
    for (int s = 0; s < kSectionCount; ++s) {
      const NibbleArray& layer = layerOf(neighbour->light(), channel, s);
      if (layer.isUniform() && layer.uniformLevel() <= 1) continue;
      for (int ly = 0; ly < 16; ++ly)
        for (int a = 0; a < 16; ++a) {
          const BlockPos c = faceCell(pos, d, a, kMinY + s * 16 + ly, 1);
          const std::uint8_t level = layer.get(Section::index(c.x & 15, ly, c.z & 15));
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
        for (int ly = 0; ly < 16; ++ly)
          for (int a = 0; a < 16; ++a) {
            const BlockPos c = faceCell(pos, d, a, kMinY + s * 16 + ly, 0);
            const std::uint8_t level = layer.get(Section::index(c.x & 15, ly, c.z & 15));
            if (level > 0) p.decrease(c.x, c.y, c.z, level, static_cast<std::uint8_t>(1 << d));
          }
      }
    }
    p.run();
  }
  chunk->light().lit = false;
}

void LightEngine::blockChanged(const BlockChange& change) {
  const BlockPos& at = change.pos;
  const bool sameLight = opacity_[change.before] == opacity_[change.after] &&
                         emission_[change.before] == emission_[change.after];
  Chunk* chunk = world_.chunk(ChunkPos::of(at));
  if (sameLight || !chunk || !chunk->light().lit) return;

  ChunkLight& light = chunk->light();
  const int oldTop = light.skyTop[static_cast<std::size_t>(localOf(at.z) * 16 + localOf(at.x))];
  const int newTop = updateSkyTop(*chunk, change);
  auto& emitters = light.emitters[static_cast<std::size_t>(sectionOf(at.y))];
  emitters = static_cast<std::uint16_t>(emitters - (emission_[change.before] > 0) + (emission_[change.after] > 0));

  const ChunkPos here = ChunkPos::of(at);
  const light::ChunkWindow window(world_, {here.x - kReach, here.z - kReach}, {here.x + kReach, here.z + kReach});
  // Sky light only sees opacity: a new or removed emitter leaves it alone.
  const bool skyToo = opacity_[change.before] != opacity_[change.after];
  for (const LightChannel channel : {LightChannel::Block, LightChannel::Sky}) {
    if (channel == LightChannel::Sky && !skyToo) continue;
    Propagator p = propagator(window, channel);
    seedChangedCell(p, at);
    if (channel == LightChannel::Sky) seedSkyColumn(p, at, oldTop, newTop);
    p.run();
  }
}

// The column's highest block with opacity after the change (ChunkLight::skyTop), stored and returned.
int LightEngine::updateSkyTop(Chunk& chunk, const BlockChange& change) {
  const BlockPos& at = change.pos;
  auto& top = chunk.light().skyTop[static_cast<std::size_t>(localOf(at.z) * 16 + localOf(at.x))];
  int newTop = top;
  if (opacity_[change.after] > 0 && at.y > top) newTop = at.y;
  if (opacity_[change.after] == 0 && at.y == top) {
    newTop = kMinY - 1;
    for (int y = at.y - 1; y >= kMinY; --y) {
      if (opacity_[chunk.get(localOf(at.x), y, localOf(at.z))] > 0) {
        newTop = y;
        break;
      }
    }
  }
  top = static_cast<std::int16_t>(newTop);
  return newTop;
}

// The changed cell takes its own new level (removing light it can no longer hold), and its neighbours
// offer theirs, since it may now let more light in.
void LightEngine::seedChangedCell(light::Propagator& p, const BlockPos& at) {
  Cell cell;
  p.locate(at.x, at.y, at.z, cell);
  const std::uint8_t before = p.light(cell), own = p.source(cell);
  if (own != before) p.setLight(cell, own);
  if (before > own) p.decrease(at.x, at.y, at.z, before, kAllDirections);
  if (own > 0) p.increase(at.x, at.y, at.z, own, kAllDirections);
  for (int d = 0; d < 6; ++d) {
    const BlockPos n = at.offset(kDirectionOffsets[d].x, kDirectionOffsets[d].y, kDirectionOffsets[d].z);
    Cell near;
    if (!p.locate(n.x, n.y, n.z, near)) continue;
    const std::uint8_t level = p.light(near);
    if (level > 1) p.increase(n.x, n.y, n.z, level, static_cast<std::uint8_t>(1 << light::opposite(d)));
  }
}

// The open sky column got longer (its cells gain their own 15) or shorter (they lose it).
void LightEngine::seedSkyColumn(light::Propagator& p, const BlockPos& at, int oldTop, int newTop) {
  Cell cell;
  for (int y = newTop + 1; y <= oldTop && y < kMaxY; ++y) {
    if (y == at.y || !p.locate(at.x, y, at.z, cell)) continue;
    p.setLight(cell, 15);
    p.increase(at.x, y, at.z, 15, kAllDirections);
  }
  for (int y = oldTop + 1; y <= newTop; ++y) {
    if (y == at.y || !p.locate(at.x, y, at.z, cell)) continue;
    const std::uint8_t level = p.light(cell);
    if (level == 0) continue;
    p.setLight(cell, 0);
    p.decrease(at.x, y, at.z, level, kAllDirections);
  }
}

// The levels a section's cells have by themselves, a byte each: their emission, or the open sky
// column's 15 (and the top layer of the world, lit from the sky above through its own opacity).
void LightEngine::ownLevels(const Chunk& chunk, int section, LightChannel channel, std::uint8_t* levels) const {
  const Section& blocks = chunk.section(section);
  if (channel == LightChannel::Block) {
    if (chunk.light().emitters[static_cast<std::size_t>(section)] == 0) {
      std::fill(levels, levels + Section::kVolume, 0);
      return;
    }
    for (int i = 0; i < Section::kVolume; ++i) levels[i] = emission_[blocks.at(i)];
    return;
  }
  const auto& tops = chunk.light().skyTop;
  const int y0 = kMinY + section * 16;
  for (int ly = 0; ly < 16; ++ly) {
    const int y = y0 + ly;
    for (std::size_t column = 0; column < 256; ++column) levels[ly * 256 + column] = y > tops[column] ? 15 : 0;
  }
  if (y0 + 15 != kMaxY - 1) return;
  for (int column = 0; column < 256; ++column) {
    std::uint8_t& level = levels[15 * 256 + column];
    if (level == 0) level = light::topLayerSky(attenuation_[blocks.at(15 * 256 + column)]);
  }
}

namespace {

// True when a cell on the section's faces would get less light than it has (`current`).
bool faceLosesLight(const std::uint8_t* current, const light::SectionSolver::Levels& levels) {
  for (int q = 0; q < light::kByteWords; ++q) {
    if (light::lowerBytes(light::byteWord(current, q), light::byteWord(levels.data(), q)) &
        light::faceBytes(q)) {
      return true;
    }
  }
  return false;
}

// Calls fn(index) for each cell of a section whose own level (`levels`) must spread: emitters, and
// open-sky cells up to the highest neighbouring column top (spreadTops); the rest of the open sky only
// has 15s around it.
template <class Fn>
void forSources(const std::uint8_t* levels, LightChannel channel, bool emitters, const std::array<int, 256>& tops,
                const std::array<std::int16_t, 256>& skyTop, int y0, Fn&& fn) {
  if (channel == LightChannel::Block) {
    if (!emitters) return;
    for (int i = 0; i < Section::kVolume; ++i) {
      if (levels[i] > 1) fn(i);
    }
    return;
  }
  for (int column = 0; column < 256; ++column) {
    const int lo = std::max<int>(skyTop[static_cast<std::size_t>(column)] + 1, y0);
    const int hi = std::min(tops[static_cast<std::size_t>(column)], y0 + 15);
    for (int y = lo; y <= hi; ++y) fn((y - y0) * 256 + column);
  }
  if (y0 + 15 != kMaxY - 1) return;
  for (int i = 15 * 256; i < Section::kVolume; ++i) {
    if (levels[i] > 1 && levels[i] < 15) fn(i);  // the top layer under the sky (topLayerSky)
  }
}

}  // namespace

// The section's light is solved in bytes, from its own sources and the light around it
// (SectionSolver), then written whole. Light leaving through a face that got brighter spreads on
// outside. If a face cell got darker, light outside may have come from it, and the solver took some
// of that back in: then the section is relit the general way instead.
void LightEngine::relightSection(const SectionPos& s) {
  Chunk* chunk = world_.chunk({s.x, s.z});
  if (!chunk || !chunk->light().lit || s.section < 0 || s.section >= kSectionCount) return;
  const int x0 = s.x * 16, y0 = kMinY + s.section * 16, z0 = s.z * 16;
  const auto tops = spreadTops(world_, *chunk);
  const light::ChunkWindow window(world_, {s.x - kReach, s.z - kReach}, {s.x + kReach, s.z + kReach});
  const Section& blocks = chunk->section(s.section);
  const BlockId uniform = blocks.uniformBlock();
  light::SectionSolver& solver = *solver_;
  solver.begin(blocks.blocks() ? blocks.blocks()->data() : &uniform,
               blocks.blocks() ? Section::kVolume - 1 : 0, attenuation_.data());
  for (const LightChannel channel : {LightChannel::Block, LightChannel::Sky}) {
    Propagator p = propagator(window, channel);
    Cell origin;
    p.locate(x0, y0, z0, origin);
    Cell beyond[6];  // each neighbouring section's cell 0, packed; ref null where not loaded
    for (int d = 0; d < 6; ++d) {
      const BlockPos& o = kDirectionOffsets[d];
      if (!p.locatePacked(x0 + o.x * 16, y0 + o.y * 16, z0 + o.z * 16, beyond[d])) beyond[d].ref = nullptr;
    }

    // Every source offers its light. Open-sky cells above the neighbouring columns only have 15s
    // around them and are left out.
    auto& levels = solver.levels();
    ownLevels(*chunk, s.section, channel, levels.data());
    const bool emitters = chunk->light().emitters[static_cast<std::size_t>(s.section)] > 0;
    forSources(levels.data(), channel, emitters, tops, chunk->light().skyTop, y0, [&](int i) { solver.seed(i); });
    for (int d = 0; d < 6; ++d) {
      if (!beyond[d].ref) continue;
      const NibbleArray& n = *beyond[d].ref->layer;
      if (n.isUniform() && n.uniformLevel() <= 1) continue;
      for (const light::FaceCell& c : light::kFaceCells[static_cast<std::size_t>(d)]) solver.offer(c.ours, n.get(c.theirs));
    }
    solver.solve();

    light::SectionRef& r = *origin.ref;
    if (std::memcmp(levels.data(), r.levelBytes(), levels.size()) == 0) continue;  // nothing to write
    if (faceLosesLight(r.levelBytes(), levels)) {
      relightGeneral(p, *chunk, s, origin, beyond, tops, channel);
    } else {
      // Face cells light the cells beyond them where those are darker.
      p.replaceLevels(r, origin.pos, levels.data());
      for (int d = 0; d < 6; ++d) {
        if (!beyond[d].ref) continue;
        const NibbleArray& n = *beyond[d].ref->layer;
        if (n.isUniform() && n.uniformLevel() >= 14) continue;
        for (const light::FaceCell& c : light::kFaceCells[static_cast<std::size_t>(d)]) {
          const std::uint8_t level = levels[c.ours];
          if (level > 1 && n.get(c.theirs) + 1 < level) {
            p.increase(Propagator::posOf(origin.pos, c.ours), level, static_cast<std::uint8_t>(1 << d));
          }
        }
      }
    }
    p.run();
  }
  stats_.blockReads += solver.reads();
}

// Every cell gets its own level; light that left the section through a face cell that lost some is
// removed outside. Then every source inside and the light just outside each face offer their light
// again, through the general flood fill, which crosses the faces both ways.
void LightEngine::relightGeneral(light::Propagator& p, const Chunk& chunk, const SectionPos& s, const Cell& origin,
                                 const Cell* beyond, const std::array<int, 256>& tops, LightChannel channel) {
  const int y0 = kMinY + s.section * 16;
  auto& levels = solver_->levels();
  ownLevels(chunk, s.section, channel, levels.data());
  p.replaceLevels(*origin.ref, origin.pos, levels.data());
  const bool emitters = chunk.light().emitters[static_cast<std::size_t>(s.section)] > 0;
  forSources(levels.data(), channel, emitters, tops, chunk.light().skyTop, y0, [&](int i) {
    p.increase(Propagator::posOf(origin.pos, i), levels[static_cast<std::size_t>(i)], kAllDirections);
  });
  for (int d = 0; d < 6; ++d) {
    if (!beyond[d].ref) continue;
    const NibbleArray& n = *beyond[d].ref->layer;
    const auto toward = static_cast<std::uint8_t>(1 << light::opposite(d));
    for (const light::FaceCell& c : light::kFaceCells[static_cast<std::size_t>(d)]) {
      const std::uint8_t level = n.get(c.theirs);
      if (level > 1 && levels[c.ours] + 1 < level) p.increase(Propagator::posOf(beyond[d].pos, c.theirs), level, toward);
    }
  }
}

}  // namespace terrasol
