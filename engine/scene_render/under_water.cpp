#include "scene_render/under_water.h"

#include <cmath>

#include "core/light_level.h"
#include "world/liquid.h"

namespace terrasol {

std::optional<UnderWater> underWaterAt(const World& world, const LightEngine& light, glm::dvec3 eye) {
  const std::optional<double> surface = liquidSurfaceAbove(world, eye);
  if (!surface) return std::nullopt;
  const BlockPos cell = BlockPos::containing(eye.x, eye.y, eye.z);
  return UnderWater{*surface, static_cast<float>(light.lightAt(cell, LightChannel::Sky)) / kMaxLight};
}

}  // namespace terrasol
