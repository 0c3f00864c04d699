#pragma once
// A Minecraft chunk's NBT as a Terrasol chunk: 1.18 and later (sections[] with block_states and a
// yPos) and 1.13 to 1.17 (a Level wrapper, Sections[] with Palette and BlockStates, 0..255 high).
// Block indices are (y << 8 | z << 4 | x), packed at max(4, ceil(log2(palette))) bits a block, spanning
// two longs before 20w17a and not since; a one-entry palette may have no data. Only full chunks are
// worlds' ground: the rest (proto-chunks) are counted, not decoded.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "minecraft/block_state_mapper.h"
#include "minecraft/nbt.h"
#include "world/chunk.h"

namespace terrasol {

// The light a save keeps per section (2 048 bytes each, two cells a byte, the even index in the low
// nibble; index y << 8 | z << 4 | x), by Terrasol's section index; an empty vector where the section
// keeps none.
struct StoredLight {
  std::array<std::vector<std::uint8_t>, kSectionCount> sky, block;
  // The value the save holds: a section without an array is all 0 (Minecraft leaves empty layers out),
  // except sky light above the highest array, which is open sky (15).
  std::uint8_t skyAt(int x, int y, int z) const;
  std::uint8_t blockAt(int x, int y, int z) const;
};

struct AnvilChunk {
  int dataVersion = 0;
  std::string status;  // "minecraft:full", "full", "fullchunk", "structure_starts"...
  bool full = false;
  std::unique_ptr<Chunk> chunk;           // full chunks only
  std::size_t unknownCells = 0;           // cells drawn as the placeholder
  std::size_t droppedPropertyCells = 0;   // cells whose state lost an unknown property or value
  std::vector<std::string> unknownNames;  // sorted, once each
  // With `withLight`: the stored light of a full chunk Minecraft lit (isLightOn; any light array).
  std::optional<StoredLight> light;
};

// Whether Minecraft counts a chunk of `status` (any DataVersion) as finished.
bool isFullStatus(std::string_view status);

// Decodes `root` (a chunk's NBT root compound) for the chunk at `expected`. Throws Error starting with
// `what` when the chunk is malformed: its position disagrees with its slot, a palette index is past
// the palette, an array has the wrong length, a required tag is missing.
AnvilChunk decodeAnvilChunk(const nbt::Tag& root, ChunkPos expected, BlockStateMapper& mapper,
                            std::string_view what, bool withLight = false);

}  // namespace terrasol
