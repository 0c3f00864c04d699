#include "world/noise.h"

#include <cmath>

namespace terrasol {
namespace {

double fade(double t) {
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}
double lerp(double a, double b, double t) {
  return a + (b - a) * t;
}

// Dot product of the fraction with one of 8 (2D) or 12 (3D) gradient directions picked by the hash.
double grad2(std::uint64_t h, double x, double z) {
  switch (h >> 61) {  // top 3 bits
    case 0:
      return x + z;
    case 1:
      return x - z;
    case 2:
      return -x + z;
    case 3:
      return -x - z;
    case 4:
      return x;
    case 5:
      return -x;
    case 6:
      return z;
    default:
      return -z;
  }
}

double grad3(std::uint64_t h, double x, double y, double z) {
  switch ((h >> 32) % 12) {
    case 0:
      return x + y;
    case 1:
      return -x + y;
    case 2:
      return x - y;
    case 3:
      return -x - y;
    case 4:
      return x + z;
    case 5:
      return -x + z;
    case 6:
      return x - z;
    case 7:
      return -x - z;
    case 8:
      return y + z;
    case 9:
      return -y + z;
    case 10:
      return y - z;
    default:
      return -y - z;
  }
}

}  // namespace

double Noise::at(double x, double z) const {
  const double fx = std::floor(x), fz = std::floor(z);
  const auto ix = static_cast<std::int64_t>(fx), iz = static_cast<std::int64_t>(fz);
  const double dx = x - fx, dz = z - fz;
  const double u = fade(dx), v = fade(dz);
  const double n00 = grad2(hashCoords(seed_, ix, 0, iz), dx, dz);
  const double n10 = grad2(hashCoords(seed_, ix + 1, 0, iz), dx - 1.0, dz);
  const double n01 = grad2(hashCoords(seed_, ix, 0, iz + 1), dx, dz - 1.0);
  const double n11 = grad2(hashCoords(seed_, ix + 1, 0, iz + 1), dx - 1.0, dz - 1.0);
  return lerp(lerp(n00, n10, u), lerp(n01, n11, u), v);
}

double Noise::at(double x, double y, double z) const {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy),
             iz = static_cast<std::int64_t>(fz);
  const double dx = x - fx, dy = y - fy, dz = z - fz;
  const double u = fade(dx), v = fade(dy), w = fade(dz);
  double corners[2][2][2];
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int c = 0; c < 2; ++c)
        corners[a][b][c] = grad3(hashCoords(seed_, ix + a, iy + b, iz + c), dx - a, dy - b, dz - c);
  const double x00 = lerp(corners[0][0][0], corners[1][0][0], u);
  const double x10 = lerp(corners[0][1][0], corners[1][1][0], u);
  const double x01 = lerp(corners[0][0][1], corners[1][0][1], u);
  const double x11 = lerp(corners[0][1][1], corners[1][1][1], u);
  return lerp(lerp(x00, x10, v), lerp(x01, x11, v), w);
}

double Noise::fractal(double x, double z, int octaves) const {
  double sum = 0.0, amplitude = 1.0, total = 0.0, frequency = 1.0;
  for (int i = 0; i < octaves; ++i) {
    // Offsetting each octave keeps their lattice points from lining up at the origin.
    sum += amplitude * at(x * frequency + i * 17.31, z * frequency - i * 11.97);
    total += amplitude;
    amplitude *= 0.5;
    frequency *= 2.0;
  }
  return sum / total;
}

double Noise::fractal(double x, double y, double z, int octaves) const {
  double sum = 0.0, amplitude = 1.0, total = 0.0, frequency = 1.0;
  for (int i = 0; i < octaves; ++i) {
    sum += amplitude * at(x * frequency + i * 17.31, y * frequency + i * 5.13, z * frequency - i * 11.97);
    total += amplitude;
    amplitude *= 0.5;
    frequency *= 2.0;
  }
  return sum / total;
}

}  // namespace terrasol
