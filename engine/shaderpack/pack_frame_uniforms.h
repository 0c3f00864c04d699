#pragma once
// The uniforms a shader pack reads each frame, by OptiFine's names, with Minecraft's meaning computed
// from Terrasol's camera, world time and sky (OptiFine shaders.txt "Uniforms", Iris's uniforms/*):
// time, the sun and moon, the camera and its matrices (this frame's and the last's), the shadow
// camera, eye brightness smoothed as OptiFine does, fog and sky colours, and constants for what
// Terrasol lacks (no rain, no held item, no entity). Then the pack's custom uniforms and variables
// from shaders.properties, in order, each reading what came before. GL-free.

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "shaderpack/pack_expression.h"
#include "shaderpack/pack_settings.h"
#include "shaderpack/shader_properties.h"

namespace terrasol {

using PackUniform =
    std::variant<bool, int, float, glm::vec2, glm::vec3, glm::vec4, glm::ivec2, glm::ivec3, glm::mat4>;

class PackUniforms {
 public:
  void set(std::string name, PackUniform value) { values_[std::move(name)] = value; }
  const PackUniform* find(std::string_view name) const;
  // A scalar or vector as the expression language reads it; nothing for matrices and unknown names.
  std::optional<PackValue> value(std::string_view name) const;
  const std::map<std::string, PackUniform, std::less<>>& all() const { return values_; }

 private:
  std::map<std::string, PackUniform, std::less<>> values_;
};

// Near plane of the pack's projection: packs linearise depth with `near` (Iris: 0.05).
inline constexpr float kPackNear = 0.05f;

// What the frame is, in Terrasol's terms.
struct PackView {
  glm::dvec3 camera{0.0};
  glm::dvec3 lookAt{0.0, 0.0, -1.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  float fovDegrees = 70.0f;
  std::int64_t ticks = 0;
  float sunPathRotation = 0.0f;  // degrees, as packs turn it (PackSettings::sunPathRotation, or the world's)
  glm::ivec2 size{1};
  float viewDistance = 64.0f;     // blocks: `far`
  float frameTime = 0.0f;         // seconds since the last frame
  float frameTimeCounter = 0.0f;  // seconds since the start, wrapped at 3600
  int frameCounter = 0;
  glm::ivec2 eyeLight{0, 15};  // block and sky light at the eye, 0..15
  bool underWater = false;
  glm::vec3 fogColor{0.0f}, skyColor{0.0f};  // sRGB 0..1, as Minecraft's
  glm::ivec2 atlasSize{0};
};

// This frame's camera matrices and what the next frame reads as the previous ones.
struct PackCamera {
  glm::mat4 modelView{1.0f}, projection{1.0f};
};
PackCamera packCamera(const PackView& view);
// The projection's far plane: vanilla's lies well beyond the render distance (fog ends there).
float packFarPlane(const PackView& view);

// What carries from one frame to the next: the previous camera and the smoothed eye brightness.
struct PackHistory {
  bool valid = false;
  PackCamera camera;
  glm::dvec3 position{0.0};
  glm::vec2 eyeBrightnessSmooth{0.0f};
};

// Every built-in uniform for `view`; updates `history` for the next frame.
PackUniforms packFrameUniforms(const PackView& view, const PackSettings& settings, PackHistory& history);

// Evaluates the pack's custom uniforms and variables into `uniforms` (variables too: later
// expressions read them; programs never see them). Throws Error naming the custom's line.
void evaluateCustoms(const ShaderProperties& properties, PackUniforms& uniforms, float frameTime);

}  // namespace terrasol
