#pragma once
// The block and sky light (0..15) at a camera's eye: what shader packs read as eyeBrightness
// (FrameInputs::eyeLight). For the game and scene renders alike.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "light/light_engine.h"

namespace terrasol {

glm::ivec2 eyeLightAt(const LightEngine& light, glm::dvec3 eye);

}  // namespace terrasol
