#include "render/dynamic_resolution.h"

#include <algorithm>
#include <cmath>

namespace terrasol {
namespace {

float clampScale(float scale, float maxScale) {
  return std::clamp(scale, DynamicResolution::kMinScale, maxScale);
}

}  // namespace

DynamicResolution::DynamicResolution(float maxScale)
    : maxScale_(std::clamp(maxScale, kMinScale, 1.0f)), scale_(maxScale_) {}

void DynamicResolution::setMaxScale(float maxScale) {
  maxScale_ = std::clamp(std::isfinite(maxScale) ? maxScale : 1.0f, kMinScale, 1.0f);
  scale_ = clampScale(scale_, maxScale_);
}

float DynamicResolution::update(double frameMs, double targetFps) {
  if (!std::isfinite(frameMs) || frameMs < 0.0 || !std::isfinite(targetFps) || targetFps <= 0.0)
    return scale_;
  smoothedMs_ = smoothedMs_ == 0.0 ? frameMs : smoothedMs_ + (frameMs - smoothedMs_) * 0.25;
  if (++sinceStep_ < kSettleFrames) return scale_;
  const double budget = 1000.0 / targetFps;
  // Most of a frame's cost goes with its pixels, the square of the scale: aim for the budget's
  // middle, moving at most a few steps at once.
  const auto toward = [&](double wanted) {
    const float target = static_cast<float>(scale_ * std::sqrt(wanted / std::max(smoothedMs_, 1e-3)));
    return std::clamp(target, scale_ - 3.0f * kStep, scale_ + 2.0f * kStep);
  };
  float next = scale_;
  if (smoothedMs_ > budget * kOver) {
    next = std::floor(toward(budget * 0.95) / kStep) * kStep;
    next = std::min(next, scale_ - kStep);
  } else if (smoothedMs_ < budget * kUnder && scale_ < maxScale_) {
    next = std::ceil(toward(budget * 0.9) / kStep) * kStep;
    next = std::max(next, scale_ + kStep);
  }
  next = clampScale(next, maxScale_);
  if (next != scale_) {
    scale_ = next;
    sinceStep_ = 0;
  }
  return scale_;
}

}  // namespace terrasol
