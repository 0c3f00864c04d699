// Fitting the frames to the machine: the first start's probe, and dynamic resolution after each frame.
#include "game_session.h"

#include <epoxy/gl.h>

#include <algorithm>

#include "core/log.h"
#include "first_run.h"

namespace terrasol::session {

void Game::probeMachine() {
  if (drawableSize().x <= 0 || drawableSize().y <= 0) return;
  std::vector<double> ms;
  for (int i = 0; i < 7; ++i) {
    const Clock::time_point start = Clock::now();
    draw(false);
    glFinish();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  ms.erase(ms.begin());  // the first pays for shader and target creation
  std::sort(ms.begin(), ms.end());
  settings_ = firstRunSettings({glRenderer_, ms[ms.size() / 2]}, settings_);
  renderer_.applySettings(settings_);
  world_.setViewDistance(settings_.viewDistance);
  resolution_.setMaxScale(settings_.renderScale);
  logInfo("first start: " + settings_.firstRun->choice);
  if (!options_.benchmark) saveSettings(settingsFile_, settings_);
}

void Game::frameDone(double seconds) {
  frameGraph_.push_back(static_cast<float>(seconds * 1000.0));
  if (frameGraph_.size() > 240) frameGraph_.pop_front();
  resolution_.setMaxScale(settings_.renderScale);
  if (settings_.targetFps > 0) resolution_.update(seconds * 1000.0, settings_.targetFps);
}

}  // namespace terrasol::session
