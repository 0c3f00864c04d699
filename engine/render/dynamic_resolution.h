#pragma once
// Dynamic resolution: moves the render scale (FrameInputs::renderScale) in small steps so frames hold
// a target rate. The frame time is smoothed; the scale drops when frames run over the budget and
// rises when they run well under it, with a dead band between (hysteresis) and a pause after each
// step while its effect shows, so it does not oscillate. Steps are 1/32 of the size, so the G-buffer
// is reallocated only when a step is taken. Plain C++.

namespace terrasol {

class DynamicResolution {
 public:
  static constexpr float kStep = 1.0f / 32.0f;
  static constexpr float kMinScale = 0.375f;
  static constexpr double kOver = 1.08, kUnder = 0.8;  // the dead band, as fractions of the budget
  static constexpr int kSettleFrames = 4;              // frames to wait after a step

  // `maxScale`: the highest scale it moves to (the player's render scale).
  explicit DynamicResolution(float maxScale = 1.0f);

  // After a frame of `frameMs` (the whole frame), for a target of `targetFps`: the scale for the next.
  // Invalid times (NaN, infinite, negative) are ignored.
  float update(double frameMs, double targetFps);
  float scale() const { return scale_; }
  void setMaxScale(float maxScale);

 private:
  float maxScale_, scale_;
  double smoothedMs_ = 0.0;
  int sinceStep_ = 0;
};

}  // namespace terrasol
