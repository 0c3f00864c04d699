#include "scene_render/eye_light.h"

#include <cmath>

namespace terrasol {

glm::ivec2 eyeLightAt(const LightEngine& light, glm::dvec3 eye) {
  const BlockPos cell{static_cast<int>(std::floor(eye.x)), static_cast<int>(std::floor(eye.y)),
                      static_cast<int>(std::floor(eye.z))};
  return {light.lightAt(cell, LightChannel::Block), light.lightAt(cell, LightChannel::Sky)};
}

}  // namespace terrasol
