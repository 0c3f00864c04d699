#include "game_session.h"

#include <epoxy/gl.h>
#include <stdlib.h>

#include <cmath>
#include <map>

#include <glm/trigonometric.hpp>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "scene/camera_path.h"
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
  // A scene file's camera path, flown over the benchmark's world in `seconds`.
  std::optional<SceneFile> scene;
  if (!options_.benchmarkPath.empty()) {
    scene = loadScene(options_.benchmarkPath);
    if (!scene->cameraPath) throw Error(options_.benchmarkPath.string() + ": --benchmark needs a camera_path");
  }
  // The circle: 20 blocks over the ground below, followed smoothly (over the hills, never into them).
  double altitude = 0.0, lastT = 0.0;
  const auto place = [&](double t) {
    if (scene) {
      const CameraState c = cameraOnPath(*scene->cameraPath, std::min(t / seconds, 1.0));
      player_.teleport(c.position - glm::dvec3(0.0, Player::kEyeHeight, 0.0));
      player_.yaw = static_cast<float>(glm::degrees(std::atan2(-c.forward.x, c.forward.z)));
      player_.pitch = static_cast<float>(glm::degrees(std::asin(std::clamp(-c.forward.y, -1.0, 1.0))));
      player_.flying = true;
      world_.level().time = c.time;
      return;
    }
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
  // And shown from where the clock starts for a second, so its first frame does not redraw the shadow
  // map whole and dynamic resolution starts settled, as it is in play.
  place(0.0);
  for (int i = 0; i < 30 && !window_.shouldClose(); ++i) {
    const Clock::time_point start = Clock::now();
    window_.pollEvents();
    stream(start);
    draw(false);
    drawHud();
    window_.swapBuffers();
    glFinish();
    frameDone(std::chrono::duration<double>(Clock::now() - start).count());
  }
  std::vector<double> frames;
  nlohmann::json timeline = nlohmann::json::array();  // what each frame did, for --benchmark-json
  const Clock::time_point begin = Clock::now();
  const auto ms = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
  };
  double t = 0.0;
  while (t < seconds && !window_.shouldClose()) {
    const Clock::time_point start = Clock::now();
    window_.pollEvents();
    place(t);
    const int uploads = stream(start);
    const Clock::time_point streamed = Clock::now();
    draw(false);
    drawHud();
    window_.swapBuffers();
    glFinish();  // the frame is done when it is on screen, not when it is queued
    const Clock::time_point done = Clock::now();
    frames.push_back(std::chrono::duration<double>(done - start).count());
    const float scale = settings_.targetFps > 0 ? resolution_.scale() : settings_.renderScale;
    frameDone(frames.back());
    const FrameStats& stats = renderer_.lastFrame();
    timeline.push_back({{"t", t},
                        {"ms", ms(start, done)},
                        {"world_ms", ms(start, streamed)},
                        {"uploads", uploads},
                        {"scale", scale},
                        {"shadow_slices", stats.shadowSlices},
                        {"quads", stats.quadsDrawn}});
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
  std::printf("benchmark: render scale %s\n",
              settings_.targetFps > 0 ? format("dynamic for %d fps (at most %.2f)", settings_.targetFps, settings_.renderScale).c_str()
                                      : format("%.2f", settings_.renderScale).c_str());
  std::printf("benchmark: median %.1f fps (%.2f ms), 1%% low %.1f fps (%.2f ms), mean %.1f fps\n", fps.medianFps,
              fps.medianMs, fps.onePercentLowFps, fps.onePercentLowMs, fps.meanFps);
  // Then where the time goes: the same flight on, with a glFinish after each pass (slower frames).
  std::map<std::string, double> passMs;
  constexpr int kTimedFrames = 40;
  for (int i = 0; i < kTimedFrames && !window_.shouldClose(); ++i) {
    const Clock::time_point start = Clock::now();
    window_.pollEvents();
    place(scene ? seconds * i / kTimedFrames : t + i / 20.0);
    stream(start);
    const Clock::time_point streamed = Clock::now();
    draw(true);
    const Clock::time_point drawn = Clock::now();
    drawHud();
    glFinish();
    const Clock::time_point hud = Clock::now();
    window_.swapBuffers();
    glFinish();
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
  if (!options_.benchmarkJson.empty()) {
    writeFileAtomically(options_.benchmarkJson,
                        nlohmann::json{{"gl", glRenderer_},
                                       {"size", {size.x, size.y}},
                                       {"view_distance", settings_.viewDistance},
                                       {"path", scene ? options_.benchmarkPath.string() : "circle"},
                                       {"median_ms", fps.medianMs},
                                       {"one_percent_low_ms", fps.onePercentLowMs},
                                       {"pass_ms", passMs},
                                       {"frames", timeline}}
                                .dump(1) +
                            "\n");
  }
  return 0;
}

}  // namespace terrasol::session
