#pragma once
// Minecraft's sound events from resource packs (assets/<namespace>/sounds.json): each event
// ("block.stone.break") a weighted list of sound files or other events, with volume, pitch, streaming
// and the distance it carries. Packs stack as Minecraft stacks them: a pack's event adds its sounds to
// those below unless it says "replace"; its subtitle wins. Bad files and entries are reported with the
// file and key and left out; the rest still plays. Plain C++: the audio engine plays what `pick` says.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "assets/resource_pack.h"

namespace terrasol {

inline constexpr float kDefaultSoundReach = 16.0f;  // blocks: attenuation_distance when none is given

struct SoundEntry {
  std::string name;    // "minecraft:dig/stone1" (a file under sounds/, without ".ogg"), or an event's
  bool event = false;  // "type": "event": the name is another event, picked from in turn
  float volume = 1.0f, pitch = 1.0f;
  int weight = 1;
  bool stream = false;               // long (music, records): streamed, not loaded whole
  float reach = kDefaultSoundReach;  // attenuation_distance, blocks
};

struct SoundEvent {
  std::vector<SoundEntry> sounds;
  std::optional<std::string> subtitle;  // a translation key, kept for subtitles
};

// One sound to play: the pack path of its file, and its volume and pitch (the entries' on the way,
// multiplied).
struct SoundPick {
  std::string file;  // "assets/minecraft/sounds/dig/stone1.ogg"
  float volume = 1.0f, pitch = 1.0f;
  bool stream = false;
  float reach = kDefaultSoundReach;
};

class SoundEvents {
 public:
  // Every pack's sounds.json, bottom to top (namespace minecraft). Problems are appended, each naming
  // its file and key.
  static SoundEvents load(const PackStack& packs, std::vector<std::string>& problems);

  // One pack's sounds.json over what is there; `file` names it in problems.
  void merge(std::string_view text, const std::string& file, std::vector<std::string>& problems);

  const SoundEvent* find(std::string_view event) const;
  std::size_t size() const { return events_.size(); }

  // A sound of `event` chosen by weight with `random` (any 32 bits; the caller's generator), events
  // named by entries followed. None when the event is unknown or names nothing playable (an empty
  // list, or events that only name each other).
  std::optional<SoundPick> pick(std::string_view event, std::uint32_t random) const;
  // Every file `event` can play, events named by entries followed; `streamed` ones too or not.
  std::vector<std::string> files(std::string_view event, bool streamed = false) const;

 private:
  std::map<std::string, SoundEvent, std::less<>> events_;
};

// A sound entry's file in a pack: "minecraft:dig/stone1" or "dig/stone1" is
// "assets/minecraft/sounds/dig/stone1.ogg".
std::string soundFile(std::string_view name);

}  // namespace terrasol
