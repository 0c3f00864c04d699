#include "block_sound_cues.h"

namespace terrasol {
namespace {

constexpr std::string_view kActionNames[] = {"break", "place", "step", "hit", "fall"};

// Minecraft's scaling of a sound type's volume and pitch (both 1 for nearly every type) per action.
struct ActionScale {
  float volume, pitch;
};
constexpr ActionScale kScales[] = {
    {1.0f, 0.8f},   // break: (1 + 1) / 2
    {1.0f, 0.8f},   // place
    {0.15f, 1.0f},  // step
    {0.25f, 0.5f},  // hit while digging: (1 + 1) / 8
    {0.5f, 0.75f},  // fall
};

std::string event(std::string_view group, std::string_view action) {
  return "block." + std::string(group) + "." + std::string(action);
}

}  // namespace

BlockSoundTable::BlockSoundTable(const BlockRegistry& blocks)
    : blocks_(&blocks), flowingWater_(blocks.size(), 0), lava_(blocks.size(), 0), open_(blocks.size(), 0) {
  for (std::size_t i = 0; i < blocks.blockCount(); ++i) {
    const BlockType& type = blocks.block(i);
    groups_.push_back(&blockSoundGroup(type.name));
    openKinds_.push_back(openSoundKind(type.name));
    const bool water = type.name == "water" || type.name == "minecraft:water";
    const bool isLava = type.name == "lava" || type.name == "minecraft:lava";
    const bool opens = type.opens;
    if (!water && !isLava && !opens) continue;
    for (BlockId s = type.firstState; s < type.firstState + type.stateCount; ++s) {
      const StateValues values = blocks.stateValues(s);
      const auto level = values.find("level");
      if (water) flowingWater_[s] = level != values.end() && level->second != "0";
      if (isLava) lava_[s] = 1;
      const auto open = values.find("open");
      if (opens) open_[s] = open != values.end() && open->second == "true";
    }
  }
}

std::optional<SoundCue> BlockSoundTable::cue(BlockId state, const BlockPos& at, BlockAction action,
                                             std::int64_t tick) const {
  const SoundGroup& g = group(state);
  if (g.name == kSilentSoundGroup) return std::nullopt;
  const auto a = static_cast<std::size_t>(action);
  SoundCue c;
  c.sound.event = event(g.name, kActionNames[a]);
  if (g.like != g.name) c.sound.fallback = event(g.like, kActionNames[a]);
  c.sound.at = glm::vec3(at.x + 0.5f, at.y + 0.5f, at.z + 0.5f);
  c.sound.volume = kScales[a].volume;
  c.sound.pitch = kScales[a].pitch;
  c.sound.category = SoundCategory::Blocks;
  c.tick = tick;
  return c;
}

std::optional<SoundCue> BlockSoundTable::editCue(BlockId before, BlockId after, const BlockPos& at,
                                                 std::int64_t tick) const {
  if (before == after) return std::nullopt;
  const std::size_t typeBefore = blocks_->blockIndex(before), typeAfter = blocks_->blockIndex(after);
  if (typeBefore == typeAfter && open_[before] != open_[after] && !openKinds_[typeAfter].empty()) {
    SoundCue c;
    c.sound.event = "block." + std::string(openKinds_[typeAfter]) + (open_[after] ? ".open" : ".close");
    c.sound.at = glm::vec3(at.x + 0.5f, at.y + 0.5f, at.z + 0.5f);
    c.sound.category = SoundCategory::Blocks;
    c.tick = tick;
    return c;
  }
  if (silent(after)) return cue(before, at, BlockAction::Break, tick);
  return cue(after, at, BlockAction::Place, tick);
}

}  // namespace terrasol
