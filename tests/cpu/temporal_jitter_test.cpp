// TAA's jitter sequence: Halton (2, 3), centred on the pixel, its cycle lengthened as the render scale
// falls.

#include "core/temporal_jitter.h"

#include <gtest/gtest.h>

#include <limits>

namespace terrasol {
namespace {

TEST(TemporalJitter, HaltonIsTheRadicalInverse) {
  EXPECT_FLOAT_EQ(halton(1, 2), 0.5f);
  EXPECT_FLOAT_EQ(halton(2, 2), 0.25f);
  EXPECT_FLOAT_EQ(halton(3, 2), 0.75f);
  EXPECT_FLOAT_EQ(halton(1, 3), 1.0f / 3.0f);
  EXPECT_FLOAT_EQ(halton(5, 3), 2.0f / 3.0f + 1.0f / 9.0f);  // 12 in base 3, mirrored
  EXPECT_FLOAT_EQ(halton(0, 2), 0.0f);
}

TEST(TemporalJitter, OffsetsStayInsideThePixelAndAverageToItsCentre) {
  for (const int phases : {8, 18, 64}) {
    glm::vec2 sum(0.0f);
    for (int f = 0; f < phases; ++f) {
      const glm::vec2 j = jitterAt(f, phases);
      EXPECT_GE(j.x, -0.5f);
      EXPECT_LT(j.x, 0.5f);
      EXPECT_GE(j.y, -0.5f);
      EXPECT_LT(j.y, 0.5f);
      sum += j;
    }
    EXPECT_NEAR(sum.x / static_cast<float>(phases), 0.0f, 0.07f) << phases;
    EXPECT_NEAR(sum.y / static_cast<float>(phases), 0.0f, 0.07f) << phases;
    EXPECT_EQ(jitterAt(phases, phases), jitterAt(0, phases)) << "the cycle repeats";
  }
}

TEST(TemporalJitter, MorePhasesAtASmallerScale) {
  EXPECT_EQ(jitterPhases(1.0f), 8);
  EXPECT_EQ(jitterPhases(0.5f), 32);
  EXPECT_EQ(jitterPhases(0.25f), 64);  // at most
  EXPECT_EQ(jitterPhases(2.0f), 8);    // clamped
  EXPECT_EQ(jitterPhases(std::numeric_limits<float>::quiet_NaN()), 8);
}

}  // namespace
}  // namespace terrasol
