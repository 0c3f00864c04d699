#include "render/shadow_schedule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/trigonometric.hpp>

namespace terrasol {
namespace {

using Action = ShadowPlan::Action;

ShadowSettings settings(int updateFrames) {
  ShadowSettings s;
  s.resolution = 1024;
  s.distance = 64.0f;  // texel 0.125 blocks: re-centred after 1 block
  s.updateFrames = updateFrames;
  return s;
}

ShadowFrame frameAt(glm::dvec3 camera, std::uint64_t meshes = 1) {
  ShadowFrame f;
  f.camera = camera;
  f.toLight = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
  f.meshes = meshes;
  f.cone.eye = camera;
  f.mayReuse = true;
  return f;
}

// Plans and carries out a frame, as the shadow pass does.
ShadowPlan step(ShadowSchedule& schedule, const ShadowFrame& frame) {
  const ShadowPlan plan = schedule.plan(frame);
  schedule.commit(plan);
  return plan;
}

TEST(ShadowScheduleTest, MeasuredRendersDrawTheWholeMapEveryFrame) {
  ShadowSchedule schedule(settings(4), false);
  ShadowFrame f = frameAt({0.0, 80.0, 0.0});
  f.mayReuse = false;
  for (int i = 0; i < 3; ++i) {
    const ShadowPlan plan = step(schedule, f);
    EXPECT_EQ(plan.action, Action::Whole);
    EXPECT_EQ(plan.slices.count, plan.slices.of);
  }
}

TEST(ShadowScheduleTest, AMapIsKeptUntilTheMeshesOrTheLightChange) {
  ShadowSchedule schedule(settings(1), false);
  ShadowFrame f = frameAt({0.0, 80.0, 0.0});
  EXPECT_EQ(step(schedule, f).action, Action::Whole) << "the first frame";
  EXPECT_EQ(step(schedule, f).action, Action::Keep);
  f.toLight = glm::normalize(f.toLight + glm::vec3(0.0002f, 0.0f, 0.0f));  // about 0.01 degrees
  EXPECT_EQ(step(schedule, f).action, Action::Keep) << "within 0.05 degrees";
  f.toLight = glm::normalize(f.toLight + glm::vec3(0.01f, 0.0f, 0.0f));  // about 0.5 degrees
  EXPECT_EQ(step(schedule, f).action, Action::Whole);
  f.meshes = 2;
  EXPECT_EQ(step(schedule, f).action, Action::Whole) << "a remeshed section";
  EXPECT_EQ(step(schedule, f).action, Action::Keep);
}

TEST(ShadowScheduleTest, TheCentreStaysPutForSmallMovesAndFollowsLargerOnes) {
  ShadowSchedule schedule(settings(1), false);
  const glm::dvec3 start(0.0, 80.0, 0.0);
  step(schedule, frameAt(start));
  const ShadowPlan small = step(schedule, frameAt(start + glm::dvec3(0.9, 0.0, 0.0)));
  EXPECT_EQ(small.action, Action::Keep) << "under 8 texels (1 block)";
  EXPECT_EQ(small.centre, start);
  const ShadowPlan large = step(schedule, frameAt(start + glm::dvec3(1.1, 0.0, 0.0)));
  EXPECT_EQ(large.action, Action::Whole);
  EXPECT_EQ(large.centre, start + glm::dvec3(1.1, 0.0, 0.0));
}

TEST(ShadowScheduleTest, ASpreadRebuildDrawsEverySliceOnceThenSwapsTheMapIn) {
  ShadowSchedule schedule(settings(4), false);
  const glm::dvec3 start(0.0, 80.0, 0.0);
  step(schedule, frameAt(start));
  const ShadowKey before = schedule.shown();
  int next = 0;
  for (int frame = 0; frame < 4; ++frame) {
    const ShadowPlan plan = step(schedule, frameAt(start, 2));  // remeshed: a rebuild
    ASSERT_EQ(plan.action, Action::Spread);
    EXPECT_EQ(plan.slices.first, next);
    EXPECT_EQ(plan.slices.count, 1) << "a still camera: one slice a frame";
    EXPECT_EQ(plan.slices.of, 4);
    EXPECT_EQ(plan.startsBuild, frame == 0);
    EXPECT_EQ(plan.completes, frame == 3);
    EXPECT_EQ(plan.key.meshes, 2u) << "every slice draws the same build";
    EXPECT_EQ(schedule.shown().meshes, frame == 3 ? 2u : before.meshes) << "the old map serves until then";
    next += plan.slices.count;
  }
  EXPECT_FALSE(schedule.building());
  EXPECT_EQ(step(schedule, frameAt(start, 2)).action, Action::Keep);
}

TEST(ShadowScheduleTest, AFastCameraGetsMoreSlicesAFrameAndAJumpRedrawsWhole) {
  ShadowSchedule schedule(settings(4), false);
  glm::dvec3 camera(0.0, 80.0, 0.0);
  step(schedule, frameAt(camera));
  const double reach = ShadowSchedule::kKeptReach * 64.0;  // 16 blocks
  // A sixteenth of the distance a frame: a build must land within half the reach, two frames.
  for (int frame = 0; frame < 6; ++frame) {
    camera.x += 4.0;
    const ShadowPlan plan = step(schedule, frameAt(camera));
    ASSERT_EQ(plan.action, Action::Spread) << "frame " << frame;
    EXPECT_EQ(plan.slices.count, 2) << "frame " << frame;
  }
  camera.x += 2.0 * reach;
  EXPECT_EQ(step(schedule, frameAt(camera)).action, Action::Whole) << "a teleport";
}

TEST(ShadowScheduleTest, ATurnPastHalfTheMarginRebuildsAndPastAllOfItRedrawsWhole) {
  ShadowSchedule schedule(settings(4), true);
  ShadowFrame f = frameAt({0.0, 80.0, 0.0});
  f.cone.aspect = 16.0f / 9.0f;
  step(schedule, f);
  const auto turned = [&](float degrees) {
    ShadowFrame t = f;
    const float a = glm::radians(degrees);
    t.cone.forward = glm::vec3(-std::sin(a), 0.0f, -std::cos(a));
    t.forward = glm::dvec3(t.cone.forward);
    return t;
  };
  EXPECT_EQ(step(schedule, turned(3.0f)).action, Action::Keep) << "inside half the margin";
  EXPECT_EQ(step(schedule, turned(10.0f)).action, Action::Spread) << "past half the margin: a rebuild starts";
  EXPECT_EQ(step(schedule, turned(20.0f)).action, Action::Whole)
      << "past the margin: the kept map is dropped";
}

}  // namespace
}  // namespace terrasol
