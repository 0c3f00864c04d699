#pragma once
// Relative luminance of linear RGB (Rec. 709 weights); shaders get the weights as LUMA_WEIGHTS.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace terrasol {

inline constexpr glm::vec3 kLumaWeights{0.2126f, 0.7152f, 0.0722f};

inline float luma(glm::vec3 linear) {
  return glm::dot(linear, kLumaWeights);
}

}  // namespace terrasol
