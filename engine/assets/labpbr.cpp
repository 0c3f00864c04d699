#include "assets/labpbr.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace terrasol::labpbr {
namespace {

struct Metal {
  const char* name;
  glm::vec3 n, k;
};

// LabPBR 1.3, predefined metals G = 230..237.
constexpr Metal kMetals[8] = {
    {"iron", {2.9114f, 2.9497f, 2.5845f}, {3.0893f, 2.9318f, 2.7670f}},
    {"gold", {0.18299f, 0.42108f, 1.3734f}, {3.4242f, 2.3459f, 1.7704f}},
    {"aluminium", {1.3456f, 0.96521f, 0.61722f}, {7.4746f, 6.3995f, 5.3031f}},
    {"chrome", {3.1071f, 3.1812f, 2.3230f}, {3.3314f, 3.3291f, 3.1350f}},
    {"copper", {0.27105f, 0.67693f, 1.3164f}, {3.6092f, 2.6248f, 2.2921f}},
    {"lead", {1.9100f, 1.8300f, 1.4400f}, {3.5100f, 3.4000f, 3.1800f}},
    {"platinum", {2.3757f, 2.0847f, 1.8453f}, {4.2655f, 3.7153f, 3.1365f}},
    {"silver", {0.15943f, 0.14512f, 0.13547f}, {3.9291f, 3.1900f, 2.3808f}},
};

float unorm(std::uint8_t v) {
  return static_cast<float>(v) / 255.0f;
}
std::uint8_t toByte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

NormalTexel decodeNormal(const std::uint8_t rgba[4], bool openGlConvention) {
  // 8 bits cannot hold the centre (127.5): 127 and 128 both mean flat, exactly (as labpbr.glsl).
  auto component = [](std::uint8_t v) { return v == 127 || v == 128 ? 0.0f : unorm(v) * 2.0f - 1.0f; };
  float x = component(rgba[0]);
  float y = component(rgba[1]);
  if (!openGlConvention) y = -y;  // DirectX: green points down the texture
  const float xy2 = x * x + y * y;
  float z = 0.0f;
  if (xy2 > 1.0f) {  // outside the unit disc: project onto its rim, never sqrt of a negative
    const float len = std::sqrt(xy2);
    x /= len;
    y /= len;
  } else {
    z = std::sqrt(1.0f - xy2);
  }
  return {glm::vec3(x, y, z), unorm(rgba[2]), 0.25f * (1.0f - unorm(rgba[3]))};
}

void encodeNormal(const glm::vec3& normal, float ao, float depth, std::uint8_t rgba[4]) {
  const float len = glm::length(normal);
  const glm::vec3 n = len > 1e-6f ? normal / len : glm::vec3(0.0f, 0.0f, 1.0f);
  rgba[0] = toByte(n.x * 0.5f + 0.5f);
  rgba[1] = toByte(-n.y * 0.5f + 0.5f);
  rgba[2] = toByte(ao);
  rgba[3] = toByte(1.0f - depth / 0.25f);
}

SpecularTexel decodeSpecular(const std::uint8_t rgba[4], const glm::vec3& albedo) {
  SpecularTexel s{};
  s.smoothness = unorm(rgba[0]);
  s.roughness = (1.0f - s.smoothness) * (1.0f - s.smoothness);
  const int g = rgba[1];
  if (g <= 229) {
    s.reflectance = Reflectance::Dielectric;
    s.f0 = glm::vec3(static_cast<float>(g) / 255.0f);
  } else if (g <= 237) {
    s.reflectance = Reflectance::Metal;
    s.metalId = g;
    s.f0 = metalF0(g);
  } else {
    s.reflectance = Reflectance::AlbedoMetal;
    s.f0 = albedo;
  }
  const int b = rgba[2];
  if (b <= 64) {
    s.porosity = static_cast<float>(b) / 64.0f;
  } else {
    s.subsurface = static_cast<float>(b - 65) / 190.0f;
  }
  s.emission = rgba[3] == 255 ? 0.0f : static_cast<float>(rgba[3]) / 254.0f;
  return s;
}

glm::vec3 metalF0(int id) {
  if (id < 230 || id > 237) return glm::vec3(0.0f);
  const Metal& m = kMetals[id - 230];
  const glm::vec3 num = (m.n - 1.0f) * (m.n - 1.0f) + m.k * m.k;
  const glm::vec3 den = (m.n + 1.0f) * (m.n + 1.0f) + m.k * m.k;
  return num / den;
}

const char* metalName(int id) {
  return id >= 230 && id <= 237 ? kMetals[id - 230].name : "none";
}

}  // namespace terrasol::labpbr
