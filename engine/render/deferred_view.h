#pragma once
// One frame's view as the deferred renderer's passes share it. Internal to engine/render.

#include <array>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/day_cycle.h"
#include "core/lightmap.h"
#include "render/deferred_renderer.h"
#include "render/frustum.h"

namespace terrasol {

struct DeferredRenderer::View {
  glm::dvec3 camera;
  glm::mat4 viewProjection;  // camera-relative
  glm::mat4 inverseViewProjection;
  FrustumPlanes frustum;  // camera-relative
  glm::vec2 nearFar;
  glm::vec2 fogRange;
  DayState day;
  LightmapColours lightmap;
  bool materialAo;
  bool shadowLive = false;  // the shadow pass ran this frame
  glm::dvec3 shadowCentreOffset{0.0};
  glm::dvec3 forward{0.0, 0.0, -1.0};  // unit view direction
  ViewCone cone;                       // the view's receivers, for the shadow pass (after culling)
};

}  // namespace terrasol
