#include "scene/camera_path.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <vector>

namespace terrasol {
namespace {

glm::dvec3 directionOf(glm::dvec3 position, glm::dvec3 lookAt) {
  const glm::dvec3 d = lookAt - position;
  const double length = glm::length(d);
  return length > 1e-9 ? d / length : glm::dvec3(0.0, 0.0, -1.0);
}

// Orientation with -Z along `forward` and +Y as close to world up as it can be; looking straight up
// or down, world up says nothing, so `upHint` (the previous keyframe's up) keeps the roll.
glm::dquat orientationOf(glm::dvec3 forward, glm::dvec3 upHint) {
  const glm::dvec3 hint = std::abs(forward.y) < 0.9999 ? glm::dvec3(0.0, 1.0, 0.0) : upHint;
  glm::dvec3 right = glm::cross(forward, hint);
  if (glm::length(right) < 1e-9)
    right = glm::cross(forward, glm::dvec3(0.0, 0.0, -1.0));  // hint along forward
  right = glm::normalize(right);
  const glm::dvec3 up = glm::cross(right, forward);
  return glm::normalize(glm::quat_cast(glm::dmat3(right, up, -forward)));
}

// Uniform Catmull-Rom between p1 and p2 at u in [0, 1].
glm::dvec3 catmullRom(glm::dvec3 p0, glm::dvec3 p1, glm::dvec3 p2, glm::dvec3 p3, double u) {
  const double u2 = u * u, u3 = u2 * u;
  return 0.5 * ((2.0 * p1) + (p2 - p0) * u + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * u2 +
                (3.0 * p1 - p0 - 3.0 * p2 + p3) * u3);
}

// Keyframe orientations, each in the same hemisphere as the one before, so slerp takes the short way.
std::vector<glm::dquat> orientations(const CameraPath& path) {
  std::vector<glm::dquat> out;
  glm::dvec3 up(0.0, 0.0, -1.0);  // the first keyframe, if vertical, faces screen-up towards -Z
  for (const CameraKeyframe& k : path.keyframes) {
    glm::dquat q = orientationOf(directionOf(k.position, k.lookAt), up);
    if (!out.empty() && glm::dot(q, out.back()) < 0.0) q = -q;
    up = q * glm::dvec3(0.0, 1.0, 0.0);
    out.push_back(q);
  }
  return out;
}

}  // namespace

CameraState cameraOnPath(const CameraPath& path, double t) {
  const auto& keys = path.keyframes;
  const std::vector<glm::dquat> turns = orientations(path);
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  // The segment [i, i + 1] holding t; before the first keyframe or after the last, hold still.
  std::size_t i = 0;
  while (i + 1 < keys.size() && keys[i + 1].t <= t) ++i;
  const std::size_t j = std::min(i + 1, keys.size() - 1);
  const double span = keys[j].t - keys[i].t;
  const double u = span > 0.0 ? std::clamp((t - keys[i].t) / span, 0.0, 1.0) : 0.0;

  CameraState c;
  const std::size_t before = i == 0 ? 0 : i - 1, after = std::min(j + 1, keys.size() - 1);
  c.position = catmullRom(keys[before].position, keys[i].position, keys[j].position, keys[after].position, u);
  const glm::dquat q = glm::slerp(turns[i], turns[j], u);
  c.forward = glm::normalize(q * glm::dvec3(0.0, 0.0, -1.0));
  c.up = glm::normalize(q * glm::dvec3(0.0, 1.0, 0.0));
  c.fov = static_cast<float>(keys[i].fov + (keys[j].fov - keys[i].fov) * u);
  c.time = keys[i].time +
           static_cast<std::int64_t>(std::llround(static_cast<double>(keys[j].time - keys[i].time) * u));
  return c;
}

CameraState cameraAtFrame(const SceneFile& scene, int frame) {
  if (!scene.cameraPath) {
    CameraState c;
    c.position = scene.cameraPosition;
    c.forward = directionOf(scene.cameraPosition, scene.cameraLookAt);
    c.up = orientationOf(c.forward, glm::dvec3(0.0, 0.0, -1.0)) * glm::dvec3(0.0, 1.0, 0.0);
    c.fov = scene.fov;
    c.time = scene.time;
    return c;
  }
  const int frames = scene.cameraPath->frames;
  const double t = frames > 1 ? static_cast<double>(frame) / static_cast<double>(frames - 1) : 0.0;
  return cameraOnPath(*scene.cameraPath, t);
}

}  // namespace terrasol
