#include <algorithm>
#include <cstring>

#include "light/level_words.h"
#include "light/light_engine.h"
#include "light/light_frame.h"
#include "light/propagator.h"
#include "light/section_solver.h"
#include "light/sky_columns.h"

// Relighting one section after its blocks changed (LightEngine::relightSection): solved in bytes
// inside the section where it can be, else by the general flood fill.

namespace terrasol {

using light::Cell;
using light::kAllDirections;
using light::Propagator;
using light::spreadTops;

// The levels a section's cells have by themselves, a byte each: their emission, or the open sky
// column's kMaxLight (and the top layer of the world, lit from the sky above through its own opacity).
void LightEngine::ownLevels(const Chunk& chunk, int section, LightChannel channel,
                            std::uint8_t* levels) const {
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
  const int y0 = sectionMinY(section);
  for (int ly = 0; ly < kChunkSize; ++ly) {
    const int y = y0 + ly;
    for (std::size_t column = 0; column < kChunkArea; ++column)
      levels[ly * kChunkArea + column] = y > tops[column] ? kMaxLight : 0;
  }
  if (y0 + kLastCell != kMaxY - 1) return;
  constexpr int kTopLayer = kLastCell * kChunkArea;
  for (int column = 0; column < kChunkArea; ++column) {
    std::uint8_t& level = levels[kTopLayer + column];
    if (level == 0) level = light::topLayerSky(attenuation_[blocks.at(kTopLayer + column)]);
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
// has kMaxLight around it.
template <class Fn>
void forSources(const std::uint8_t* levels, LightChannel channel, bool emitters,
                const std::array<int, kChunkArea>& tops, const std::array<std::int16_t, kChunkArea>& skyTop,
                int y0, Fn&& fn) {
  if (channel == LightChannel::Block) {
    if (!emitters) return;
    for (int i = 0; i < Section::kVolume; ++i) {
      if (levels[i] > 1) fn(i);
    }
    return;
  }
  for (int column = 0; column < kChunkArea; ++column) {
    const int lo = std::max<int>(skyTop[static_cast<std::size_t>(column)] + 1, y0);
    const int hi = std::min(tops[static_cast<std::size_t>(column)], y0 + kLastCell);
    for (int y = lo; y <= hi; ++y) fn((y - y0) * kChunkArea + column);
  }
  if (y0 + kLastCell != kMaxY - 1) return;
  for (int i = kLastCell * kChunkArea; i < Section::kVolume; ++i) {
    if (levels[i] > 1 && levels[i] < kMaxLight) fn(i);  // the top layer under the sky (topLayerSky)
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
  const int x0 = s.x * kChunkSize, y0 = s.minBlockY(), z0 = s.z * kChunkSize;
  const auto tops = spreadTops(world_, *chunk);
  const light::ChunkWindow window(world_, {s.x - kReach, s.z - kReach}, {s.x + kReach, s.z + kReach});
  const Section& blocks = chunk->section(s.section);
  countSpecialCells(*chunk, s.section);  // its blocks may have changed unheard of
  const BlockId uniform = blocks.uniformBlock();
  light::SectionSolver& solver = *solver_;
  solver.begin(blocks.blocks() ? blocks.blocks()->data() : &uniform,
               blocks.blocks() ? Section::kVolume - 1 : 0, attenuation_.data());
  for (const LightChannel channel : {LightChannel::Block, LightChannel::Sky}) {
    Propagator p = propagator(window, channel);
    Cell origin;
    p.locate(x0, y0, z0, origin);
    Cell beyond[6];  // each neighbouring section's cell 0, packed; ref null where not loaded
    bool shaped = chunk->light().shaped[static_cast<std::size_t>(s.section)] > 0;
    for (int d = 0; d < 6; ++d) {
      const BlockPos& o = kDirectionOffsets[d];
      if (!p.locatePacked(x0 + o.x * kChunkSize, y0 + o.y * kChunkSize, z0 + o.z * kChunkSize, beyond[d]))
        beyond[d].ref = nullptr;
      shaped = shaped || (beyond[d].ref && *beyond[d].ref->shaped > 0);
    }
    if (shaped) {
      // The solver knows nothing of light sides: the flood fill, which does, relights the section.
      relightGeneral(p, *chunk, s, origin, beyond, tops, channel);
      p.run();
      continue;
    }

    // Every source offers its light. Open-sky cells above the neighbouring columns only have
    // kMaxLight around them and are left out.
    auto& levels = solver.levels();
    ownLevels(*chunk, s.section, channel, levels.data());
    const bool emitters = chunk->light().emitters[static_cast<std::size_t>(s.section)] > 0;
    forSources(levels.data(), channel, emitters, tops, chunk->light().skyTop, y0,
               [&](int i) { solver.seed(i); });
    for (int d = 0; d < 6; ++d) {
      if (!beyond[d].ref) continue;
      const NibbleArray& n = *beyond[d].ref->layer;
      if (n.isUniform() && n.uniformLevel() <= 1) continue;
      for (const light::FaceCell& c : light::kFaceCells[static_cast<std::size_t>(d)])
        solver.offer(c.ours, n.get(c.theirs));
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
        if (n.isUniform() && n.uniformLevel() >= kMaxLight - 1) continue;  // no face cell is two brighter
        for (const light::FaceCell& c : light::kFaceCells[static_cast<std::size_t>(d)]) {
          const std::uint8_t level = levels[c.ours];
          if (level > 1 && n.get(c.theirs) + 1 < level) {
            p.increase(Propagator::posOf(origin.pos, c.ours), level,
                       static_cast<std::uint8_t>(light::faceBit(d)));
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
void LightEngine::relightGeneral(light::Propagator& p, const Chunk& chunk, const SectionPos& s,
                                 const Cell& origin, const Cell* beyond,
                                 const std::array<int, kChunkArea>& tops, LightChannel channel) {
  const int y0 = s.minBlockY();
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
    const auto toward = static_cast<std::uint8_t>(light::faceBit(light::opposite(d)));
    for (const light::FaceCell& c : light::kFaceCells[static_cast<std::size_t>(d)]) {
      const std::uint8_t level = n.get(c.theirs);
      if (level > 1 && levels[c.ours] + 1 < level)
        p.increase(Propagator::posOf(beyond[d].pos, c.theirs), level, toward);
    }
  }
}

}  // namespace terrasol
