#include "benchmark.h"

#include <stdlib.h>

#include <cmath>
#include <glm/trigonometric.hpp>
#include <map>
#include <nlohmann/json.hpp>

#include "core/day_cycle.h"
#include "core/error.h"
#include "frame_rate.h"
#include "game.h"
#include "platform/glfw/glfw_window.h"
#include "scene/camera_path.h"

namespace terrasol {
namespace {

double ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// Where the camera is at each moment of the flight.
class Flight {
 public:
  Flight(PlayWorld& world, const GameOptions& options) : world_(world), seconds_(*options.benchmark) {
    if (options.benchmarkPath.empty()) return;
    scene_ = loadScene(options.benchmarkPath);
    if (!scene_->cameraPath)
      throw Error(options.benchmarkPath.string() + ": --benchmark needs a camera_path");
  }
  bool onPath() const { return scene_.has_value(); }

  // Puts the player's eye where the flight is `t` seconds in.
  void place(double t) {
    Player& player = world_.player();
    player.flying = true;
    if (scene_) {
      const CameraState c = cameraOnPath(*scene_->cameraPath, std::min(t / seconds_, 1.0));
      lookFrom(c.position, c.forward);
      world_.level().time = c.time;
      return;
    }
    // The circle: 20 blocks over the ground below, followed smoothly (over the hills, never into them).
    glm::dvec3 eye = circle(t);
    const glm::dvec3 ahead = circle(t + 0.5);
    const auto ground =
        world_.streamed().surfaceY(static_cast<int>(std::floor(eye.x)), static_cast<int>(std::floor(eye.z)));
    const double target = ground ? *ground + 20.0 : std::max(altitude_, 100.0);
    altitude_ =
        altitude_ == 0.0 ? target : altitude_ + (target - altitude_) * std::min(1.0, (t - lastT_) * 2.0);
    lastT_ = t;
    eye.y = altitude_;
    player.teleport(eye - glm::dvec3(0.0, Player::kEyeHeight, 0.0));
    player.yaw = static_cast<float>(glm::degrees(std::atan2(-(ahead.x - eye.x), ahead.z - eye.z)));
    player.pitch = 20.0f;
  }
  // Forgets the height followed so far (placed again once the ground there is known).
  void resetAltitude() { altitude_ = 0.0; }

 private:
  // A circle of 96 blocks round the spawn at sprint-flying speed.
  static glm::dvec3 circle(double t) {
    constexpr double kRadius = 96.0, kSpeed = 21.6;
    const double a = t * kSpeed / kRadius;
    return {kRadius * std::cos(a), 0.0, kRadius * std::sin(a)};
  }
  void lookFrom(glm::dvec3 eye, glm::dvec3 forward) {
    Player& player = world_.player();
    player.teleport(eye - glm::dvec3(0.0, Player::kEyeHeight, 0.0));
    player.yaw = static_cast<float>(glm::degrees(std::atan2(-forward.x, forward.z)));
    player.pitch = static_cast<float>(glm::degrees(std::asin(std::clamp(-forward.y, -1.0, 1.0))));
  }

  PlayWorld& world_;
  double seconds_;
  std::optional<SceneFile> scene_;
  double altitude_ = 0.0, lastT_ = 0.0;
};

void printSummary(Game& game, const FrameRateSummary& fps, double seconds) {
  const GameSettings& settings = game.settings();
  const glm::ivec2 size = game.window().framebufferSize();
  const ShadowSettings& s = settings.shadow;
  std::printf("benchmark: %zu frames in %.1f s at %dx%d, view %d chunks, shadows %s\n", fps.frames, seconds,
              size.x, size.y, settings.viewDistance,
              s.enabled ? format("%s %d^2 over %.0f blocks, pcf %d, updates over %d frames",
                                 std::string(nameOf(s.mode, kShadowModes)).c_str(), s.resolution, s.distance,
                                 s.pcfSamples, s.updateFrames)
                              .c_str()
                        : "off");
  std::printf(
      "benchmark: render scale %s\n",
      settings.targetFps > 0
          ? format("dynamic for %d fps (at most %.2f)", settings.targetFps, settings.renderScale).c_str()
          : format("%.2f", settings.renderScale).c_str());
  std::printf("benchmark: median %.1f fps (%.2f ms), 1%% low %.1f fps (%.2f ms), mean %.1f fps\n",
              fps.medianFps, fps.medianMs, fps.onePercentLowFps, fps.onePercentLowMs, fps.meanFps);
}

}  // namespace

std::filesystem::path benchmarkWorldDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "terrasol-benchmark-XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw Error("cannot create a temporary world for --benchmark");
  return pattern;
}

int runBenchmark(Game& game, const GameOptions& options) {
  const double seconds = *options.benchmark;
  PlayWorld& world = game.world();
  GlfwWindow& window = game.window();
  world.level().time = kNoon;  // the sun casts shadows the whole run
  world.time().stop();
  game.ui().showHud();
  Flight flight(world, options);
  // The start is loaded and meshed before the clock runs (a player waits for the world to load too).
  flight.place(0.0);
  flight.resetAltitude();
  const auto loadDeadline = Clock::now() + std::chrono::seconds(120);
  while (Clock::now() < loadDeadline && !window.shouldClose()) {
    game.frameStep(0.0, {.play = false, .hud = false, .pace = false});
    if (world.ready()) break;
  }
  // And shown from where the clock starts for a second, so its first frame does not redraw the shadow
  // map whole and dynamic resolution starts settled, as it is in play.
  flight.place(0.0);
  for (int i = 0; i < 30 && !window.shouldClose(); ++i) game.frameStep(0.0, {.play = false, .finish = true});
  std::vector<double> frames;
  nlohmann::json timeline = nlohmann::json::array();  // what each frame did, for --benchmark-json
  const Clock::time_point begin = Clock::now();
  double t = 0.0;
  while (t < seconds && !window.shouldClose()) {
    flight.place(t);
    const float scale = game.renderScale();  // what this frame is drawn at
    const FrameTimes f = game.frameStep(0.0, {.play = false, .finish = true});
    frames.push_back(f.seconds());
    const FrameStats& stats = game.renderer().lastFrame();
    timeline.push_back({{"t", t},
                        {"ms", ms(f.start, f.done)},
                        {"world_ms", ms(f.start, f.streamed)},
                        {"uploads", f.uploads},
                        {"scale", scale},
                        {"shadow_slices", stats.shadowSlices},
                        {"quads", stats.quadsDrawn}});
    t = std::chrono::duration<double>(Clock::now() - begin).count();
  }
  if (frames.empty()) throw Error("--benchmark: no frame was drawn");
  const FrameRateSummary fps = summarizeFrames(frames);
  printSummary(game, fps, t);
  // Then where the time goes: the same flight on, with a glFinish after each pass (slower frames).
  std::map<std::string, double> passMs;
  constexpr int kTimedFrames = 40;
  for (int i = 0; i < kTimedFrames && !window.shouldClose(); ++i) {
    flight.place(flight.onPath() ? seconds * i / kTimedFrames : t + i / 20.0);
    const bool last = i + 1 == kTimedFrames && !options.screenshot.empty();
    const FrameTimes f = game.frameStep(
        0.0, {.play = false, .passTimes = true, .finish = true, .pace = false, .screenshot = last});
    passMs["~world"] += ms(f.start, f.streamed) / kTimedFrames;
    passMs["~hud"] += ms(f.drawn, f.hud) / kTimedFrames;
    passMs["~swap"] += ms(f.hud, f.done) / kTimedFrames;
    for (const PassTiming& p : game.overlay().timings()) passMs[p.pass] += p.ms / kTimedFrames;
  }
  std::string passes;
  for (const auto& [pass, passTime] : passMs) passes += format(" %s %.1f", pass.c_str(), passTime);
  std::printf("benchmark: mean ms per pass over %d more frames:%s\n", kTimedFrames, passes.c_str());
  std::printf("benchmark: GL %s\n", game.overlay().glRenderer().c_str());
  if (!options.benchmarkJson.empty()) {
    const glm::ivec2 size = window.framebufferSize();
    writeFileAtomically(options.benchmarkJson,
                        nlohmann::json{{"gl", game.overlay().glRenderer()},
                                       {"size", {size.x, size.y}},
                                       {"view_distance", game.settings().viewDistance},
                                       {"path", flight.onPath() ? options.benchmarkPath.string() : "circle"},
                                       {"median_ms", fps.medianMs},
                                       {"one_percent_low_ms", fps.onePercentLowMs},
                                       {"pass_ms", passMs},
                                       {"frames", timeline}}
                                .dump(1) +
                            "\n");
  }
  return 0;
}

}  // namespace terrasol
