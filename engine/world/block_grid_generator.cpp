#include "world/block_grid_generator.h"

#include <cmath>

namespace terrasol {
namespace {

// The room's walls stand this far outside the grid; its ceiling this high above the floor.
constexpr int kMargin = 3;
constexpr int kRoomHeight = 6;

BlockId brightestState(const BlockRegistry& blocks, const BlockType& type) {
  BlockId best = type.defaultState;
  for (std::uint16_t s = 0; s < type.stateCount; ++s) {
    const auto state = static_cast<BlockId>(type.firstState + s);
    if (blocks.emissions()[state] > blocks.emissions()[best]) best = state;
  }
  return best;
}

class BlockGridGenerator final : public ChunkGenerator {
 public:
  BlockGridGenerator(BlockGrid grid, const BlockRegistry& blocks)
      : grid_(std::move(grid)),
        bedrock_(blocks.id("bedrock")),
        stone_(blocks.id("stone")),
        dirt_(blocks.id("dirt")),
        grass_(blocks.id("grass_block")) {}

  void generate(Chunk& chunk) const override {
    const int x0 = chunk.pos().minBlockX(), z0 = chunk.pos().minBlockZ();
    for (int lz = 0; lz < kChunkSize; ++lz) {
      for (int lx = 0; lx < kChunkSize; ++lx) {
        const int x = x0 + lx, z = z0 + lz;
        chunk.set(lx, 0, lz, bedrock_);
        for (int y = 1; y < 60; ++y) chunk.set(lx, y, lz, stone_);
        for (int y = 60; y < BlockGrid::kFloorY; ++y) chunk.set(lx, y, lz, dirt_);
        chunk.set(lx, BlockGrid::kFloorY, lz, grid_.room ? stone_ : grass_);
        if (grid_.room) buildRoom(chunk, lx, lz, x, z);
        if (x < 0 || z < 0 || x % BlockGrid::kSpacing != 0 || z % BlockGrid::kSpacing != 0) continue;
        const int column = x / BlockGrid::kSpacing;
        if (column >= grid_.columns) continue;
        const std::size_t i = static_cast<std::size_t>(z / BlockGrid::kSpacing * grid_.columns + column);
        if (i < grid_.states.size()) chunk.set(lx, BlockGrid::kFloorY + 1, lz, grid_.states[i]);
      }
    }
    chunk.compact();
  }

  int surfaceHeight(int x, int z) const override {
    return grid_.room && inRoom(x, z, kMargin) ? BlockGrid::kFloorY + kRoomHeight : BlockGrid::kFloorY;
  }

 private:
  bool inRoom(int x, int z, int margin) const {
    return x >= -margin && z >= -margin && x < grid_.width() + margin && z < grid_.depth() + margin;
  }

  void buildRoom(Chunk& chunk, int lx, int lz, int x, int z) const {
    if (!inRoom(x, z, kMargin)) return;
    const bool wall = !inRoom(x, z, kMargin - 1);
    for (int y = BlockGrid::kFloorY + 1; y < BlockGrid::kFloorY + kRoomHeight; ++y)
      if (wall) chunk.set(lx, y, lz, stone_);
    chunk.set(lx, BlockGrid::kFloorY + kRoomHeight, lz, stone_);
  }

  BlockGrid grid_;
  BlockId bedrock_, stone_, dirt_, grass_;
};

}  // namespace

BlockGrid BlockGrid::of(const BlockRegistry& blocks, bool lightsOnly) {
  BlockGrid grid;
  grid.room = lightsOnly;
  for (std::size_t b = 1; b < blocks.blockCount(); ++b) {
    const BlockType& type = blocks.block(b);
    if (type.shape == BlockShape::None) continue;
    BlockId state = lightsOnly ? brightestState(blocks, type) : type.defaultState;
    if (lightsOnly && blocks.emissions()[state] == 0) continue;
    state = blocks.with(state, "waterlogged", "false").value_or(state);
    grid.states.push_back(state);
  }
  grid.columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(grid.states.size())))));
  return grid;
}

BlockPos BlockGrid::at(std::size_t i) const {
  const int n = static_cast<int>(i);
  return {n % columns * kSpacing, kFloorY + 1, n / columns * kSpacing};
}

int BlockGrid::depth() const {
  const int rows = (static_cast<int>(states.size()) + columns - 1) / columns;
  return (std::max(rows, 1) - 1) * kSpacing + 1;
}

std::unique_ptr<ChunkGenerator> makeBlockGridGenerator(const BlockRegistry& blocks, bool lightsOnly) {
  return std::make_unique<BlockGridGenerator>(BlockGrid::of(blocks, lightsOnly), blocks);
}

}  // namespace terrasol
