#pragma once
// LabPBR 1.3 decoding, exactly as the format gives it (docs/packs.md). The shaders implement the same rules;
// these functions are the reference the tests check, and what the atlas builder uses for mipmaps.

#include <cstdint>
#include <glm/vec3.hpp>

namespace terrasol::labpbr {

// What an absent map reads as.
inline constexpr std::uint8_t kDefaultNormal[4] = {127, 127, 255, 255};
inline constexpr std::uint8_t kDefaultSpecular[4] = {0, 0, 0, 0};

struct NormalTexel {
  glm::vec3 normal;  // unit length, tangent space, OpenGL convention (+y up the texture), z >= 0
  float ao;          // 1 = no occlusion
  float depth;       // 0 at the surface .. 0.25 at height 0
};
// `openGlConvention`: the pack's green points up; LabPBR's own (DirectX) green points down.
NormalTexel decodeNormal(const std::uint8_t rgba[4], bool openGlConvention = false);
// Back to LabPBR's DirectX convention.
void encodeNormal(const glm::vec3& normal, float ao, float depth, std::uint8_t rgba[4]);

enum class Reflectance : std::uint8_t {
  Dielectric,   // G 0..229: F0 = G / 255, grey
  Metal,        // G 230..237: one of the predefined metals
  AlbedoMetal,  // G 238..255: metal whose F0 is the albedo
};

struct SpecularTexel {
  float smoothness;  // perceptual, R / 255
  float roughness;   // (1 - smoothness)^2
  Reflectance reflectance;
  int metalId;       // 230..237 for Metal, else 0
  glm::vec3 f0;      // for AlbedoMetal, the albedo passed in
  float porosity;    // B 0..64 -> 0..1, else 0
  float subsurface;  // B 65..255 -> 0..1, else 0
  float emission;    // A 0..254 -> 0..1; 255 -> 0
};
SpecularTexel decodeSpecular(const std::uint8_t rgba[4], const glm::vec3& albedo);

// F0 of predefined metal `id` (230..237) from the standard's complex index of refraction:
// ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2) per channel. Black for any other id.
glm::vec3 metalF0(int id);
const char* metalName(int id);

}  // namespace terrasol::labpbr
