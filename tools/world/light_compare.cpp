#include "light_compare.h"

#include <map>
#include <set>

#include "light/light_engine.h"
#include "minecraft/minecraft_save.h"
#include "scene/block_atlas.h"
#include "world/world.h"

namespace terrasol {
namespace {

constexpr std::size_t kSamples = 400;

void compareCell(int ours, int theirs, ChannelComparison& channel, const BlockPos& pos, bool sky,
                 std::vector<LightDifference>& samples) {
  channel.equal += ours == theirs;
  ++channel.differences[static_cast<std::size_t>(ours - theirs + kMaxLight)];
  if (ours != theirs && samples.size() < kSamples) samples.push_back({pos, ours, theirs, sky});
}

}  // namespace

LightComparison compareLight(const std::filesystem::path& path, const BlockRegistry& blocks) {
  const BlockShapes shapes = defaultPackShapes(blocks);
  World world(blocks, &shapes);
  LightEngine engine(world);
  const MinecraftSave save(path);
  BlockStateMapper mapper(blocks, blocks.id("unknown_block"));
  std::map<ChunkPos, StoredLight> stored;
  std::set<ChunkPos> full;
  for (const ChunkPos pos : save.chunks()) {
    std::optional<AnvilChunk> c;
    try {
      c = save.load(pos, mapper, true);
    } catch (const Error&) {
      continue;  // damaged: `info` names it
    }
    if (!c || !c->full) continue;
    world.insertChunk(std::move(c->chunk));
    full.insert(pos);
    if (c->light) stored.emplace(pos, std::move(*c->light));
  }
  for (const ChunkPos pos : full) engine.chunkLoaded(pos);

  LightComparison out;
  for (const auto& [pos, light] : stored) {
    bool surrounded = true;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dx = -1; dx <= 1; ++dx) surrounded &= full.contains({pos.x + dx, pos.z + dz});
    if (!surrounded) continue;
    ++out.chunks;
    for (int y = kMinY; y < kMaxY; ++y)
      for (int z = 0; z < kChunkSize; ++z)
        for (int x = 0; x < kChunkSize; ++x) {
          const BlockPos at{pos.minBlockX() + x, y, pos.minBlockZ() + z};
          ++out.cells;
          compareCell(engine.lightAt(at, LightChannel::Sky), light.skyAt(x, y, z), out.sky, at, true,
                      out.samples);
          compareCell(engine.lightAt(at, LightChannel::Block), light.blockAt(x, y, z), out.block, at, false,
                      out.samples);
        }
  }
  return out;
}

}  // namespace terrasol
