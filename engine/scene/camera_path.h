#pragma once
// Where a scene's camera is at each frame. Positions follow a Catmull-Rom spline through the keyframes;
// orientation is a quaternion slerp between the keyframes' orientations, so it never flips, also through
// a keyframe looking straight up or down (whose roll is taken from its neighbour); fov and world time
// are interpolated linearly.

#include <cstdint>
#include <glm/vec3.hpp>

#include "scene/scene_file.h"

namespace terrasol {

struct CameraState {
  glm::dvec3 position{0.0};
  glm::dvec3 forward{0.0, 0.0, -1.0};  // unit
  glm::dvec3 up{0.0, 1.0, 0.0};        // unit, perpendicular to forward
  float fov = 70.0f;
  std::int64_t time = kNoon;
};

// `t` is clamped to [0, 1]; keyframes must be as parseScene leaves them (at least one, t increasing).
CameraState cameraOnPath(const CameraPath& path, double t);

// Frame `frame` of the scene: on its camera path at t = frame / (frames - 1), or its fixed camera.
CameraState cameraAtFrame(const SceneFile& scene, int frame);

}  // namespace terrasol
