#include "scene/camera_path.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "support/error_of.h"

namespace terrasol {
namespace {

CameraPath path(std::initializer_list<CameraKeyframe> keys, int frames = 9) {
  CameraPath p;
  p.frames = frames;
  p.keyframes = keys;
  return p;
}

CameraKeyframe key(double t, glm::dvec3 position, glm::dvec3 lookAt, float fov = 70.0f,
                   std::int64_t time = 6000) {
  return {t, position, lookAt, fov, time};
}

double angle(glm::dvec3 a, glm::dvec3 b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
}

TEST(CameraPath, KeyframesAreHitExactly) {
  const CameraPath p =
      path({key(0.0, {0, 70, 0}, {0, 70, -10}, 60, 0), key(0.5, {10, 75, 0}, {20, 75, 0}, 80, 1000),
            key(1.0, {10, 80, 10}, {10, 80, 20}, 90, 3000)});
  for (const auto& k : p.keyframes) {
    const CameraState c = cameraOnPath(p, k.t);
    EXPECT_NEAR(glm::length(c.position - k.position), 0.0, 1e-9);
    EXPECT_NEAR(angle(c.forward, glm::normalize(k.lookAt - k.position)), 0.0, 1e-6);
    EXPECT_FLOAT_EQ(c.fov, k.fov);
    EXPECT_EQ(c.time, k.time);
  }
  const CameraState mid = cameraOnPath(p, 0.25);
  EXPECT_FLOAT_EQ(mid.fov, 70.0f);
  EXPECT_EQ(mid.time, 500);
}

TEST(CameraPath, PositionsFollowACatmullRomSpline) {
  // Through four collinear, evenly spaced points a Catmull-Rom spline is the straight line.
  const CameraPath p = path({key(0.0, {0, 0, 0}, {0, 0, -1}), key(1.0 / 3, {3, 0, 0}, {3, 0, -1}),
                             key(2.0 / 3, {6, 0, 0}, {6, 0, -1}), key(1.0, {9, 0, 0}, {9, 0, -1})});
  EXPECT_NEAR(cameraOnPath(p, 0.5).position.x, 4.5, 1e-9);
  // And it is smooth: bending through a corner, not a polyline's kink.
  const CameraPath corner = path({key(0.0, {0, 0, 0}, {0, 0, -1}), key(0.5, {10, 0, 0}, {10, 0, -1}),
                                  key(1.0, {10, 0, 10}, {10, 0, 9})});
  const CameraState c = cameraOnPath(corner, 0.75);
  EXPECT_GT(c.position.x, 10.0) << "the spline overshoots the corner a little, unlike a straight segment";
}

// Orientation through a straight-down keyframe: consecutive frames never turn by much more than the
// path's own steps, and screen-up never flips.
TEST(CameraPath, OrientationNeverFlipsThroughStraightDown) {
  const CameraPath p = path({key(0.0, {0, 70, 10}, {0, 60, 0}), key(0.5, {0, 70, 0}, {0, 60, 0}),
                             key(1.0, {0, 70, -10}, {0, 60, -20})},
                            201);
  CameraState previous = cameraOnPath(p, 0.0);
  for (int i = 1; i <= 200; ++i) {
    const CameraState c = cameraOnPath(p, i / 200.0);
    EXPECT_LT(angle(c.forward, previous.forward), 0.05) << "frame " << i;
    EXPECT_LT(angle(c.up, previous.up), 0.05) << "frame " << i;
    EXPECT_NEAR(glm::dot(c.up, c.forward), 0.0, 1e-9);
    EXPECT_NEAR(glm::length(c.forward), 1.0, 1e-9);
    previous = c;
  }
  const CameraState down = cameraOnPath(p, 0.5);
  EXPECT_NEAR(down.forward.y, -1.0, 1e-9);
}

TEST(CameraPath, FramesMapToEvenlySpacedT) {
  SceneFile scene;
  scene.cameraPath =
      path({key(0.0, {0, 70, 0}, {0, 70, -1}, 70, 0), key(1.0, {0, 70, 0}, {0, 70, -1}, 70, 800)}, 5);
  EXPECT_EQ(cameraAtFrame(scene, 0).time, 0);
  EXPECT_EQ(cameraAtFrame(scene, 1).time, 200);
  EXPECT_EQ(cameraAtFrame(scene, 4).time, 800);
  scene.cameraPath->frames = 1;
  EXPECT_EQ(cameraAtFrame(scene, 0).time, 0);
}

TEST(CameraPath, DegenerateInputsStayFinite) {
  const CameraPath p =
      path({key(0.0, {1, 2, 3}, {1, 2, 3}), key(1.0, {1, 2, 3}, {1, 12, 3}, 1.0f, 1'000'000'000'000)});
  for (double t : {-1.0, 0.0, 0.3, 1.0, 2.0, std::nan("")}) {
    const CameraState c = cameraOnPath(p, t);
    EXPECT_TRUE(std::isfinite(c.forward.x) && std::isfinite(c.up.y) && std::isfinite(c.position.z)) << t;
    EXPECT_NEAR(glm::length(c.up), 1.0, 1e-9);
  }
  EXPECT_EQ(cameraOnPath(p, 1.0).time, 1'000'000'000'000);
}

TEST(CameraPath, ScenesParseKeyframesWithDefaultsAndFrameEdits) {
  const SceneFile scene = parseScene(R"({
      "time": 100, "camera": {"fov": 55},
      "world": {"edits": [{"set": [0, 64, 0], "block": "torch", "at_frame": 3}]},
      "camera_path": {"frames": 4, "keyframes": [
        {"t": 0, "position": [0, 70, 0], "look_at": [0, 70, -1]},
        {"t": 1, "position": [5, 70, 0], "look_at": [5, 70, -1], "fov": 80, "time": 900}]}})",
                                     "a.json");
  ASSERT_TRUE(scene.cameraPath);
  EXPECT_EQ(scene.frameCount(), 4);
  EXPECT_FLOAT_EQ(scene.cameraPath->keyframes[0].fov, 55.0f);
  EXPECT_EQ(scene.cameraPath->keyframes[0].time, 100);
  EXPECT_EQ(scene.cameraPath->keyframes[1].time, 900);
  EXPECT_EQ(scene.edits[0].atFrame, 3);
}

std::string errorOf(const std::string& json) {
  return testing::errorOf([&] { parseScene(json, "a.json"); });
}

TEST(CameraPath, BadPathsNameTheKey) {
  EXPECT_NE(errorOf(R"({"camera_path": {"keyframes": []}})")
                .find("a.json: camera_path.keyframes: expected a non-empty"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"camera_path": {"frames": 2}})").find("a.json: camera_path: needs \"keyframes\""),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"camera_path": {"keyframes": [{"t": 0, "look_at": [0,0,0]}]}})")
                .find("camera_path.keyframes[0]: needs \"position\""),
            std::string::npos);
  EXPECT_NE(
      errorOf(R"({"camera_path": {"keyframes": [{"t": -0.1, "position": [0,0,0], "look_at": [0,0,1]}]}})")
          .find("camera_path.keyframes[0].t: expected a number from 0 to 1"),
      std::string::npos);
  EXPECT_NE(errorOf(R"({"camera_path": {"keyframes": [{"t": 0.5, "position": [0,0,0], "look_at": [0,0,1]},
                                                      {"t": 0.5, "position": [0,0,0], "look_at": [0,0,1]}]}})")
                .find("camera_path.keyframes[1].t: must be greater"),
            std::string::npos);
  EXPECT_NE(
      errorOf(
          R"({"camera_path": {"frames": 0, "keyframes": [{"t": 0, "position": [0,0,0], "look_at": [0,0,1]}]}})")
          .find("camera_path.frames"),
      std::string::npos);
  EXPECT_NE(errorOf(R"({"world": {"edits": [{"set": [0,0,0], "block": "stone", "at_frame": 1}]}})")
                .find("world.edits[0].at_frame: the scene has 1 frame(s)"),
            std::string::npos);
}

TEST(CameraPath, OverridesChangeAnyValueAndAreChecked) {
  const auto file = std::filesystem::temp_directory_path() / "terrasol_override_test.json";
  std::ofstream(file) << R"({"render": {"width": 320},
    "camera_path": {"keyframes": [{"t": 0, "position": [0, 70, 0], "look_at": [0, 70, -1]}]}})";
  const SceneFile scene = loadScene(file, {"render.width=640", "camera_path.keyframes.0.time=777",
                                           "world.generator=flat", "render.specular=\"ggx\""});
  EXPECT_EQ(scene.width, 640);
  EXPECT_EQ(scene.cameraPath->keyframes[0].time, 777);
  EXPECT_EQ(scene.generator, "flat");
  EXPECT_EQ(scene.specular, SpecularModel::Ggx);
  auto fails = [&](const std::string& setting, const std::string& part) {
    try {
      loadScene(file, {setting});
    } catch (const Error& e) {
      return std::string(e.what()).find(part) != std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(fails("render.widht=1", "render.widht: unknown key"));
  EXPECT_TRUE(fails("render.width=huge", "render.width: expected a whole number"));
  EXPECT_TRUE(fails("noequals", "--set noequals: expected key.path=value"));
  EXPECT_TRUE(fails("camera_path.keyframes.4.t=0", "index 4 is past the end"));
  EXPECT_TRUE(fails("render.width.x=1", "is inside a value that is not an object"));
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace terrasol
