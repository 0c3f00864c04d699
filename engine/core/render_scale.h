#pragma once
// The fractions of the target's size that the scene (render.scale) and the reflection march
// (reflections.resolution_scale) may be drawn at, both clamped to this range.

namespace terrasol {

inline constexpr float kMinRenderScale = 0.25f;
inline constexpr float kMaxRenderScale = 1.0f;

}  // namespace terrasol
