#pragma once
// Vanilla-style block and sky light (levels 0..15), kept up to date incrementally.
//
// Rules (Minecraft Java 1.20+): an emitter has its emission at its own cell; a neighbour receives
// `level - max(1, opacity(neighbour))`, unless the side between them is a light side of either
// block (World::shapes: a slab's bottom, a stair's back). Sky light is 15 in the open sky column:
// down to the highest block of opacity >= 1 or with a light side up, and into a clear block with only
// its bottom closed (a snow layer) but not under it (ChunkLight::skyTop); from there it spreads in all
// six directions like block light. A chunk that is not loaded acts as opaque.
//
// Updates run breadth first over explicit queues, decreases before increases; every queue entry
// carries its level and the directions still to visit (Starlight's method). Main thread only, like
// the World it lights.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "light/changed_sections.h"
#include "light/light_faces.h"
#include "world/world.h"

namespace terrasol {

namespace light {
class LightFrame;
struct ChunkWindow;
class Propagator;
class SectionSolver;
struct Cell;
}  // namespace light

enum class LightChannel : std::uint8_t { Block, Sky };

struct LightStats {
  std::uint64_t blockReads = 0;   // block ids looked up during propagation
  std::uint64_t lightWrites = 0;  // light values changed
};

class LightEngine {
 public:
  explicit LightEngine(World& world);
  ~LightEngine();
  LightEngine(const LightEngine&) = delete;
  LightEngine& operator=(const LightEngine&) = delete;

  // Call after World::insertChunk: lights the chunk and lets light flow across its borders.
  void chunkLoaded(ChunkPos pos);
  // Call before World::removeChunk: takes back the light that flowed out of the chunk.
  void chunkUnloading(ChunkPos pos);
  // Call after a World::setBlock that changed something.
  void blockChanged(const BlockChange& change);
  // Recomputes one section's light from scratch, as if nothing were known about it: its light, and
  // whatever light spread from it, is removed, then refilled from sources inside and outside.
  void relightSection(const SectionPos& section);

  // Sections whose light, or the light in their one-block halo, changed since the last call: what the
  // mesher must rebuild. Each once, in no particular order.
  std::vector<SectionPos> takeChangedSections();

  // 0..15; sky light is 15 above the world, both are 0 below it and in unloaded chunks.
  std::uint8_t lightAt(const BlockPos& pos, LightChannel channel) const;

  const LightStats& stats() const { return stats_; }
  void resetStats() { stats_ = {}; }

  // 16-bit fields, not 8: a store through an 8-bit integer may alias anything, so the compiler
  // would reload every pointer and counter of the flood fill after each entry queued.
  struct Entry {
    std::uint32_t pos;  // frame position (light_frame.h)
    std::uint16_t level;
    std::uint16_t directions;  // bit d set: still to visit Direction d
  };

 private:
  static constexpr int kReach = 2;  // chunks an update can reach beyond its seeds (see light_frame.h)

  // The flood fill of one channel over `window`, on the engine's reused frame and queues.
  light::Propagator propagator(const light::ChunkWindow& window, LightChannel channel);
  void seedEmitters(light::Propagator& p, Chunk& chunk);
  // Counts section `s`'s emitters and shaped cells into ChunkLight; true when it has an emitter.
  bool countSpecialCells(Chunk& chunk, int s) const;
  void seedOpenSky(light::Propagator& p, const Chunk& chunk);
  void seedFromNeighbours(light::Propagator& p, ChunkPos pos, LightChannel channel);
  int updateSkyTop(Chunk& chunk, const BlockChange& change);
  void seedChangedCell(light::Propagator& p, const BlockPos& at, bool reshaped);
  void seedSkyColumn(light::Propagator& p, const BlockPos& at, int oldTop, int newTop);
  void ownLevels(const Chunk& chunk, int section, LightChannel channel, std::uint8_t* levels) const;
  void relightGeneral(light::Propagator& p, const Chunk& chunk, const SectionPos& s,
                      const light::Cell& origin, const light::Cell* beyond,
                      const std::array<int, kChunkArea>& tops, LightChannel channel);

  World& world_;
  light::LightFaces faces_;                // light through shaped blocks (none without shapes)
  std::vector<std::uint8_t> columnStop_;   // how a block ends the open sky column (light::kStopsAt...)
  std::vector<std::uint8_t> attenuation_;  // max(1, opacity)
  std::vector<std::uint8_t> flood_;        // the flood fill's (light::floodAttenuations)
  const std::uint8_t* emission_;
  std::vector<std::uint8_t> special_;  // per block id: 1 emits, 2 has light sides
  LightStats stats_;
  std::vector<Entry> decrease_, increase_;        // reused between updates
  std::unique_ptr<light::LightFrame> frame_;      // likewise
  std::unique_ptr<light::SectionSolver> solver_;  // likewise
  light::ChangedSections changed_;
};

}  // namespace terrasol
