// Fuzz target: a chunk as a Minecraft region file holds it, its compression type byte then its data
// (gzip, zlib, none or LZ4 blocks), inflated, parsed as NBT and decoded into a Terrasol chunk with its
// stored light. Bad input must end in terrasol::Error; anything else (a crash, another exception, a
// sanitizer report, a huge allocation) is a bug.

#include <cstddef>
#include <cstdint>
#include <span>

#include "core/error.h"
#include "core/paths.h"
#include "minecraft/anvil_chunk.h"
#include "minecraft/chunk_compression.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const terrasol::BlockRegistry blocks =
      terrasol::BlockRegistry::load(terrasol::resourcePackDir() / "default" / "blocks.json");
  if (size == 0) return 0;
  try {
    const auto compression = static_cast<terrasol::ChunkCompression>(data[0] & 0x7f);
    const std::vector<std::uint8_t> raw =
        terrasol::decompressChunk(compression, std::span(data + 1, size - 1), "fuzz chunk");
    const terrasol::nbt::Document doc = terrasol::nbt::parse(raw, "fuzz chunk");
    terrasol::BlockStateMapper mapper(blocks, terrasol::kAir);
    const terrasol::nbt::Tag* x = doc.root.find("xPos");
    const terrasol::nbt::Tag* z = doc.root.find("zPos");
    const terrasol::ChunkPos at{x && x->isInteger() ? static_cast<int>(x->integer()) : 0,
                                z && z->isInteger() ? static_cast<int>(z->integer()) : 0};
    terrasol::decodeAnvilChunk(doc.root, at, mapper, "fuzz chunk", true);
  } catch (const terrasol::Error&) {
  }
  return 0;
}
