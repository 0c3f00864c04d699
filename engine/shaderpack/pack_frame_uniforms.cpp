#include "shaderpack/pack_frame_uniforms.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>

#include "core/camera.h"
#include "core/error.h"
#include "shaderpack/pack_uniforms.h"

namespace terrasol {
namespace {

constexpr float kTicksPerSecond = 20.0f;
constexpr int kGlLinear = 0x2601;  // fogMode: GL_LINEAR, as vanilla's terrain fog

PackValue toValue(const PackUniform& u) {
  return std::visit(
      [](const auto& v) -> PackValue {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, int> || std::is_same_v<T, float>) {
          return PackValue::of(static_cast<float>(v));
        } else if constexpr (std::is_same_v<T, glm::mat4>) {
          return {};
        } else {
          PackValue out{static_cast<int>(T::length()), glm::vec4(0.0f)};
          for (int i = 0; i < T::length(); ++i) out.v[i] = static_cast<float>(v[i]);
          return out;
        }
      },
      u);
}

PackUniform fromValue(const std::string& type, const PackValue& v) {
  if (type == "bool") return v.scalar() != 0.0f;
  if (type == "int") return static_cast<int>(v.scalar());
  if (type == "vec2") return glm::vec2(v.v);
  if (type == "vec3") return glm::vec3(v.v);
  if (type == "vec4") return v.v;
  return v.scalar();
}

}  // namespace

const PackUniform* PackUniforms::find(std::string_view name) const {
  const auto it = values_.find(name);
  return it == values_.end() ? nullptr : &it->second;
}

std::optional<PackValue> PackUniforms::value(std::string_view name) const {
  const PackUniform* u = find(name);
  if (!u || std::holds_alternative<glm::mat4>(*u)) return std::nullopt;
  return toValue(*u);
}

float packFarPlane(const PackView& view) {
  return std::max(4.0f * view.viewDistance, 256.0f);
}

PackCamera packCamera(const PackView& view) {
  Camera camera;  // at the origin: packs add cameraPosition themselves
  camera.lookAt = glm::vec3(view.lookAt - view.camera);
  camera.up = glm::vec3(view.up);
  camera.fovDegrees = view.fovDegrees;
  camera.nearPlane = kPackNear;
  camera.farPlane = packFarPlane(view);
  const float aspect =
      static_cast<float>(std::max(view.size.x, 1)) / static_cast<float>(std::max(view.size.y, 1));
  return {camera.view(), camera.projection(aspect)};
}

PackUniforms packFrameUniforms(const PackView& view, const PackSettings& settings, PackHistory& history) {
  PackUniforms u;
  const PackTime time = packTimeAt(view.ticks);
  u.set("worldTime", time.worldTime);
  u.set("worldDay", time.worldDay);
  u.set("moonPhase", time.moonPhase);
  u.set("sunAngle", time.sunAngle);
  u.set("shadowAngle", time.shadowAngle);
  u.set("frameCounter", view.frameCounter);
  u.set("frameTime", view.frameTime);
  u.set("frameTimeCounter", view.frameTimeCounter);

  const PackCamera camera = packCamera(view);
  if (!history.valid) {
    history.camera = camera;
    history.position = view.camera;
  }
  u.set("gbufferModelView", camera.modelView);
  u.set("gbufferModelViewInverse", glm::inverse(camera.modelView));
  u.set("gbufferProjection", camera.projection);
  u.set("gbufferProjectionInverse", glm::inverse(camera.projection));
  u.set("gbufferPreviousModelView", history.camera.modelView);
  u.set("gbufferPreviousProjection", history.camera.projection);

  const PackCelestial sky = packCelestial(time, view.sunPathRotation, camera.modelView);
  u.set("sunPosition", sky.sunPosition);
  u.set("moonPosition", sky.moonPosition);
  u.set("shadowLightPosition", sky.shadowLightPosition);
  u.set("upPosition", sky.upPosition);

  const glm::mat4 shadowModelView =
      packShadowModelView(time, view.sunPathRotation, settings.shadowIntervalSize, view.camera);
  const glm::mat4 shadowProjection = packShadowProjection(settings.shadowDistance);
  u.set("shadowModelView", shadowModelView);
  u.set("shadowModelViewInverse", glm::inverse(shadowModelView));
  u.set("shadowProjection", shadowProjection);
  u.set("shadowProjectionInverse", glm::inverse(shadowProjection));

  u.set("cameraPosition", glm::vec3(view.camera));
  u.set("previousCameraPosition", glm::vec3(history.position));
  const glm::dvec3 whole = glm::floor(view.camera);
  u.set("cameraPositionInt", glm::ivec3(whole));
  u.set("cameraPositionFract", glm::vec3(view.camera - whole));
  u.set("eyeAltitude", static_cast<float>(view.camera.y));
  u.set("near", kPackNear);
  u.set("far", view.viewDistance);
  u.set("viewWidth", static_cast<float>(view.size.x));
  u.set("viewHeight", static_cast<float>(view.size.y));
  u.set("aspectRatio", static_cast<float>(view.size.x) / static_cast<float>(std::max(view.size.y, 1)));

  // Eye brightness: light x 16, smoothed towards it with the pack's half-life (ticks).
  const glm::vec2 eye = glm::vec2(glm::clamp(view.eyeLight, 0, 15)) * 16.0f;
  if (!history.valid) history.eyeBrightnessSmooth = eye;
  const float halfLife = std::max(settings.eyeBrightnessHalflife, 1e-3f);
  const float keep = std::exp2(-std::max(view.frameTime, 0.0f) * kTicksPerSecond / halfLife);
  history.eyeBrightnessSmooth = eye + (history.eyeBrightnessSmooth - eye) * keep;
  u.set("eyeBrightness", glm::ivec2(eye));
  u.set("eyeBrightnessSmooth", glm::ivec2(glm::round(history.eyeBrightnessSmooth)));
  u.set("isEyeInWater", view.underWater ? 1 : 0);

  u.set("fogColor", view.fogColor);
  u.set("skyColor", view.skyColor);
  u.set("fogMode", kGlLinear);
  u.set("fogStart", 0.8f * view.viewDistance);
  u.set("fogEnd", view.viewDistance);
  u.set("fogDensity", 0.0f);

  // What Terrasol has no notion of.
  for (const char* zero : {"rainStrength", "wetness", "nightVision", "blindness", "darknessFactor",
                           "darknessLightFactor", "playerMood", "thunderStrength"}) {
    u.set(zero, 0.0f);
  }
  u.set("screenBrightness", 1.0f);
  u.set("hideGUI", 1);
  for (const char* none : {"heldItemId", "heldItemId2", "entityId", "blockEntityId"}) u.set(none, -1);
  u.set("heldBlockLightValue", 0);
  u.set("heldBlockLightValue2", 0);
  u.set("entityColor", glm::vec4(0.0f));
  u.set("atlasSize", view.atlasSize);
  u.set("alphaTestRef", 0.1f);

  history.valid = true;
  history.camera = camera;
  history.position = view.camera;
  return u;
}

void evaluateCustoms(const ShaderProperties& properties, PackUniforms& uniforms, float frameTime) {
  const PackEvaluation context{[&](std::string_view name) { return uniforms.value(name); }, frameTime};
  for (const PackCustom& c : properties.customs)
    uniforms.set(c.name, fromValue(c.type, c.expression.evaluate(context)));
}

}  // namespace terrasol
