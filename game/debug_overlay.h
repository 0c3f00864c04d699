#pragma once
// The F3 overlay: frame rate and its graph, ms per pass, where the player is and what they look at,
// light, time, chunks and sections on the left; memory, GL, display, render scale, shadows, the debug
// view (F4) and the targeted block on the right.

#include <cstdio>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/render_settings.h"
#include "lod/lod_terrain.h"
#include "render/pass_clock.h"
#include "settings.h"
#include "targeting.h"

namespace terrasol {

class GameRenderer;
class PlayWorld;

class DebugOverlay {
 public:
  explicit DebugOverlay(std::string glRenderer) : glRenderer_(std::move(glRenderer)) {}

  bool shown() const { return shown_; }
  void toggle() { shown_ = !shown_; }
  DebugView view() const { return view_; }
  void nextView() {
    view_ = static_cast<DebugView>((static_cast<std::size_t>(view_) + 1) % kDebugViews.size());
  }
  const std::string& glRenderer() const { return glRenderer_; }

  // Each frame's time in seconds (the rate), and that of each drawn frame (the graph).
  void frameTime(double seconds);
  void drawnFrameTime(double seconds);
  const std::deque<float>& graph() const { return graph_; }
  // The last timed frame's passes (filled by the renderer).
  std::vector<PassTiming>& timings() { return timings_; }

  // `scale`: the render scale the frame was drawn at.
  // `far`: far terrain's tiles, when it is on.
  std::vector<std::string> left(const PlayWorld& world, const GameRenderer& renderer,
                                const std::optional<LodTerrainStats>& far = std::nullopt) const;
  std::vector<std::string> right(const PlayWorld& world, const GameSettings& settings, glm::ivec2 size,
                                 float scale, const std::optional<Target>& target) const;

 private:
  std::string glRenderer_;
  bool shown_ = false;
  DebugView view_ = DebugView::None;
  std::vector<PassTiming> timings_;
  std::vector<double> frameTimes_;  // seconds, the last second's
  std::deque<float> graph_;         // ms, the last frames' (the F3 graph)
};

// printf into a std::string (overlay lines are short).
template <class... Args>
std::string format(const char* fmt, Args... args) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, fmt, args...);
  return buffer;
}

}  // namespace terrasol
