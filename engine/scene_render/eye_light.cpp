#include "scene_render/eye_light.h"

#include <cmath>

namespace terrasol {

glm::ivec2 eyeLightAt(const LightEngine& light, glm::dvec3 eye) {
  const BlockPos cell = BlockPos::containing(eye.x, eye.y, eye.z);
  return {light.lightAt(cell, LightChannel::Block), light.lightAt(cell, LightChannel::Sky)};
}

}  // namespace terrasol
