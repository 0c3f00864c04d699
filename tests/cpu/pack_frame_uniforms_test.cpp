// A shader pack's per-frame uniforms, by group, against values worked by hand: the camera and its
// matrices (this frame's and, a frame later, the previous ones), eye brightness smoothed with the
// pack's half-life, the constants for what Terrasol lacks, and custom uniforms reading built-ins.

#include "shaderpack/pack_frame_uniforms.h"

#include <gtest/gtest.h>

#include <cmath>

#include "shaderpack/pack_conditions.h"
#include "shaderpack/pack_macros.h"

namespace terrasol {
namespace {

template <class T>
T get(const PackUniforms& u, const char* name) {
  const PackUniform* v = u.find(name);
  EXPECT_TRUE(v) << name;
  EXPECT_TRUE(v && std::holds_alternative<T>(*v)) << name;
  return v && std::holds_alternative<T>(*v) ? std::get<T>(*v) : T{};
}

PackView noonView() {
  PackView view;
  view.camera = {10.5, 70.25, -3.75};
  view.lookAt = view.camera + glm::dvec3(0.0, 0.0, -1.0);  // north, level
  view.size = {320, 180};
  view.viewDistance = 64.0f;
  view.ticks = 6000;
  view.eyeLight = {0, 15};
  return view;
}

TEST(PackFrameUniforms, TheCameraGroup) {
  PackHistory history;
  const PackUniforms u = packFrameUniforms(noonView(), PackSettings{}, history);
  EXPECT_EQ(get<glm::vec3>(u, "cameraPosition"), glm::vec3(10.5f, 70.25f, -3.75f));
  EXPECT_EQ(get<glm::ivec3>(u, "cameraPositionInt"), glm::ivec3(10, 70, -4));
  EXPECT_EQ(get<glm::vec3>(u, "cameraPositionFract"), glm::vec3(0.5f, 0.25f, 0.25f));
  EXPECT_FLOAT_EQ(get<float>(u, "eyeAltitude"), 70.25f);
  EXPECT_FLOAT_EQ(get<float>(u, "near"), 0.05f);
  EXPECT_FLOAT_EQ(get<float>(u, "far"), 64.0f);
  EXPECT_FLOAT_EQ(get<float>(u, "viewWidth"), 320.0f);
  EXPECT_FLOAT_EQ(get<float>(u, "viewHeight"), 180.0f);
  EXPECT_NEAR(get<float>(u, "aspectRatio"), 1.777778f, 1e-6f);
  EXPECT_EQ(get<int>(u, "worldTime"), 6000);
}

TEST(PackFrameUniforms, TheMatricesAndThePreviousFramesOnes) {
  PackHistory history;
  const PackView first = noonView();
  const PackUniforms a = packFrameUniforms(first, PackSettings{}, history);
  // Looking north with y up, the view is no rotation at all: packs add cameraPosition themselves.
  const glm::mat4 modelView = get<glm::mat4>(a, "gbufferModelView");
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(modelView[c][r], c == r ? 1.0f : 0.0f, 1e-6f);
  // 70 degrees vertical: 1 / tan(35) = 1.428148; across, that over the aspect 16:9.
  const glm::mat4 projection = get<glm::mat4>(a, "gbufferProjection");
  EXPECT_NEAR(projection[1][1], 1.428148f, 1e-5f);
  EXPECT_NEAR(projection[0][0], 1.428148f / (320.0f / 180.0f), 1e-5f);
  // A point at the near plane (0.05 ahead) lands at depth -1 in NDC, as packs' linearisation assumes.
  const glm::vec4 nearPoint = projection * glm::vec4(0.0f, 0.0f, -0.05f, 1.0f);
  EXPECT_NEAR(nearPoint.z / nearPoint.w, -1.0f, 1e-4f);
  const glm::mat4 inverse = get<glm::mat4>(a, "gbufferProjectionInverse");
  const glm::vec4 back = inverse * nearPoint;
  EXPECT_NEAR(back.z / back.w, -0.05f, 1e-6f);
  EXPECT_EQ(get<glm::mat4>(a, "gbufferPreviousProjection"), projection)
      << "the first frame is its own previous";
  EXPECT_EQ(get<glm::vec3>(a, "previousCameraPosition"), get<glm::vec3>(a, "cameraPosition"));

  PackView second = first;
  second.camera.x += 1.0;
  second.lookAt = second.camera + glm::dvec3(1.0, 0.0, 0.0);  // turned to face east
  const PackUniforms b = packFrameUniforms(second, PackSettings{}, history);
  EXPECT_EQ(get<glm::vec3>(b, "previousCameraPosition"), glm::vec3(10.5f, 70.25f, -3.75f));
  EXPECT_EQ(get<glm::mat4>(b, "gbufferPreviousModelView"), modelView);
  const glm::vec4 east = get<glm::mat4>(b, "gbufferModelView") * glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
  EXPECT_NEAR(east.z, -1.0f, 1e-6f) << "east is straight ahead now";
}

TEST(PackFrameUniforms, EyeBrightnessIsSmoothedWithThePacksHalfLife) {
  PackHistory history;
  PackView view = noonView();
  PackUniforms u = packFrameUniforms(view, PackSettings{}, history);
  EXPECT_EQ(get<glm::ivec2>(u, "eyeBrightness"), glm::ivec2(0, 240));
  EXPECT_EQ(get<glm::ivec2>(u, "eyeBrightnessSmooth"), glm::ivec2(0, 240)) << "the first frame starts there";
  view.eyeLight = {15, 0};  // into a torch-lit cave
  view.frameTime = 0.5f;    // 10 ticks: the default half-life
  u = packFrameUniforms(view, PackSettings{}, history);
  EXPECT_EQ(get<glm::ivec2>(u, "eyeBrightness"), glm::ivec2(240, 0));
  EXPECT_EQ(get<glm::ivec2>(u, "eyeBrightnessSmooth"), glm::ivec2(120, 120));
  PackSettings slow;
  slow.eyeBrightnessHalflife = 20.0f;
  PackHistory other;
  view.eyeLight = {0, 15};
  packFrameUniforms(view, slow, other);
  view.eyeLight = {15, 0};
  u = packFrameUniforms(view, slow, other);
  EXPECT_EQ(get<glm::ivec2>(u, "eyeBrightnessSmooth"), glm::ivec2(70, 170)) << "240 (1 - 2^-0.5) = 70.3";
  view.underWater = true;
  EXPECT_EQ(get<int>(packFrameUniforms(view, slow, other), "isEyeInWater"), 1);
}

TEST(PackFrameUniforms, WhatTerrasolLacksIsConstant) {
  PackHistory history;
  const PackUniforms u = packFrameUniforms(noonView(), PackSettings{}, history);
  EXPECT_FLOAT_EQ(get<float>(u, "rainStrength"), 0.0f);
  EXPECT_FLOAT_EQ(get<float>(u, "wetness"), 0.0f);
  EXPECT_EQ(get<int>(u, "heldItemId"), -1);
  EXPECT_EQ(get<int>(u, "heldBlockLightValue"), 0);
  EXPECT_EQ(get<int>(u, "entityId"), -1);
  EXPECT_EQ(get<int>(u, "isEyeInWater"), 0);
}

TEST(PackFrameUniforms, CustomUniformsReadBuiltInsAndEarlierVariables) {
  const ShaderProperties properties = parseShaderProperties(
      "uniform.float.halfTime = worldTime / 2\n"
      "variable.float.wider = viewWidth + 1\n"
      "uniform.vec2.size = vec2(wider, viewHeight)\n"
      "uniform.bool.high = cameraPosition.y > 64\n",
      "shaders.properties", PackMacros(packMacros()));
  PackHistory history;
  PackUniforms u = packFrameUniforms(noonView(), PackSettings{}, history);
  evaluateCustoms(properties, u, 0.0f);
  EXPECT_FLOAT_EQ(get<float>(u, "halfTime"), 3000.0f);
  EXPECT_EQ(get<glm::vec2>(u, "size"), glm::vec2(321.0f, 180.0f));
  EXPECT_TRUE(get<bool>(u, "high"));
}

}  // namespace
}  // namespace terrasol
