#pragma once
// The shadow map: orthographic depth from the shadow-casting light (sun or moon), centred on the
// camera. Either one map warped so texels crowd near the camera, or (cascaded) up to four unwarped
// maps, each covering twice the distance of the one before, as layers of one array texture. Settings
// come from the scene ("render.shadow").
//
// Stability: the map's centre is snapped to whole texels of the unwarped map, computed in double from
// the camera's world position, so a moving camera slides the map by whole texels and edges do not
// crawl; the light direction itself is used as is (continuous). Everything is camera-relative, so it
// holds at any distance from the world's origin.

#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/render_settings.h"
#include "render/gl/object.h"

namespace terrasol {

// Casters this far beyond the map's reach towards the light still shadow it (a mountain between the
// sun and the camera's surroundings); the shadow truth marches rays as far.
inline constexpr float kShadowCasterReach = 256.0f;

// The light's orthographic view of the camera's surroundings.
struct ShadowView {
  glm::mat4 matrix;   // camera-relative world position -> light clip space, before the warp
  glm::vec3 toLight;  // unit
  float depthRange;   // blocks from the near to the far plane
  float texelWorld;   // blocks per texel of the unwarped map
};

// A map of `distance` blocks around `centre` (the camera; moved only to measure flicker), for positions
// relative to `camera`. `toLight` must be unit length (DayState::toShadowLight).
ShadowView shadowViewFor(int resolution, float distance, glm::vec3 toLight, glm::dvec3 camera,
                         glm::dvec3 centre);

class ShadowMap {
 public:
  // Reallocates when the resolution or layer count changes. Throws Error for an incomplete framebuffer.
  void ensure(int resolution, int layers);
  // The framebuffer drawing opaque casters into `layer`.
  GLuint framebuffer(int layer) const { return framebuffers_[static_cast<std::size_t>(layer)].id(); }
  // The framebuffer drawing translucent casters into `layer`: their depth and transmittance.
  GLuint translucentFramebuffer(int layer) const {
    return translucentFramebuffers_[static_cast<std::size_t>(layer)].id();
  }
  GLuint depth() const { return depth_.id(); }
  // RGBA16: the colour light keeps through the nearest translucent caster, and that caster's depth.
  GLuint transmittance() const { return transmittance_.id(); }
  int resolution() const { return resolution_; }

 private:
  int resolution_ = 0, layers_ = 0;
  gl::Texture depth_, transmittance_;
  gl::Texture translucentDepth_;  // only the translucent draw's depth test: the nearest caster is kept
  std::array<gl::Framebuffer, kMaxShadowCascades> framebuffers_, translucentFramebuffers_;
};

}  // namespace terrasol
