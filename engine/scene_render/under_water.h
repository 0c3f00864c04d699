#pragma once
// Whether a camera's eye is under a liquid's surface, and the sky light there: what the renderer
// needs to show the surface from below (FrameInputs::underWater). For the game and scene renders alike.

#include <glm/vec3.hpp>
#include <optional>

#include "light/light_engine.h"
#include "render/frame_inputs.h"
#include "world/world.h"

namespace terrasol {

std::optional<UnderWater> underWaterAt(const World& world, const LightEngine& light, glm::dvec3 eye);

}  // namespace terrasol
