// Dynamic resolution (render/dynamic_resolution.h) against a model of frame cost: a fixed part and
// one that goes with the pixels, the square of the scale.
#include "render/dynamic_resolution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace terrasol {
namespace {

struct Flight {
  int steps = 0;        // scale changes over the last frames
  double meanMs = 0.0;  // over the last frames
  float lowest = 1.0f, last = 1.0f;
};

// `frames` frames of cost fixed + perPixel * scale², with multiplicative noise of +-`noise`.
Flight fly(double fixed, double perPixel, double targetFps, double noise, int frames = 400,
           int counted = 200) {
  DynamicResolution dr;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(1.0 - noise, 1.0 + noise);
  Flight run;
  float scale = dr.scale();
  for (int i = 0; i < frames; ++i) {
    const double ms = (fixed + perPixel * scale * scale) * jitter(rng);
    const float next = dr.update(ms, targetFps);
    if (i >= frames - counted) {
      run.steps += next != scale;
      run.meanMs += ms / counted;
    }
    scale = next;
    run.lowest = std::min(run.lowest, scale);
  }
  run.last = scale;
  return run;
}

TEST(DynamicResolution, HoldsTheTargetWithoutOscillating) {
  // 48 ms at full scale against a 33.3 ms budget: settles inside the band and stays there.
  const Flight r = fly(8.0, 40.0, 30.0, 0.10);
  EXPECT_LT(r.last, 0.95f);
  EXPECT_GE(r.meanMs, 1000.0 / 30.0 * DynamicResolution::kUnder);
  EXPECT_LE(r.meanMs, 1000.0 / 30.0 * DynamicResolution::kOver);
  EXPECT_LE(r.steps, 4) << "a settled scale moves rarely, even with 10 % noise";
}

TEST(DynamicResolution, StaysAtFullScaleWhenFramesAreCheapAndNeverLeavesItsRange) {
  EXPECT_EQ(fly(5.0, 10.0, 30.0, 0.1).last, 1.0f);
  const Flight heavy = fly(10.0, 5000.0, 60.0, 0.0);
  EXPECT_EQ(heavy.last, DynamicResolution::kMinScale) << "as low as it goes, no lower";
  EXPECT_EQ(heavy.lowest, DynamicResolution::kMinScale);
  // A frame that costs nothing, then a run of invalid times: nothing moves past the bounds or breaks.
  DynamicResolution dr(0.75f);
  EXPECT_EQ(dr.scale(), 0.75f);
  for (double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), -5.0}) {
    EXPECT_EQ(dr.update(bad, 30.0), 0.75f);
    EXPECT_EQ(dr.update(20.0, bad), 0.75f);
  }
  for (int i = 0; i < 100; ++i) dr.update(0.0, 30.0);
  EXPECT_EQ(dr.scale(), 0.75f) << "the player's render scale caps it";
}

}  // namespace
}  // namespace terrasol
