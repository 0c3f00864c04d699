#pragma once
// A chunk's blocks as bytes, for saves. Block states are stored through a palette of their names
// ("stone", "oak_log[axis=x]"), so a save survives states being renumbered between versions, and a
// name saved before its block had properties opens as the block's default state.
//
// Uncompressed layout (little-endian), then compressed with zstd as one frame:
//   u8 version (2; 1 is read too, its two renamed snow blocks renamed)
//   u16 palette size N, then N x (u8 length, name bytes)
//   24 sections bottom to top: u8 kind; kind 0 (uniform): u16 palette index;
//                                    kind 1 (dense): 4096 x u16 palette index in Section::index order

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "world/block_registry.h"
#include "world/chunk.h"

namespace terrasol {

std::vector<std::uint8_t> encodeChunk(const Chunk& chunk, const BlockRegistry& blocks);

// Throws Error saying what is wrong (bad frame, wrong size, palette index out of range). Names of
// blocks not in the registry become air, unknown properties or values the block's default state; both
// are listed in `unknownBlocks` when it is given.
std::unique_ptr<Chunk> decodeChunk(ChunkPos pos, const std::uint8_t* data, std::size_t size,
                                   const BlockRegistry& blocks,
                                   std::vector<std::string>* unknownBlocks = nullptr);

}  // namespace terrasol
