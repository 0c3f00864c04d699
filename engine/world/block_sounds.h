#pragma once
// Which sounds a block makes: its sound group ("stone", "wood", "gravel"...), Minecraft's SoundType,
// whose events are "block.<group>.break", ".place", ".step", ".hit" and ".fall". Minecraft sets one
// per block in code; Terrasol derives it from the block's name by the same families (every plank,
// stair and door of a wood is "wood", of cherry "cherry_wood"; dirt and clay "gravel"; ice "glass"),
// so blocks of any pack and of Minecraft saves sound as players know them. Each group also names
// the plain group it sounds like ("deepslate" like "stone"): what plays where a pack stack has no
// event of the group itself. Plain C++.

#include <span>
#include <string_view>

namespace terrasol {

struct SoundGroup {
  std::string_view name;
  std::string_view like;  // a group whose `like` is itself: the plain groups every pack should carry
};

// Every group blockSoundGroup answers.
std::span<const SoundGroup> soundGroups();

// The sound group of the block named `name` ("minecraft:" optional). A name no family claims is
// "stone", Minecraft's default; fluids, air and the like are "empty", which makes no sound.
const SoundGroup& blockSoundGroup(std::string_view name);

inline constexpr std::string_view kSilentSoundGroup = "empty";

// Doors, trapdoors and gates open and close with their own events ("block.wooden_door.open",
// ".close"); the kind of block `name`, empty when it has none.
std::string_view openSoundKind(std::string_view name);

}  // namespace terrasol
