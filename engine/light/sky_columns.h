#pragma once
// The open sky over a chunk, column by column: where each column's sky light starts, the open sky
// filled in above it, and how high each column's open sky borders a darker neighbour (where sky light
// spreads sideways). Used when a chunk is lit and when one of its sections is relit.

#include <array>
#include <cstdint>

#include "world/chunk.h"
#include "world/world.h"

namespace terrasol::light {

inline constexpr int kHorizontal[4] = {0, 1, 4, 5};  // West, East, North, South

// How a block ends the open sky column, by block id: not at all (0), at itself, or below itself (only
// its bottom is closed to light: the sky's light fills it and goes no lower).
inline constexpr std::uint8_t kStopsAt = 1, kStopsBelow = 2;
// The highest cell out of the sky's reach when a block that `stop`s is at `y`.
constexpr int skyTopUnder(std::uint8_t stop, int y) {
  return stop == kStopsBelow ? y - 1 : y;
}

// Each column's highest cell out of the sky's reach, from the highest block where `stops` is not 0.
// Uniform sections are skipped whole.
void computeSkyTops(const Chunk& chunk, const std::uint8_t* stops, ChunkLight& light);
// Sky light kMaxLight above each column's top, 0 elsewhere; whole sections stay uniform where they can.
void fillOpenSky(ChunkLight& light);
// For each column of a chunk: the highest sky top among its four horizontal neighbours (in this
// chunk or the next; unlit neighbours do not count, they take no light), at least its own top + 1.
// Open-sky cells up to that height border a darker cell, so sky light spreads from them.
std::array<int, kChunkArea> spreadTops(const World& world, const Chunk& chunk);

}  // namespace terrasol::light
