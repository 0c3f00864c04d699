#include "render/shadow_schedule.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace terrasol {

namespace {

constexpr float kReuseCos = 0.99999962f;  // cos(0.05 degrees): 5 cm of edge movement 60 blocks away

}  // namespace

glm::dvec3 ShadowSchedule::recentred(glm::dvec3 wanted) const {
  const double texel = 2.0 * cascadeDistance(settings_, 0) / std::max(settings_.resolution, 1);
  if (!centre_ || glm::length(wanted - *centre_) > kRecentreTexels * texel) return wanted;
  return *centre_;
}

ShadowPlan ShadowSchedule::plan(const ShadowFrame& frame) const {
  ShadowPlan plan;
  // Cascades are picked by distance from the camera, so only the single warped map moves ahead.
  const glm::dvec3 forward(frame.forward.x, 0.0, frame.forward.z);
  const double along = glm::length(forward);
  const glm::dvec3 ahead =
      settings_.mode == ShadowMode::Warped && along > 1e-6
          ? forward / along * static_cast<double>(settings_.shiftAhead * settings_.distance)
          : glm::dvec3(0.0);
  plan.wanted = frame.camera + frame.centreOffset + ahead;
  plan.centre = recentred(plan.wanted);
  const double step = lastWanted_ ? glm::length(plan.wanted - *lastWanted_) : 0.0;

  ShadowKey wanted{plan.centre, frame.toLight, frame.meshes, frame.props, frame.far, true, std::nullopt};
  if (casterCulling_) wanted.receivers.emplace(frame.cone.widened(kMarginDegrees, kPullBack));
  const auto serves = [&](const ViewCone& cone) {
    return !shown_.receivers || shown_.receivers->contains(cone);
  };
  const bool unchanged = shown_.valid && shown_.centre == plan.centre && shown_.meshes == wanted.meshes &&
                         shown_.props == wanted.props && shown_.far == wanted.far &&
                         glm::dot(shown_.toLight, wanted.toLight) > kReuseCos &&
                         serves(frame.cone.widened(0.5f * kMarginDegrees, 0.5f * kPullBack));
  const int slices = frame.mayReuse ? std::max(settings_.updateFrames, 1) : 1;
  // A kept map must still cover the camera well; a jump (a teleport) redraws it whole at once.
  const double reach = kKeptReach * settings_.distance;
  const double used = glm::length(plan.centre - shown_.centre);
  const bool near = shown_.valid && used < reach && serves(frame.cone);
  if (frame.mayReuse && unchanged && !build_) {
    plan.action = ShadowPlan::Action::Keep;
    plan.key = shown_;
    return plan;
  }
  if (slices > 1 && near) {
    // The kept map serves until its centre is `reach` from the camera's. At a low frame rate a slice a
    // frame would not finish the new map by then, and the kept one would be redrawn whole in one
    // frame, again and again (hitches of a whole map). So, at the last frame's pace, a build is
    // finished by the time its own centre is half `reach` behind (the next build then has the other
    // half) and before the kept map runs out, spreading more slices a frame over the frames that leaves.
    plan.action = ShadowPlan::Action::Spread;
    plan.startsBuild = !build_;
    plan.key = build_ ? build_->key : wanted;
    const int done = build_ ? build_->slice : 0;
    const auto framesUntil = [&](double distance) {
      return step > 0.0 ? std::max(std::ceil(distance / step), 1.0) : 1e9;
    };
    const double frames = std::min(framesUntil(0.5 * reach - glm::length(plan.centre - plan.key.centre)),
                                   framesUntil(reach - used));
    const int remaining = slices - done;
    const int count = std::clamp(static_cast<int>(std::ceil(remaining / frames)), 1, remaining);
    plan.slices = {done, count, slices};
    plan.completes = done + count == slices;
    plan.slicesDrawn = count;
    return plan;
  }
  plan.action = ShadowPlan::Action::Whole;
  plan.key = wanted;
  plan.slices = {0, 1, 1};
  plan.slicesDrawn = slices;
  return plan;
}

void ShadowSchedule::commit(const ShadowPlan& plan) {
  centre_ = plan.centre;
  lastWanted_ = plan.wanted;
  switch (plan.action) {
    case ShadowPlan::Action::Keep:
      return;
    case ShadowPlan::Action::Spread:
      if (plan.startsBuild) build_ = Build{plan.key, 0};
      build_->slice += plan.slices.count;
      if (plan.completes) {
        shown_ = build_->key;
        build_.reset();
      }
      return;
    case ShadowPlan::Action::Whole:
      build_.reset();
      shown_ = plan.key;
      return;
  }
}

}  // namespace terrasol
