#pragma once
// Light levels, block and sky alike: 0 (dark) to kMaxLight, as in Minecraft. A level fits a nibble.

namespace terrasol {

inline constexpr int kMaxLight = 15;  // a light source's level, and the open sky's
inline constexpr int kLightLevels = kMaxLight + 1;
inline constexpr int kLightMask = kMaxLight;  // a level's bits in a nibble or a packed field
static_assert((kLightLevels & kMaxLight) == 0, "levels fill a whole number of bits");

}  // namespace terrasol
