#pragma once
// Seeded gradient noise (Perlin's improved noise with hashed gradients), written here rather than
// taken from a library because it must be exact far from the origin: lattice coordinates are 64-bit
// integers and only the fraction inside a cell is floating point, so terrain at x = 29 999 000 is
// as smooth as at 0. Deterministic across threads and runs (no global state).

#include <cstdint>

namespace terrasol {

// A 64-bit mixer (splitmix64's finaliser): every input bit affects every output bit.
constexpr std::uint64_t mix64(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// A deterministic hash of a seed and up to three integer coordinates.
constexpr std::uint64_t hashCoords(std::uint64_t seed, std::int64_t x, std::int64_t y = 0,
                                   std::int64_t z = 0) {
  std::uint64_t h = mix64(seed ^ 0x9E3779B97F4A7C15ull);
  h = mix64(h ^ static_cast<std::uint64_t>(x));
  h = mix64(h ^ static_cast<std::uint64_t>(y) * 0xD6E8FEB86659FD93ull);
  return mix64(h ^ static_cast<std::uint64_t>(z) * 0xA0761D6478BD642Full);
}

// Uniform in [0, 1) from a hash.
constexpr double unitFloat(std::uint64_t h) {
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

class Noise {
 public:
  explicit Noise(std::uint64_t seed) : seed_(mix64(seed)) {}

  // Roughly in [-1, 1], 0 at lattice points, smooth (C2) everywhere.
  double at(double x, double z) const;
  double at(double x, double y, double z) const;

  // Sum of `octaves` layers, each twice the frequency and half the amplitude; normalised to about [-1, 1].
  double fractal(double x, double z, int octaves) const;
  double fractal(double x, double y, double z, int octaves) const;

 private:
  std::uint64_t seed_;
};

}  // namespace terrasol
