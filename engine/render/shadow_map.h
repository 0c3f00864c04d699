#pragma once
// The shadow map: one orthographic depth map from the shadow-casting light (sun or moon), centred on
// the camera and warped so texels crowd near it. Settings come from the scene ("render.shadow").
//
// Stability: the map's centre is snapped to whole texels of the unwarped map, computed in double from
// the camera's world position, so a moving camera slides the map by whole texels and edges do not
// crawl; the light direction itself is used as is (continuous). Everything is camera-relative, so it
// holds at any distance from the world's origin.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "render/gl/object.h"

namespace terrasol {

enum class ShadowWarp { None, Square, Radial };
enum class PcfPattern { Grid, Disk };

struct ShadowSettings {
  bool enabled = true;
  int resolution = 2048;        // texels per side
  float distance = 128.0f;      // blocks from the camera to the map's edge
  ShadowWarp warp = ShadowWarp::Radial;
  float warpStrength = 0.85f;   // [0, 1): 0 = no warp
  int pcfSamples = 1;           // N: (2N + 1)^2 grid taps, or a 16-tap disk; 0 = one tap
  float pcfRadius = 1.0f;       // texels of the shadow map
  PcfPattern pcfPattern = PcfPattern::Disk;
};

// The light's orthographic view of the camera's surroundings.
struct ShadowView {
  glm::mat4 matrix;        // camera-relative world position -> light clip space, before the warp
  glm::vec3 toLight;       // unit
  float depthRange;        // blocks from the near to the far plane
  float texelWorld;        // blocks per texel of the unwarped map
};

// `toLight` must be unit length (DayState::toShadowLight).
ShadowView shadowViewFor(const ShadowSettings& settings, glm::vec3 toLight, glm::dvec3 camera);

class ShadowMap {
 public:
  // Reallocates when the resolution changes. Throws Error for an incomplete framebuffer.
  void ensure(int resolution);
  GLuint framebuffer() const { return framebuffer_.id(); }
  GLuint depth() const { return depth_.id(); }
  int resolution() const { return resolution_; }

 private:
  int resolution_ = 0;
  gl::Texture depth_;
  gl::Framebuffer framebuffer_;
};

}  // namespace terrasol
