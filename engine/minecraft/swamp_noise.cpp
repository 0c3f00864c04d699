#include "minecraft/swamp_noise.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace terrasol {
namespace {

// java.util.Random's generator, as Minecraft's LegacyRandomSource.
class JavaRandom {
 public:
  explicit JavaRandom(std::int64_t seed) : seed_((static_cast<std::uint64_t>(seed) ^ kMultiplier) & kMask) {}

  int next(int bits) {
    seed_ = (seed_ * kMultiplier + 0xB) & kMask;
    return static_cast<int>(static_cast<std::int64_t>(seed_) >> (48 - bits));
  }
  double nextDouble() {
    const std::int64_t high = next(26), low = next(27);
    return static_cast<double>((high << 27) + low) * 0x1.0p-53;
  }
  int nextInt(int bound) {
    if ((bound & (bound - 1)) == 0)
      return static_cast<int>((static_cast<std::int64_t>(bound) * next(31)) >> 31);
    for (;;) {
      const int bits = next(31), value = bits % bound;
      if (bits - value + (bound - 1) >= 0) return value;
    }
  }

 private:
  static constexpr std::uint64_t kMultiplier = 0x5DEECE66DULL, kMask = (1ULL << 48) - 1;
  std::uint64_t seed_;
};

// Minecraft's SimplexNoise: its permutation from the random, and its 2D value.
class Simplex {
 public:
  explicit Simplex(JavaRandom& random) {
    for (int i = 0; i < 3; ++i) random.nextDouble();  // the offsets, which the 2D value does not use
    for (int i = 0; i < 256; ++i) p_[static_cast<std::size_t>(i)] = i;
    for (int i = 0; i < 256; ++i) {
      const int j = random.nextInt(256 - i);
      std::swap(p_[static_cast<std::size_t>(i)], p_[static_cast<std::size_t>(i + j)]);
    }
  }

  double value(double x, double y) const {
    const double f2 = 0.5 * (std::sqrt(3.0) - 1.0), g2 = (3.0 - std::sqrt(3.0)) / 6.0;
    const double skew = (x + y) * f2;
    const int i = static_cast<int>(std::floor(x + skew)), j = static_cast<int>(std::floor(y + skew));
    const double unskew = static_cast<double>(i + j) * g2;
    const double x0 = x - (static_cast<double>(i) - unskew), y0 = y - (static_cast<double>(j) - unskew);
    const int i1 = x0 > y0 ? 1 : 0, j1 = x0 > y0 ? 0 : 1;
    const double x1 = x0 - i1 + g2, y1 = y0 - j1 + g2;
    const double x2 = x0 - 1.0 + 2.0 * g2, y2 = y0 - 1.0 + 2.0 * g2;
    const int ii = i & 255, jj = j & 255;
    const int g0 = p(ii + p(jj)) % 12, g1 = p(ii + i1 + p(jj + j1)) % 12, g2i = p(ii + 1 + p(jj + 1)) % 12;
    return 70.0 * (corner(g0, x0, y0) + corner(g1, x1, y1) + corner(g2i, x2, y2));
  }

 private:
  int p(int index) const { return p_[static_cast<std::size_t>(index & 255)]; }
  static double corner(int gradient, double x, double y) {
    static constexpr int kGradients[12][2] = {{1, 1}, {-1, 1}, {1, -1}, {-1, -1}, {1, 0}, {-1, 0},
                                              {1, 0}, {-1, 0}, {0, 1},  {0, -1},  {0, 1}, {0, -1}};
    double t = 0.5 - x * x - y * y;
    if (t < 0.0) return 0.0;
    t *= t;
    return t * t * (kGradients[gradient][0] * x + kGradients[gradient][1] * y);
  }

  std::array<int, 256> p_;
};

const Simplex& biomeInfoNoise() {
  static const Simplex noise = [] {
    JavaRandom random(2345);
    return Simplex(random);
  }();
  return noise;
}

}  // namespace

double swampGrassNoise(int x, int z) {
  return biomeInfoNoise().value(static_cast<double>(x) * 0.0225, static_cast<double>(z) * 0.0225);
}

}  // namespace terrasol
