#include "ambience.h"

#include <algorithm>
#include <cmath>

#include "world/liquid.h"

namespace terrasol {
namespace {

constexpr float kWindFollow = 0.05f;  // of the way to the wind's target gain each tick: ~1 s to settle

BlockPos cellOf(glm::dvec3 p) {
  return BlockPos::containing(p.x, p.y, p.z);
}
float unit(std::mt19937& random) {
  return std::uniform_real_distribution<float>(0.0f, 1.0f)(random);
}

SoundCue ambientCue(std::string_view event, glm::vec3 at, bool positional, std::int64_t tick) {
  SoundCue c;
  c.sound.event = std::string(event);
  c.sound.at = at;
  c.sound.positional = positional;
  c.sound.category = SoundCategory::Ambient;
  c.tick = tick;
  return c;
}

}  // namespace

void Ambience::tick(const World& world, const LightEngine& light, const BlockSoundTable& sounds,
                    glm::dvec3 eye, std::int64_t tick, std::mt19937& random, std::vector<SoundCue>& out) {
  const bool under = underWater(world, eye);
  if (started_ && under != underwater_)
    out.push_back(ambientCue(under ? kEnterWaterEvent : kLeaveWaterEvent, {}, false, tick));
  underwater_ = under;
  started_ = true;

  const float sky = light.lightAt(cellOf(eye), LightChannel::Sky) / 15.0f;
  const float height = static_cast<float>(std::clamp((eye.y - kWindLow) / (kWindHigh - kWindLow), 0.0, 1.0));
  const float target = under ? 0.0f : height * sky * sky;
  wind_ += (target - wind_) * kWindFollow;
  if (wind_ < 1e-3f && target == 0.0f) wind_ = 0.0f;

  caveMood(light, eye, tick, random, out);
  fluids(world, sounds, eye, tick, random, out);
}

void Ambience::caveMood(const LightEngine& light, glm::dvec3 eye, std::int64_t tick, std::mt19937& random,
                        std::vector<SoundCue>& out) {
  std::uniform_int_distribution<int> offset(-kMoodReach, kMoodReach);
  const BlockPos at = cellOf(eye).offset(offset(random), offset(random), offset(random));
  const int sky = light.lightAt(at, LightChannel::Sky);
  if (sky > 0)
    mood_ -= sky / 15.0f * 0.001f;
  else
    mood_ -= static_cast<float>(light.lightAt(at, LightChannel::Block) - 1) / kMoodTicks;
  if (mood_ < 1.0f) {
    mood_ = std::clamp(mood_, 0.0f, 1.0f);
    return;
  }
  // Heard from beyond the dark cell, 2 blocks farther along the line from the player.
  const glm::dvec3 to = glm::dvec3(at.x + 0.5, at.y + 0.5, at.z + 0.5) - eye;
  const double d = std::max(glm::length(to), 1e-3);
  out.push_back(ambientCue(kCaveEvent, glm::vec3(eye + to / d * (d + 2.0)), true, tick));
  mood_ = 0.0f;
}

void Ambience::fluids(const World& world, const BlockSoundTable& sounds, glm::dvec3 eye, std::int64_t tick,
                      std::mt19937& random, std::vector<SoundCue>& out) {
  std::uniform_int_distribution<int> offset(-kFluidReach + 1, kFluidReach - 1);
  const BlockPos centre = cellOf(eye);
  for (int i = 0; i < kFluidSamples; ++i) {
    const BlockPos at = centre.offset(offset(random), offset(random), offset(random));
    const BlockId state = world.getBlock(at);
    const glm::vec3 middle(at.x + 0.5f, at.y + 0.5f, at.z + 0.5f);
    if (sounds.flowingWater(state) && random() % 64 == 0) {
      SoundCue c = ambientCue(kWaterEvent, middle, true, tick);
      c.sound.category = SoundCategory::Blocks;
      c.sound.volume = 0.75f + unit(random) * 0.25f;
      c.sound.pitch = 0.5f + unit(random);
      out.push_back(std::move(c));
    } else if (sounds.lava(state) && world.getBlock(at.offset(0, 1, 0)) == kAir) {
      for (const auto& [event, chance] : {std::pair{kLavaPopEvent, 100u}, std::pair{kLavaEvent, 200u}}) {
        if (random() % chance != 0) continue;
        SoundCue c = ambientCue(event, middle, true, tick);
        c.sound.category = SoundCategory::Blocks;
        c.sound.volume = 0.2f + unit(random) * 0.2f;
        c.sound.pitch = 0.9f + unit(random) * 0.15f;
        out.push_back(std::move(c));
      }
    }
  }
}

}  // namespace terrasol
