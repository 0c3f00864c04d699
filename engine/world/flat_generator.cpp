#include <charconv>

#include "core/error.h"
#include "world/block_grid_generator.h"
#include "world/generator.h"
#include "world/terrain_generator.h"

namespace terrasol {
namespace {

class VoidGenerator final : public ChunkGenerator {
 public:
  void generate(Chunk&) const override {}
  int surfaceHeight(int, int) const override { return kMinY - 1; }
};

// Layers stacked from y = 0 upwards. Sections that end up one block throughout are compacted back to
// uniform, so the 59 layers of stone cost no block memory.
class FlatGenerator final : public ChunkGenerator {
 public:
  explicit FlatGenerator(std::vector<FlatLayer> layers) : layers_(std::move(layers)) {}

  void generate(Chunk& chunk) const override {
    int y = 0;
    for (const auto& layer : layers_) {
      for (int i = 0; i < layer.thickness && y < kMaxY; ++i, ++y) {
        auto& blocks = chunk.section(sectionOf(y)).mutableBlocks();
        const auto base = blocks.begin() + Section::index(0, localOf(y), 0);
        std::fill(base, base + kChunkArea, layer.block);  // one layer
      }
    }
    chunk.compact();
  }

  int surfaceHeight(int, int) const override {
    int top = 0;
    for (const auto& layer : layers_) top += layer.thickness;
    return std::min(top, kMaxY) - 1;
  }

 private:
  std::vector<FlatLayer> layers_;
};

}  // namespace

std::vector<FlatLayer> parseFlatLayers(const std::string& text, const BlockRegistry& blocks) {
  std::vector<FlatLayer> layers;
  std::size_t start = 0;
  int total = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    std::string entry = text.substr(start, end - start);
    const std::string where = "flat layers '" + text + "', entry '" + entry + "'";
    FlatLayer layer;
    if (const auto star = entry.find('*'); star != std::string::npos) {
      const auto [p, ec] = std::from_chars(entry.data(), entry.data() + star, layer.thickness);
      if (ec != std::errc() || p != entry.data() + star || layer.thickness < 1) {
        throw Error(where + ": expected COUNT*block with COUNT >= 1");
      }
      entry = entry.substr(star + 1);
    }
    if (entry.starts_with("minecraft:")) entry = entry.substr(10);
    bool found = false;
    layer.block = blocks.find(entry, &found);
    if (!found) throw Error(where + ": unknown block '" + entry + "'");
    total += layer.thickness;
    if (total > kMaxY) throw Error(where + ": layers rise above the world top y = " + std::to_string(kMaxY));
    layers.push_back(layer);
    start = end + 1;
  }
  return layers;
}

std::vector<FlatLayer> defaultFlatLayers(const BlockRegistry& blocks) {
  return parseFlatLayers("bedrock,59*stone,3*dirt,grass_block", blocks);
}

std::unique_ptr<ChunkGenerator> makeGenerator(const GeneratorSettings& settings,
                                              const BlockRegistry& blocks) {
  if (settings.type == "void") return std::make_unique<VoidGenerator>();
  if (settings.type == "flat") {
    return std::make_unique<FlatGenerator>(settings.flatLayers.empty() ? defaultFlatLayers(blocks)
                                                                       : settings.flatLayers);
  }
  if (settings.type == "terrain") return std::make_unique<TerrainGenerator>(settings.seed, blocks);
  if (settings.type == "blocks" || settings.type == "lights")
    return makeBlockGridGenerator(blocks, settings.type == "lights");
  throw Error("unknown generator '" + settings.type + "', expected void, flat, terrain, blocks or lights");
}

}  // namespace terrasol
