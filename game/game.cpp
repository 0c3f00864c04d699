#include "game.h"
#include "game_session.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>
#include <thread>

#include "core/error.h"
#include "core/log.h"
#include "core/paths.h"
#include "game_renderer.h"
#include "pipeline/streamed_world.h"
#include "hud.h"
#include "input_script.h"
#include "platform/glfw/glfw_window.h"
#include "player.h"
#include "render/gl/render_target.h"
#include "scene/block_atlas.h"
#include "scene_render/under_water.h"
#include "targeting.h"

namespace terrasol::session {
namespace {

constexpr const char* kHotbar[9] = {"stone",     "stone_slab", "oak_stairs", "oak_planks", "oak_log",
                                    "oak_fence", "glass_pane", "torch",      "oak_door"};
constexpr double kAutosaveSeconds = 300.0;
constexpr double kDoubleTapSeconds = 0.3;                  // two jump presses this close toggle flight
constexpr std::int64_t kTimePresets[] = {1000, 6000, 12000, 18000};  // morning, noon, sunset, midnight


std::filesystem::path screenshotName() {
  const std::time_t now = std::time(nullptr);
  char name[64];
  std::strftime(name, sizeof name, "%Y-%m-%d_%H.%M.%S", std::localtime(&now));
  std::filesystem::path file = std::filesystem::path("screenshots") / (std::string(name) + ".png");
  for (int i = 1; std::filesystem::exists(file); ++i) {
    file = std::filesystem::path("screenshots") / (std::string(name) + "_" + std::to_string(i) + ".png");
  }
  return file;
}

GameSettings settingsFor(const GameOptions& options, const std::filesystem::path& file) {
  GameSettings s = loadSettings(file);
  if (!options.packs.empty()) {
    s.packs.clear();
    for (const auto& p : options.packs) s.packs.push_back({std::filesystem::absolute(p), true});
  }
  return s;
}

std::uint64_t seedOf(const GameOptions& options) {
  if (options.benchmark) return options.seed.value_or(1);
  return options.seed ? *options.seed : std::random_device{}();
}

// Threads in each world pool (chunk loading, meshing): 2, or 3 where there are cores to spare.
int workerThreads() {
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(cores - 1, 2, 3);
}

}  // namespace

Game::Game(GlfwWindow& window, const GameOptions& options)
    : window_(window),
      options_(options),
      settingsFile_(options.settings.empty() ? defaultSettingsFile() : options.settings),
      settings_(settingsFor(options, settingsFile_)),
      blocks_(BlockRegistry::fromFile(resourcePackDir() / "default" / "blocks.json")),
      shapes_(defaultPackShapes(blocks_)),
      renderer_(blocks_, settings_),
      benchmarkDir_(options.benchmark ? benchmarkWorldDir() : std::filesystem::path()),
      world_(options.benchmark ? benchmarkDir_ : options.world, seedOf(options), blocks_, renderer_.assets().table,
             settings_.viewDistance, workerThreads(), &shapes_),
      controls_(settings_.keys) {
  for (std::size_t i = 0; i < hotbar_.size(); ++i) hotbar_[i] = blocks_.id(kHotbar[i]);
  const Level& level = world_.level();
  if (world_.isNew()) {
    spawnPending_ = true;
    player_.teleport({0.5, 200.0, 0.5});
    logInfo("new world at " + world_.dir().string() + " (seed " + std::to_string(level.seed) + ")");
  } else {
    player_.teleport(level.playerPosition);
    player_.yaw = level.playerYaw;
    player_.pitch = level.playerPitch;
    player_.flying = level.playerFlying;  // a player saved in mid-air stays there
    logInfo("opened " + world_.dir().string());
    if (options.seed && *options.seed != level.seed) {
      logWarning("--seed " + std::to_string(*options.seed) + " ignored: the world has its own seed " +
                 std::to_string(level.seed));
    }
  }
  props_ = std::make_unique<GameProps>(world_.dir());
  for (const LevelProp& prop : level.props) {
    try {
      props_->place(prop, world_.world(), world_.light(), true);  // dark until its chunks load
    } catch (const Error&) {
      // Kept in the level, undrawn; place() said why.
    }
  }
  renderer_.setPropNeeds(props_->placed().gpu().needs());
  const std::vector<std::string> offered = propFiles();
  if (!offered.empty()) selectedProp_ = offered.front();
  if (!options.inputScript.empty()) script_.emplace(loadInputScript(options.inputScript));
  glRenderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!std::filesystem::exists(settingsFile_)) probeMachine();
  installCallbacks();
  hud_.emplace(window_.handle());
  window_.setVsync(settings_.vsync && !options.benchmark);
  setScreens(false, false);
}

Game::~Game() {
  hud_.reset();
  if (!benchmarkDir_.empty()) {
    std::error_code ec;
    std::filesystem::remove_all(benchmarkDir_, ec);
  }
}

Game& Game::of(GLFWwindow* w) { return *static_cast<Game*>(glfwGetWindowUserPointer(w)); }

void Game::installCallbacks() {
  GLFWwindow* w = window_.handle();
  glfwSetWindowUserPointer(w, this);
  glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int) {
    Game& g = of(win);
    if (action == GLFW_REPEAT) return;
    if (g.screenOpen()) {
      if (g.menuOpen_ && action == GLFW_PRESS && g.hud_ && g.hud_->takeKey(key, g.settings_)) {
        saveSettings(g.settingsFile_, g.settings_);
        return;
      }
      // The inventory's key closes it, unless the search field is being typed in.
      if (g.inventoryOpen_ && action == GLFW_PRESS && key == g.settings_.keys.key(Action::Inventory) &&
          !(g.hud_ && g.hud_->typing())) {
        g.setScreens(false, false);
        return;
      }
      if (key != kEscapeKey) return;  // the screens' own typing goes to ImGui
    }
    g.controls_.key(key, action == GLFW_PRESS);
  });
  glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int) {
    Game& g = of(win);
    if (g.screenOpen()) return;
    const MouseButton b = button == GLFW_MOUSE_BUTTON_LEFT    ? MouseButton::Left
                          : button == GLFW_MOUSE_BUTTON_RIGHT ? MouseButton::Right
                                                              : MouseButton::Middle;
    g.controls_.button(b, action == GLFW_PRESS);
  });
  glfwSetCursorPosCallback(w, [](GLFWwindow* win, double x, double y) {
    Game& g = of(win);
    if (g.cursorKnown_ && !g.screenOpen()) g.controls_.mouseMoved(glm::dvec2(x, y) - g.lastCursor_);
    g.lastCursor_ = {x, y};
    g.cursorKnown_ = true;
  });
  glfwSetScrollCallback(w, [](GLFWwindow* win, double, double y) {
    Game& g = of(win);
    if (!g.screenOpen()) g.controls_.scrolled(y);
  });
  glfwSetWindowFocusCallback(w, [](GLFWwindow* win, int focused) {
    if (!focused) of(win).controls_.releaseAll();  // keys let go elsewhere never reach us
  });
}

void Game::playScript(double now) {
  for (int key : scriptTaps_) controls_.key(key, false);
  for (MouseButton b : buttonTaps_) controls_.button(b, false);
  scriptTaps_.clear();
  buttonTaps_.clear();
  for (const ScriptEvent& e : script_->due(now)) {
    switch (e.kind) {
      case ScriptEvent::Kind::Key:
        if (screenOpen() && e.key != kEscapeKey) break;
        controls_.key(e.key, e.down.value_or(true));
        if (!e.down) scriptTaps_.push_back(e.key);
        break;
      case ScriptEvent::Kind::Button:
        controls_.button(e.button, e.down.value_or(true));
        if (!e.down) buttonTaps_.push_back(e.button);
        break;
      case ScriptEvent::Kind::Look:
        player_.yaw = static_cast<float>(e.value.x);
        player_.pitch = static_cast<float>(e.value.y);
        break;
      case ScriptEvent::Kind::MouseMove:
        controls_.mouseMoved(e.value);
        break;
      case ScriptEvent::Kind::Scroll:
        controls_.scrolled(e.value.x);
        break;
      case ScriptEvent::Kind::Command:
        if (e.command == "save") save();
        if (e.command == "screenshot") screenshotRequested_ = true;
        if (e.command == "quit") quit_ = true;
        if (e.command == "minimise") window_.minimise();
        if (e.command == "restore") window_.restore();
        if (e.command == "place_prop") placeProp(e.model);
        break;
    }
  }
}

void Game::handleInput(const FrameInput& in, double dt) {
  if (in.menuPressed) setScreens(!screenOpen(), false);  // Esc closes what is open, or opens the menu
  if (screenOpen()) return;
  if (in.wasPressed(Action::Inventory)) {
    setScreens(false, true);
    return;
  }
  player_.look(static_cast<float>(in.mouseDelta.x * settings_.mouseSensitivity),
               static_cast<float>(in.mouseDelta.y * settings_.mouseSensitivity));
  for (int i = 0; i < 9; ++i) {
    if (in.wasPressed(static_cast<Action>(static_cast<int>(Action::Hotbar1) + i))) selected_ = i;
  }
  if (in.scroll != 0.0) {
    const int steps = static_cast<int>(std::lround(-in.scroll));  // wheel down: next slot, as in Minecraft
    selected_ = ((selected_ + steps) % 9 + 9) % 9;
  }
  if (in.wasPressed(Action::HideHud)) showHud_ = !showHud_;
  if (in.wasPressed(Action::PlaceProp)) placeProp(selectedProp_);
  if (in.wasPressed(Action::DebugOverlay)) showOverlay_ = !showOverlay_;
  if (in.wasPressed(Action::Screenshot)) screenshotRequested_ = true;
  if (in.wasPressed(Action::DebugView)) debugView_ = (debugView_ + 1) % static_cast<int>(std::size(kDebugViews));
  if (in.wasPressed(Action::TimeFaster)) timeSpeed_ = (timeSpeed_ + 1) % static_cast<int>(std::size(kTimeSpeeds));
  if (in.wasPressed(Action::TimeStop)) timeStopped_ = !timeStopped_;
  if (in.wasPressed(Action::TimeSet)) {
    std::int64_t& time = world_.level().time;
    const std::int64_t day = time / 24000, ofDay = time % 24000;
    const auto next = std::find_if(std::begin(kTimePresets), std::end(kTimePresets), [&](std::int64_t t) { return t > ofDay; });
    time = next == std::end(kTimePresets) ? (day + 1) * 24000 + kTimePresets[0] : day * 24000 + *next;
  }
  if (in.wasPressed(Action::Jump)) {
    if (lastJumpPress_ >= 0.0 && gameClock_ - lastJumpPress_ <= kDoubleTapSeconds) {
      player_.flying = !player_.flying;
      lastJumpPress_ = -1.0;
    } else {
      lastJumpPress_ = gameClock_;
    }
  }
  useBlocks(in, dt);
}

void Game::tickWorld(const FrameInput& in, int ticks) {
  MoveInput move;
  if (!screenOpen()) {
    move.forward = static_cast<float>(in.isHeld(Action::Forward)) - static_cast<float>(in.isHeld(Action::Back));
    move.strafe = static_cast<float>(in.isHeld(Action::Right)) - static_cast<float>(in.isHeld(Action::Left));
    move.jump = in.isHeld(Action::Jump);
    move.sneak = in.isHeld(Action::Sneak);
    move.sprint = in.isHeld(Action::Sprint);
  }
  for (int i = 0; i < ticks; ++i) {
    player_.tick(world_.world(), move);
    if (player_.position().y < kMinY - 64) {  // fell out of the world: back to the surface
      spawnPending_ = true;
    }
    if (!timeStopped_) world_.level().time += kTimeSpeeds[timeSpeed_];
  }
}

int Game::stream(Clock::time_point frameStart) {
  const glm::dvec3 p = player_.position();
  const ChunkPos centre = ChunkPos::of({static_cast<int>(std::floor(std::clamp(p.x, -3e7, 3e7))), 0,
                                        static_cast<int>(std::floor(std::clamp(p.z, -3e7, 3e7)))});
  std::vector<SectionPos> changed;
  for (const SectionMesh& mesh : world_.update(centre, frameStart + kWorldBudget)) {
    renderer_.upload(mesh);
    changed.push_back(mesh.pos);
  }
  if (!changed.empty()) props_->placed().relightNear(changed, world_.world(), world_.light());
  if (spawnPending_) {
    const int x = static_cast<int>(std::floor(p.x)), z = static_cast<int>(std::floor(p.z));
    if (const auto y = world_.surfaceY(x, z)) {
      player_.teleport({x + 0.5, *y + 1.0, z + 0.5});
      spawnPending_ = false;
    }
  }
  return static_cast<int>(changed.size());
}

void Game::draw(bool timed) {
  FrameInputs frame;
  const double alpha = tickAccumulator_ * kTicksPerSecond;
  frame.cameraPosition = player_.eyeAt(alpha);
  frame.cameraLookAt = frame.cameraPosition + player_.forward();
  frame.fovDegrees = settings_.fov;
  frame.ticks = world_.level().time;
  frame.sunPathRotation = settings_.sunPathRotation;
  frame.viewDistance = static_cast<float>(settings_.viewDistance * 16);
  frame.debugView = static_cast<DebugView>(debugView_);
  frame.reuseShadowMap = true;
  frame.props = &props_->placed().gpu();
  frame.underWater = underWaterAt(world_.world(), world_.light(), frame.cameraPosition);
  frame.renderScale = settings_.targetFps > 0 ? resolution_.scale() : settings_.renderScale;
  if (targetProp_ && !screenOpen() && showHud_) {
    const WorldBounds b = props_->placed().bounds(*targetProp_);
    frame.outline = WorldBox{b.min, b.max};
  } else if (target_ && !screenOpen() && showHud_) {
    frame.outline = outlineOf(world_.world(), target_->block);
  }
  timings_.clear();
  renderer_.render(frame, drawableSize(), timed ? &timings_ : nullptr);
}

glm::ivec2 Game::drawableSize() const {
  return window_.minimised() ? glm::ivec2(0) : window_.framebufferSize();
}

bool Game::worldReady() const {
  const WorldCounts c = world_.counts();
  return !spawnPending_ && c.loaded > 0 && c.pending == 0 && c.meshDirty == 0 && c.meshInFlight == 0;
}

int Game::run() {
  if (options_.benchmark) return runBenchmark();
  const bool fixed = script_ || options_.frames;
  const double step = script_ ? script_->step() : 1.0 / 60.0;
  double last = window_.time();
  int frame = 0;
  while (!window_.shouldClose() && !quit_) {
    const Clock::time_point frameStart = Clock::now();
    window_.pollEvents();
    const double now = window_.time();
    const double dt = fixed ? step : std::clamp(now - last, 0.0, 0.25);
    last = now;
    gameClock_ += dt;
    // A script starts once the world around the player is in, as a player waits for it to load.
    if (script_ && (scriptStarted_ || (scriptStarted_ = worldReady()))) {
      playScript(scriptClock_);
      scriptClock_ += dt;
    }
    const FrameInput in = controls_.take();
    handleInput(in, dt);
    tickWorld(in, Player::ticksFor(tickAccumulator_, dt));
    stream(frameStart);
    const glm::ivec2 size = drawableSize();
    if (const bool hidden = size.x <= 0 || size.y <= 0; hidden != hidden_) {
      hidden_ = hidden;
      logInfo(hidden ? "window minimised: drawing paused, the world goes on" : "window restored: drawing again");
    }
    ++(hidden_ ? framesHidden_ : framesDrawn_);
    if (!hidden_) {
      draw(showOverlay_);
      drawHud();
    } else if (!fixed) {
      std::this_thread::sleep_for(std::chrono::milliseconds(16));  // no swap to pace the loop
    }
    window_.checkErrors("frame");
    const bool final = options_.frames && frame + 1 >= *options_.frames;
    if ((screenshotRequested_ || (final && !options_.screenshot.empty())) && (size.x <= 0 || size.y <= 0)) {
      logWarning("no screenshot: the window has no pixels (minimised)");
      screenshotRequested_ = false;
    } else if (screenshotRequested_ || (final && !options_.screenshot.empty())) {
      const std::filesystem::path file = final && !options_.screenshot.empty() ? options_.screenshot : screenshotName();
      if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
      saveImage(file, readFramebuffer(0, size));
      logInfo("screenshot saved to " + file.string());
      screenshotRequested_ = false;
    }
    window_.swapBuffers();
    frameTimes_.push_back(std::chrono::duration<double>(Clock::now() - frameStart).count());
    if (!hidden_) frameDone(frameTimes_.back());
    double sum = 0.0;
    for (double t : frameTimes_) sum += t;
    while (sum > 1.0 && frameTimes_.size() > 1) {
      sum -= frameTimes_.front();
      frameTimes_.erase(frameTimes_.begin());
    }
    sinceSave_ += dt;
    if (sinceSave_ >= kAutosaveSeconds) save();
    if (final) break;
    ++frame;
  }
  save();
  saveSettings(settingsFile_, settings_);
  writeReport();
  return 0;
}

}  // namespace terrasol::session

namespace terrasol {

int playGame(GlfwWindow& window, const GameOptions& options) {
  session::Game game(window, options);
  return game.run();
}

}  // namespace terrasol
