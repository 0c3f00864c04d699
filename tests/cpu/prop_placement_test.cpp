// Props in scenes (engine/scene): the "props" key parses with errors naming the prop, placements
// turn and scale models as documented, and the voxel light at a prop's vertices is the mesher's kind
// of smooth light.

#include "scene/prop_placement.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/scene_world.h"
#include "support/error_of.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;

std::string errorOf(const std::string& json) {
  return testing::errorOf([&] { parseScene(json, "scenes/a.json"); });
}

TEST(SceneProps, ParseWithDefaultsAndPathsBesideTheScene) {
  const SceneFile scene = parseScene(R"({ "props": [
      { "model": "models/box.glb" },
      { "model": "/abs/cube.gltf", "position": [1.5, 64, -2], "rotation": [90, 0, 10], "scale": 0.25 } ] })",
                                     "scenes/a.json");
  ASSERT_EQ(scene.props.size(), 2u);
  EXPECT_EQ(scene.props[0].model, std::filesystem::path("scenes/models/box.glb"));
  EXPECT_EQ(scene.props[0].position, glm::dvec3(0.0));
  EXPECT_EQ(scene.props[0].rotation, glm::vec3(0.0f));
  EXPECT_EQ(scene.props[0].scale, 1.0f);
  EXPECT_EQ(scene.props[1].model, std::filesystem::path("/abs/cube.gltf"));
  EXPECT_EQ(scene.props[1].position, glm::dvec3(1.5, 64.0, -2.0));
  EXPECT_EQ(scene.props[1].rotation, glm::vec3(90.0f, 0.0f, 10.0f));
  EXPECT_EQ(scene.props[1].scale, 0.25f);
  EXPECT_EQ(scene.props[1].key, "props[1]");
}

TEST(SceneProps, BadPropsNameThePropAndWhatIsWrong) {
  EXPECT_EQ(errorOf(R"({ "props": {} })"), "scenes/a.json: props: expected an array of props, got an object");
  EXPECT_NE(errorOf(R"({ "props": [ { "position": [0, 0, 0] } ] })").find("props[0]: needs \"model\""),
            std::string::npos);
  EXPECT_NE(
      errorOf(R"({ "props": [ { "model": "" } ] })").find("props[0].model: expected a non-empty string"),
      std::string::npos);
  EXPECT_NE(errorOf(R"({ "props": [ { "model": "a.glb", "scale": 0 } ] })").find("props[0].scale"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({ "props": [ { "model": "a.glb", "rotation": [1, 2] } ] })").find("props[0].rotation"),
            std::string::npos);
  EXPECT_NE(
      errorOf(R"({ "props": [ { "model": "a.glb" }, { "model": "b.glb", "colour": 1 } ] })").find("props[1]"),
      std::string::npos);
}

TEST(PropPlacement, YawPitchRollThenScaleThenPosition) {
  SceneProp prop;
  prop.position = {10.0, 64.0, -3.0};
  prop.scale = 2.0f;
  prop.rotation = {90.0f, 0.0f, 0.0f};  // yaw: +x turns to -z (right-handed about +y)
  const PropTransform yaw = propTransform(prop);
  const glm::dvec3 p = toWorld(yaw, {1.0f, 0.0f, 0.0f});
  EXPECT_NEAR(p.x, 10.0, 1e-5);
  EXPECT_NEAR(p.y, 64.0, 1e-5);
  EXPECT_NEAR(p.z, -5.0, 1e-5);
  prop.rotation = {0.0f, 90.0f, 0.0f};  // pitch: +y turns to +z
  const glm::dvec3 q = toWorld(propTransform(prop), {0.0f, 1.0f, 0.0f});
  EXPECT_NEAR(q.z, -3.0 + 2.0, 1e-5);
  EXPECT_NEAR(q.y, 64.0, 1e-5);
  // The rotation alone turns normals; it stays orthonormal whatever the scale.
  const glm::mat3 r = propTransform(prop).rotation;
  EXPECT_NEAR(glm::determinant(r), 1.0f, 1e-5f);
  // Bounds of a unit box turned 45 degrees grow to the diagonal.
  prop.rotation = {45.0f, 0.0f, 0.0f};
  prop.scale = 1.0f;
  const WorldBounds b = placedBounds(propTransform(prop), glm::vec3(-0.5f), glm::vec3(0.5f));
  EXPECT_NEAR(b.max.x - b.min.x, std::sqrt(2.0), 1e-5);
  EXPECT_NEAR(b.max.y - b.min.y, 1.0, 1e-5);
  // Far from the origin the position keeps its precision (double).
  prop.position = {29'999'000.25, 64.0, -29'999'000.75};
  EXPECT_EQ(toWorld(propTransform(prop), glm::vec3(0.0f)).x, 29'999'000.25);
}

TEST(PropPlacement, VertexLightIsSmoothAndLeavesSolidCellsOut) {
  SceneFile scene = parseScene(R"({ "world": { "generator": "flat" }, "render": { "view_distance": 1 },
                                    "camera": { "position": [0, 70, 0], "look_at": [0, 64, -5] } })",
                               "test.json");
  // A sealed stone room 5 x 2 x 5 with a torch in the middle: no sky light inside.
  scene.edits.push_back({SceneEdit::Kind::Fill, {-3, 64, -3}, {3, 66, 3}, "stone", "world.edits[0]"});
  scene.edits.push_back({SceneEdit::Kind::Fill, {-2, 64, -2}, {2, 65, 2}, "air", "world.edits[1]"});
  scene.edits.push_back({SceneEdit::Kind::Set, {0, 64, 0}, {0, 64, 0}, "torch", "world.edits[2]"});
  const SceneWorld world(scene, defaultBlocks());
  const std::vector<glm::dvec3> points = {
      {1.5, 64.5, 0.5},  // the centre of the cell beside the torch: exactly its level, 13
      {1.0, 64.5, 0.5},  // halfway between the torch's cell (14) and that one (13)
      {2.5, 64.0, 0.5},  // on the floor: the stone below is left out, the air cell above counts alone
      {0.5, 67.5, 0.5},  // outside, above the roof in the open sky
      {0.5, 62.5, 0.5},  // inside the ground: all 8 cells solid, dark
  };
  const std::vector<glm::vec2> light = smoothLightAt(world.world(), world.light(), points);
  EXPECT_FLOAT_EQ(light[0].x, 13.0f / 15.0f);
  EXPECT_FLOAT_EQ(light[1].x, 13.5f / 15.0f);
  EXPECT_FLOAT_EQ(light[2].x, 12.0f / 15.0f);
  EXPECT_FLOAT_EQ(light[0].y, 0.0f) << "sealed: no sky light";
  EXPECT_FLOAT_EQ(light[3].y, 1.0f);
  EXPECT_EQ(light[4], glm::vec2(0.0f));
}

}  // namespace
}  // namespace terrasol
