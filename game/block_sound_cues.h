#pragma once
// The sounds blocks make, per state, worked out once for a block registry: each block's sound group
// (world/block_sounds.h) and open/close kind, which states are flowing water or lava, and
// Minecraft's volume and pitch for each action (a step is quiet, a break carries). Plain C++.

#include <optional>
#include <string_view>
#include <vector>

#include "sound_cue.h"
#include "world/block_registry.h"
#include "world/block_sounds.h"
#include "world/coords.h"

namespace terrasol {

enum class BlockAction : std::uint8_t { Break, Place, Step, Hit, Fall };

class BlockSoundTable {
 public:
  explicit BlockSoundTable(const BlockRegistry& blocks);

  const SoundGroup& group(BlockId state) const { return *groups_[blocks_->blockIndex(state)]; }
  bool silent(BlockId state) const { return group(state).name == kSilentSoundGroup; }
  bool flowingWater(BlockId state) const { return flowingWater_[state] != 0; }
  bool lava(BlockId state) const { return lava_[state] != 0; }

  // `action` on the block in `state` in cell `at`, at tick `tick`; none for a silent block.
  std::optional<SoundCue> cue(BlockId state, const BlockPos& at, BlockAction action, std::int64_t tick) const;
  // What changing cell `at` from `before` to `after` sounds like: breaking, placing, or a door,
  // trapdoor or gate opening or closing. None when nothing is heard.
  std::optional<SoundCue> editCue(BlockId before, BlockId after, const BlockPos& at, std::int64_t tick) const;

 private:
  const BlockRegistry* blocks_;
  std::vector<const SoundGroup*> groups_;                 // per block index
  std::vector<std::string_view> openKinds_;               // per block index, empty for none
  std::vector<std::uint8_t> flowingWater_, lava_, open_;  // per state
};

}  // namespace terrasol
