#include "core/lightmap.h"

#include <algorithm>

namespace terrasol {
namespace {

// Light that reaches even a fully dark cave, so level 0/0 is near black rather than a hole in the picture
// (vanilla keeps a small minimum too).
constexpr float kAmbient = 0.02f;

// Torches and lava: warm, so block light reads differently from daylight.
const glm::vec3 kBlockLightColor(1.0f, 0.85f, 0.6f);

// Moonlit sky light is a little blue. The tint grows as skyBrightness falls to its night value.
const glm::vec3 kNightSkyTint(0.80f, 0.88f, 1.0f);

// Flicker: smooth value noise over ticks, a fresh hashed value every kFlickerStepTicks eased into the next,
// dimming block light by up to kFlickerDepth. Pure integer hashing, so any tick gives the same answer every
// time and huge ticks lose no precision.
constexpr std::int64_t kFlickerStepTicks = 4;
constexpr float kFlickerDepth = 0.05f;

// splitmix64's finaliser: a well-mixed hash of one integer, mapped to [0, 1).
float hashUnit(std::uint64_t key) {
  key += 0x9e3779b97f4a7c15ull;
  key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ull;
  key = (key ^ (key >> 27)) * 0x94d049bb133111ebull;
  key ^= key >> 31;
  return static_cast<float>(key >> 40) / static_cast<float>(1ull << 24);
}

float blockFlicker(std::int64_t ticks) {
  std::int64_t step = ticks / kFlickerStepTicks;
  std::int64_t into = ticks % kFlickerStepTicks;
  if (into < 0) {  // floor division for negative ticks
    step -= 1;
    into += kFlickerStepTicks;
  }
  const float t = glm::smoothstep(0.0f, 1.0f, static_cast<float>(into) / kFlickerStepTicks);
  const std::uint64_t key = static_cast<std::uint64_t>(step);  // unsigned: key + 1 cannot overflow
  const float noise = glm::mix(hashUnit(key), hashUnit(key + 1), t);
  return 1.0f - kFlickerDepth * noise;
}

// Sky light per unit brightness: skyBrightness, tinted blue by how far it has fallen towards night.
glm::vec3 skyLightColor(const DayState& day) {
  const float brightness = std::clamp(day.skyBrightness, 0.0f, 1.0f);
  const float night = std::clamp((1.0f - brightness) / (1.0f - kNightSkyBrightness), 0.0f, 1.0f);
  return glm::mix(glm::vec3(1.0f), kNightSkyTint, night) * brightness;
}

}  // namespace

glm::vec3 Lightmap::at(int block, int sky) const {
  const int b = std::clamp(block, 0, kSize - 1);
  const int s = std::clamp(sky, 0, kSize - 1);
  return texels[static_cast<std::size_t>(s * kSize + b)];
}

float lightLevelBrightness(int level) {
  const float f = static_cast<float>(std::clamp(level, 0, kMaxLight)) / kMaxLight;
  return f / (4.0f - 3.0f * f);
}

LightmapColours lightmapColours(const DayState& day, std::int64_t ticks) {
  return {skyLightColor(day), kBlockLightColor * blockFlicker(ticks), kAmbient};
}

// Sky and block light add, as in vanilla, then clamp: a torch in daylight changes nothing, one at night
// lights its surroundings warmly. Each term grows with its level, so the table is monotonic in both axes.
Lightmap buildLightmap(const DayState& day, std::int64_t ticks) {
  const LightmapColours c = lightmapColours(day, ticks);
  Lightmap map{};
  for (int s = 0; s < Lightmap::kSize; ++s) {
    for (int b = 0; b < Lightmap::kSize; ++b) {
      const glm::vec3 light = c.floor + c.sky * lightLevelBrightness(s) + c.block * lightLevelBrightness(b);
      map.texels[static_cast<std::size_t>(s * Lightmap::kSize + b)] = glm::clamp(light, 0.0f, 1.0f);
    }
  }
  return map;
}

}  // namespace terrasol
