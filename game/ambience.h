#pragma once
// The world's sounds round the listener, a tick at a time, by Minecraft's rules where it has them:
// cave ambience when the "mood" filled by dark places round the player is full (about 5 minutes in
// total darkness); flowing water and lava heard from random cells within 16 blocks (Minecraft's
// animate ticks: 667 a tick, water 1 in 64, lava's pop 1 in 100 and murmur 1 in 200); entering and
// leaving water. Terrasol's own: wind that rises with height under open sky. Plain C++.

#include <random>
#include <string_view>
#include <vector>

#include "block_sound_cues.h"
#include "light/light_engine.h"

namespace terrasol {

// The events it fires, and the loops the game keeps playing from its state.
inline constexpr std::string_view kCaveEvent = "ambient.cave", kWaterEvent = "block.water.ambient",
                                  kLavaPopEvent = "block.lava.pop", kLavaEvent = "block.lava.ambient",
                                  kEnterWaterEvent = "ambient.underwater.enter",
                                  kLeaveWaterEvent = "ambient.underwater.exit",
                                  kUnderwaterLoop = "ambient.underwater.loop", kWindLoop = "ambient.wind";
inline constexpr std::string_view kAmbienceEvents[] = {kCaveEvent,      kWaterEvent,      kLavaPopEvent,
                                                       kLavaEvent,      kEnterWaterEvent, kLeaveWaterEvent,
                                                       kUnderwaterLoop, kWindLoop};

class Ambience {
 public:
  static constexpr int kFluidSamples = 667, kFluidReach = 16;
  static constexpr int kMoodTicks = 6000, kMoodReach = 8;      // Minecraft's cave mood
  static constexpr double kWindLow = 90.0, kWindHigh = 150.0;  // eye heights: no wind, full wind

  void tick(const World& world, const LightEngine& light, const BlockSoundTable& sounds, glm::dvec3 eye,
            std::int64_t tick, std::mt19937& random, std::vector<SoundCue>& out);

  float mood() const { return mood_; }
  float wind() const { return wind_; }  // the wind loop's gain, 0..1
  bool underwater() const { return underwater_; }

 private:
  void caveMood(const LightEngine& light, glm::dvec3 eye, std::int64_t tick, std::mt19937& random,
                std::vector<SoundCue>& out);
  void fluids(const World& world, const BlockSoundTable& sounds, glm::dvec3 eye, std::int64_t tick,
              std::mt19937& random, std::vector<SoundCue>& out);

  float mood_ = 0.0f, wind_ = 0.0f;
  bool underwater_ = false, started_ = false;
};

}  // namespace terrasol
