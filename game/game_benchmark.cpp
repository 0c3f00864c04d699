#include "game_session.h"

#include <epoxy/gl.h>
#include <stdlib.h>

#include <cmath>
#include <map>

#include <glm/trigonometric.hpp>

#include "core/error.h"
#include "frame_rate.h"
#include "platform/glfw/glfw_window.h"
#include "render/gl/render_target.h"

// --benchmark: a fixed flight over a throwaway world, timed frame by frame.

namespace terrasol::session {

std::filesystem::path benchmarkWorldDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "terrasol-benchmark-XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw Error("cannot create a temporary world for --benchmark");
  return pattern;
}

// A circle of 96 blocks around the spawn at sprint-flying speed (the height follows the ground).
glm::dvec3 Game::benchmarkEye(double t) const {
  constexpr double kRadius = 96.0, kSpeed = 21.6;
  const double a = t * kSpeed / kRadius;
  return {kRadius * std::cos(a), 0.0, kRadius * std::sin(a)};
}

int Game::runBenchmark() {
  const double seconds = *options_.benchmark;
  world_.level().time = 6000;  // noon: the sun casts shadows the whole run
  timeStopped_ = true;
  showHud_ = true;
  // 20 blocks over the ground below, followed smoothly (over the hills, never into them).
  double altitude = 0.0, lastT = 0.0;
  const auto place = [&](double t) {
    glm::dvec3 eye = benchmarkEye(t);
    const glm::dvec3 ahead = benchmarkEye(t + 0.5);
    const auto ground = world_.surfaceY(static_cast<int>(std::floor(eye.x)), static_cast<int>(std::floor(eye.z)));
    const double target = ground ? *ground + 20.0 : std::max(altitude, 100.0);
    altitude = altitude == 0.0 ? target : altitude + (target - altitude) * std::min(1.0, (t - lastT) * 2.0);
    lastT = t;
    eye.y = altitude;
    player_.teleport(eye - glm::dvec3(0.0, Player::kEyeHeight, 0.0));
    player_.yaw = static_cast<float>(glm::degrees(std::atan2(-(ahead.x - eye.x), ahead.z - eye.z)));
    player_.pitch = 20.0f;
    player_.flying = true;
  };
  // The start is loaded and meshed before the clock runs (a player waits for the world to load too).
  place(0.0);
  altitude = 0.0;  // placed again once the ground there is known
  const auto loadDeadline = Clock::now() + std::chrono::seconds(120);
  while (Clock::now() < loadDeadline && !window_.shouldClose()) {
    const Clock::time_point start = Clock::now();
    window_.pollEvents();
    stream(start);
    draw(false);
    window_.swapBuffers();
    if (worldReady()) break;
  }
  std::vector<double> frames;
  const Clock::time_point begin = Clock::now();
  double t = 0.0;
  while (t < seconds && !window_.shouldClose()) {
    const Clock::time_point start = Clock::now();
    window_.pollEvents();
    place(t);
    stream(start);
    draw(false);
    drawHud();
    window_.swapBuffers();
    glFinish();  // the frame is done when it is on screen, not when it is queued
    frames.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    t = std::chrono::duration<double>(Clock::now() - begin).count();
  }
  if (frames.empty()) throw Error("--benchmark: no frame was drawn");
  const FrameRateSummary fps = summarizeFrames(frames);
  const glm::ivec2 size = window_.framebufferSize();
  const ShadowSettings& s = settings_.shadow;
  std::printf("benchmark: %zu frames in %.1f s at %dx%d, view %d chunks, shadows %s\n", fps.frames, t, size.x, size.y,
              settings_.viewDistance,
              s.enabled ? format("%s %d^2 over %.0f blocks, pcf %d, updates over %d frames", std::string(nameOf(s.mode, kShadowModes)).c_str(), s.resolution,
                                 s.distance, s.pcfSamples, s.updateFrames).c_str()
                        : "off");
  std::printf("benchmark: median %.1f fps (%.2f ms), 1%% low %.1f fps (%.2f ms), mean %.1f fps\n", fps.medianFps,
              fps.medianMs, fps.onePercentLowFps, fps.onePercentLowMs, fps.meanFps);
  // Then where the time goes: the same flight on, with a glFinish after each pass (slower frames).
  std::map<std::string, double> passMs;
  constexpr int kTimedFrames = 40;
  for (int i = 0; i < kTimedFrames && !window_.shouldClose(); ++i) {
    const Clock::time_point start = Clock::now();
    window_.pollEvents();
    place(t + i / 20.0);
    stream(start);
    const Clock::time_point streamed = Clock::now();
    draw(true);
    const Clock::time_point drawn = Clock::now();
    drawHud();
    glFinish();
    const Clock::time_point hud = Clock::now();
    window_.swapBuffers();
    glFinish();
    const auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
    passMs["~world"] += ms(start, streamed) / kTimedFrames;
    passMs["~hud"] += ms(drawn, hud) / kTimedFrames;
    passMs["~swap"] += ms(hud, Clock::now()) / kTimedFrames;
    for (const PassTiming& p : timings_) passMs[p.pass] += p.ms / kTimedFrames;
  }
  if (!options_.screenshot.empty()) saveImage(options_.screenshot, readFramebuffer(0, window_.framebufferSize()));
  std::string passes;
  for (const auto& [pass, ms] : passMs) passes += format(" %s %.1f", pass.c_str(), ms);
  std::printf("benchmark: mean ms per pass over %d more frames:%s\n", kTimedFrames, passes.c_str());
  std::printf("benchmark: GL %s\n", glRenderer_.c_str());
  return 0;
}

}  // namespace terrasol::session
