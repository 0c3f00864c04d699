#pragma once
// When the shadow map is drawn, kept or rebuilt a slice at a time: the policy, apart from the GL work.
//
// - Centre: the map follows the camera (moved `shiftAhead` of its distance ahead of a warped map) but
//   stays put until the camera is kRecentreTexels of the finest layer away. Snapping to whole texels
//   alone keeps an unwarped map stable in exact arithmetic, but the warp around a centre that steps
//   moves world points by fractions of a texel and casters' float vertices round differently after a
//   step, so every step flips a few shadow edges; re-centring rarely turns that crawl into an
//   occasional step.
// - Keep (the game: FrameInputs::reuseShadowMap): nothing the map shows changed (centre, meshes, props,
//   the light within 0.05 degrees) and it still serves the view, so no shadow pass runs.
// - Spread (update_frames N > 1, Luanti's shadow_update_frames): a changed map is rebuilt into a
//   second map, slices of its casters a frame, and swapped in when complete; no frame pays the whole
//   pass. At the camera's pace a build ends before the kept map falls kKeptReach behind.
// - Whole: otherwise (measured renders, a first frame, a jump) the map is drawn whole at once.
//
// The caster view is wider than the camera's (kMarginDegrees a side, apex kPullBack behind), so a kept
// or spread map still serves a camera that turned or moved since; a new map is started once half that
// margin is used, and a whole redraw happens only once all of it is (shadow_receivers.h).
// Plain C++, no GL; plan() decides, commit() applies a decision that was carried out.

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>

#include "core/render_settings.h"
#include "render/shadow_receivers.h"

namespace terrasol {

// What a map was drawn for.
struct ShadowKey {
  glm::dvec3 centre{0.0};
  glm::vec3 toLight{0.0f};
  std::uint64_t meshes = 0;  // SectionMeshes::generation
  std::uint64_t props = 0;   // Props::generation
  std::uint64_t far = 0;     // LodMeshes::generation (far terrain casts too)
  bool valid = false;
  std::optional<ShadowReceivers> receivers;  // what its casters were chosen for; none: every caster
};

// Casters are split into `of` slices by a hash of their section; this draw covers [first, first + count).
struct ShadowSlices {
  int first = 0, count = 1, of = 1;
};

// One frame as the schedule sees it.
struct ShadowFrame {
  glm::dvec3 camera{0.0};
  glm::dvec3 centreOffset{0.0};                  // FrameInputs::shadowCentreOffset
  glm::dvec3 forward{0.0, 0.0, -1.0};            // unit view direction
  glm::vec3 toLight{0.0f, 1.0f, 0.0f};           // unit
  std::uint64_t meshes = 0, props = 0, far = 0;  // generations
  ViewCone cone;                                 // the camera's receivers
  bool mayReuse = false;                         // FrameInputs::reuseShadowMap
};

struct ShadowPlan {
  enum class Action { Keep, Spread, Whole };
  Action action = Action::Whole;
  ShadowKey key;             // the map drawn (Spread: the one being built)
  ShadowSlices slices;       // Spread: this frame's; Whole: all of them
  bool startsBuild = false;  // Spread: the build's first slice (the map is cleared first)
  bool completes = false;    // Spread: the built map replaces the shown one after this slice
  int slicesDrawn = 0;     // for the frame's stats: Spread its count, Whole all the slices there are, Keep 0
  glm::dvec3 wanted{0.0};  // where the camera wants the map this frame
  glm::dvec3 centre{0.0};  // where it is placed (re-centred rarely)
};

class ShadowSchedule {
 public:
  // How far, as a fraction of the shadow distance, a kept map's centre may fall behind the camera's
  // before it is redrawn whole; spread rebuilds are paced to land within it.
  static constexpr double kKeptReach = 0.25;
  static constexpr double kRecentreTexels = 8.0;
  static constexpr float kMarginDegrees = 15.0f, kPullBack = 16.0f;

  ShadowSchedule(const ShadowSettings& settings, bool casterCulling)
      : settings_(settings), casterCulling_(casterCulling) {}

  ShadowPlan plan(const ShadowFrame& frame) const;
  // Applies a plan whose draw was carried out (or a Keep).
  void commit(const ShadowPlan& plan);
  // The map shown this frame, after commit.
  const ShadowKey& shown() const { return shown_; }
  bool building() const { return build_.has_value(); }

 private:
  struct Build {
    ShadowKey key;
    int slice = 0;  // slices drawn so far
  };
  glm::dvec3 recentred(glm::dvec3 wanted) const;

  ShadowSettings settings_;
  bool casterCulling_;
  ShadowKey shown_;
  std::optional<Build> build_;
  std::optional<glm::dvec3> centre_;      // where the map is centred, kept between frames
  std::optional<glm::dvec3> lastWanted_;  // last frame's, for how fast the map falls behind
};

}  // namespace terrasol
