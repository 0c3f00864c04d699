#pragma once
// Minecraft's palette entries ({Name, Properties}) as the registry's states. Names may carry
// "minecraft:" or not; names Minecraft changed since 1.13 are read by the chunk's DataVersion
// (1.13's stone_slab is today's smooth_stone_slab, its sign is oak_sign, a filled cauldron of 1.16 is
// water_cauldron); a property or value the block lacks is dropped, keeping the default, and counted;
// a name nothing knows (a mod's block) becomes `placeholder`. Air of every kind is kAir.
// One mapper per thread: it caches what it has mapped.

#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "world/block_registry.h"

namespace terrasol {

using StateProperties = std::vector<std::pair<std::string, std::string>>;

struct MappedState {
  BlockId id = kAir;
  bool known = true;          // false: the placeholder stands in
  int droppedProperties = 0;  // properties or values the block lacks
};

class BlockStateMapper {
 public:
  BlockStateMapper(const BlockRegistry& blocks, BlockId placeholder);

  MappedState map(std::string_view name, const StateProperties& properties, int dataVersion);

 private:
  MappedState resolve(std::string_view name, const StateProperties& properties, int dataVersion) const;

  const BlockRegistry& blocks_;
  BlockId placeholder_;
  std::unordered_map<std::string, MappedState> cache_;
};

}  // namespace terrasol
