#pragma once
// Which shadow casters can shade something the camera sees. Light reaches a receiver after passing
// every caster above it along the light, so a caster matters only when its box, swept along the light
// down to the floor (the renderer's: the world's bottom), meets the camera's view. The rest (behind
// the camera, or off to its sides, with the light) are left out of the shadow pass.
//
// A kept or spread-rebuilt map serves a camera that has moved on since it was drawn, so the view it is
// drawn for is widened: a margin on every side and the apex pulled back along the view. The map still
// serves a later view that lies inside the widened one (`contains`): the later view's apex inside it
// and its four edge rays inside its cone make the whole later view a subset (both are convex cones).
// Plain C++, no GL.

#include <glm/vec3.hpp>

#include "render/frustum.h"

namespace terrasol {

// A camera's view as the shadow pass sees it.
struct ViewCone {
  glm::dvec3 eye{0.0};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit
  glm::vec3 up{0.0f, 1.0f, 0.0f};        // screen-up hint (Camera::up)
  float fovDegrees = 70.0f;              // vertical
  float aspect = 1.0f;
  float farPlane = 256.0f;
  double floorY = 0.0;  // world y no receiver lies below

  // The cone with `degrees` more on every side and its apex `pullBack` blocks behind.
  ViewCone widened(float degrees, float pullBack) const;
};

class ShadowReceivers {
 public:
  explicit ShadowReceivers(const ViewCone& view);  // exactly the view (widen it first for a margin)

  // Whether light passing the world box [lo, hi] can go on to a point of the view: the box swept along
  // -`toLight` (unit, above the horizon) down to the floor meets the view's frustum.
  bool mayShade(glm::dvec3 lo, glm::dvec3 hi, glm::vec3 toLight) const;
  // Whether every receiver of `view` is one of this view's: its apex and edge rays inside, its floor
  // no lower.
  bool contains(const ViewCone& view) const;

 private:
  glm::dvec3 origin_;     // the eye the planes are relative to
  FrustumPlanes planes_;  // left, right, bottom, top, near, far
  double floorY_;
};

}  // namespace terrasol
