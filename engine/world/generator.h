#pragma once
// Chunk generators: pure functions from (settings, chunk position) to blocks. `generate` is const and
// touches no shared mutable state, so any number of worker threads call it at once, and a chunk's
// blocks never depend on which thread made it or in which order.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "world/block_registry.h"
#include "world/chunk.h"

namespace terrasol {

// A column's ground as the generator lays it before caves, trees and plants: for far terrain, which
// samples the land without making chunks.
struct SurfaceColumn {
  int height = 0;         // y of the top ground block
  BlockId top = kAir;     // the block there
  int water = kMinY - 1;  // y of the water's surface over it (ice in the snow), kMinY - 1 for none
  BlockId waterBlock = kAir;
  TintClimate climate = kPlainsTint;  // its biome's grass, leaves and water
};

// A tree's crown as far terrain sees it: the column it stands on, and its leaves as two steps: the
// narrow top (within `radius` of the trunk on each axis, up to `top`) over a wider layer (within
// `wideRadius`, up to `wideTop`).
struct TreeCrown {
  int x = 0, z = 0;
  int radius = 0, top = 0;
  int wideRadius = 0, wideTop = 0;
  BlockId leaves = kAir;
};

class ChunkGenerator {
 public:
  virtual ~ChunkGenerator() = default;
  // Fills `chunk`, which is all air on entry.
  virtual void generate(Chunk& chunk) const = 0;
  // The y of the highest block the generator puts in this column before carving (kMinY - 1 for none);
  // the game spawns the player above it.
  virtual int surfaceHeight(int x, int z) const = 0;
  // Sets the chunk's column tints (Chunk::tint); generate() does it too, and a chunk loaded from a
  // save gets them here. Worlds without biomes keep the plains tint.
  virtual void fillTints(Chunk& /*chunk*/) const {}
  // A column's ground without making its chunk, where the generator can say (far terrain).
  virtual std::optional<SurfaceColumn> surfaceColumn(int /*x*/, int /*z*/) const { return std::nullopt; }
  // The crowns of the trees generate() roots in chunk `at` (far terrain's forests).
  virtual void treeCrowns(ChunkPos /*at*/, std::vector<TreeCrown>& /*out*/) const {}
  // A source that holds finished chunks (a save) rather than a rule: whether it does, and which it
  // holds. Far terrain makes those whole where there is no column rule.
  virtual bool holdsChunks() const { return false; }
  virtual bool holdsChunk(ChunkPos /*pos*/) const { return false; }
};

struct FlatLayer {
  BlockId block = kAir;
  int thickness = 1;
};

struct GeneratorSettings {
  std::string type = "terrain";  // "void" | "flat" | "terrain" | "blocks" | "lights" (block_grid_generator.h)
  std::uint64_t seed = 0;
  std::vector<FlatLayer> flatLayers;  // for "flat", bottom first from y = 0; empty means the default
};

// Minecraft's superflat layer string, bottom first: "bedrock,59*stone,3*dirt,grass_block"
// ("minecraft:" prefixes allowed). Throws Error naming the bad entry.
std::vector<FlatLayer> parseFlatLayers(const std::string& text, const BlockRegistry& blocks);
// bedrock x1, stone x59, dirt x3, grass_block x1: the surface is y = 63, standing height y = 64.
std::vector<FlatLayer> defaultFlatLayers(const BlockRegistry& blocks);

// Throws Error for an unknown type.
std::unique_ptr<ChunkGenerator> makeGenerator(const GeneratorSettings& settings, const BlockRegistry& blocks);

}  // namespace terrasol
