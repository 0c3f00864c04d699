#pragma once
// When music plays, as Minecraft times it: the first track 100 ticks (5 s) into the game, then,
// after each track ends, a quiet of 12 000 to 24 000 ticks (10 to 20 minutes) before the next. By
// day the track is from "music.game"; by night from "music.game.night" where the packs have it.
// Plain C++.

#include <cstdint>
#include <optional>
#include <random>
#include <string_view>

namespace terrasol {

class MusicTimer {
 public:
  static constexpr int kFirstDelay = 100, kMinDelay = 12000, kMaxDelay = 24000;  // ticks
  static constexpr std::string_view kDay = "music.game", kNight = "music.game.night";

  // Whether world time `ticks` is night for music: Minecraft's monsters' hours, 13 000 to 23 000.
  static bool night(std::int64_t ticks);
  // One tick; `playing`: a track still plays. The event to start a track of now, if it is time.
  std::optional<std::string_view> tick(bool playing, bool night, std::mt19937& random);
  int delay() const { return delay_; }

 private:
  int delay_ = kFirstDelay;
  bool wasPlaying_ = false;
};

}  // namespace terrasol
