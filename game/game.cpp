#include "game.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <random>
#include <thread>

#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/log.h"
#include "core/paths.h"
#include "game_renderer.h"
#include "game_world.h"
#include "hud.h"
#include "input_script.h"
#include "platform/glfw/glfw_window.h"
#include "player.h"
#include "render/gl/render_target.h"
#include "targeting.h"

namespace terrasol {
namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kHotbar[9] = {"stone", "dirt",  "grass_block", "cobblestone", "oak_planks",
                                    "oak_log", "glass", "torch",       "glowstone"};
constexpr double kAutosaveSeconds = 300.0;
constexpr double kDoubleTapSeconds = 0.3;                     // two jump presses this close toggle flight
constexpr double kBreakRepeat = 0.25, kPlaceRepeat = 0.2;     // Minecraft's creative delays (5 and 4 ticks)
constexpr auto kWorldBudget = std::chrono::milliseconds(4);   // main-thread light work per frame
constexpr int kTimeSpeeds[] = {1, 10, 100};
constexpr std::int64_t kTimePresets[] = {1000, 6000, 12000, 18000};  // morning, noon, sunset, midnight

std::size_t residentBytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

std::string format(const char* fmt, auto... args) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, fmt, args...);
  return buffer;
}

const char* facingName(float yaw) {
  const float y = std::fmod(std::fmod(yaw, 360.0f) + 360.0f, 360.0f);
  if (y < 45.0f || y >= 315.0f) return "south (towards +Z)";
  if (y < 135.0f) return "west (towards -X)";
  if (y < 225.0f) return "north (towards -Z)";
  return "east (towards +X)";
}

bool replaceable(const BlockType& type) {
  return type.shape == BlockShape::None || type.shape == BlockShape::Liquid || type.shape == BlockShape::Cross;
}

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

struct Edit {
  BlockPos pos;
  std::string block;
};

class Game {
 public:
  Game(GlfwWindow& window, const GameOptions& options);
  ~Game();
  int run();

 private:
  static Game& of(GLFWwindow* w) { return *static_cast<Game*>(glfwGetWindowUserPointer(w)); }
  void installCallbacks();
  void setMenu(bool open);
  void playScript(double now);
  void handleInput(const FrameInput& in, double dt);
  void useBlocks(const FrameInput& in, double dt);
  void tickWorld(const FrameInput& in, int ticks);
  void stream(Clock::time_point frameStart);
  void draw(bool timed);
  void drawHud();
  void applyMenu(const MenuResult& r);
  void reloadPacks();
  void save();
  void writeReport();
  std::vector<std::string> overlayLeft() const;
  std::vector<std::string> overlayRight() const;
  glm::dvec3 benchmarkEye(double t) const;
  bool worldReady() const;
  int runBenchmark();

  GlfwWindow& window_;
  GameOptions options_;
  std::filesystem::path settingsFile_;
  GameSettings settings_;
  BlockRegistry blocks_;
  GameRenderer renderer_;
  std::filesystem::path benchmarkDir_;  // a throwaway world for --benchmark
  GameWorld world_;
  Player player_;
  Controls controls_;
  std::optional<Hud> hud_;
  std::optional<ScriptPlayer> script_;
  std::vector<int> scriptTaps_;       // keys tapped this frame: released next frame
  std::vector<MouseButton> buttonTaps_;

  bool menuOpen_ = false, showHud_ = true, showOverlay_ = false, quit_ = false;
  bool spawnPending_ = false;
  int selected_ = 0;
  std::array<BlockId, 9> hotbar_{};
  int debugView_ = 0;
  int timeSpeed_ = 0;  // index into kTimeSpeeds
  bool timeStopped_ = false;
  double tickAccumulator_ = 0.0, gameClock_ = 0.0, lastJumpPress_ = -1.0, sinceSave_ = 0.0;
  double breakCooldown_ = 0.0, placeCooldown_ = 0.0;
  glm::dvec2 lastCursor_{0.0};
  bool cursorKnown_ = false;
  std::optional<Target> target_;
  std::vector<Edit> edits_;
  std::vector<PassTiming> timings_;
  std::vector<double> frameTimes_;  // seconds, the last second's
  bool screenshotRequested_ = false;
  bool scriptStarted_ = false;
  double scriptClock_ = 0.0;  // script time: starts when the world is ready
  std::string glRenderer_;
};

std::filesystem::path benchmarkWorldDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "terrasol-benchmark-XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw Error("cannot create a temporary world for --benchmark");
  return pattern;
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

Game::Game(GlfwWindow& window, const GameOptions& options)
    : window_(window),
      options_(options),
      settingsFile_(options.settings.empty() ? defaultSettingsFile() : options.settings),
      settings_(settingsFor(options, settingsFile_)),
      blocks_(BlockRegistry::fromFile(resourcePackDir() / "default" / "blocks.json")),
      renderer_(blocks_, settings_),
      benchmarkDir_(options.benchmark ? benchmarkWorldDir() : std::filesystem::path()),
      world_(options.benchmark ? benchmarkDir_ : options.world, seedOf(options), blocks_, renderer_.assets().table,
             settings_.viewDistance, std::max(1u, std::thread::hardware_concurrency()) > 2 ? 3 : 2),
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
  if (!options.inputScript.empty()) script_.emplace(loadInputScript(options.inputScript));
  glRenderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  installCallbacks();
  hud_.emplace(window_.handle());
  window_.setVsync(settings_.vsync && !options.benchmark);
  setMenu(false);
}

Game::~Game() {
  hud_.reset();
  if (!benchmarkDir_.empty()) {
    std::error_code ec;
    std::filesystem::remove_all(benchmarkDir_, ec);
  }
}

void Game::installCallbacks() {
  GLFWwindow* w = window_.handle();
  glfwSetWindowUserPointer(w, this);
  glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int) {
    Game& g = of(win);
    if (action == GLFW_REPEAT) return;
    if (g.menuOpen_) {
      if (action == GLFW_PRESS && g.hud_ && g.hud_->takeKey(key, g.settings_)) {
        saveSettings(g.settingsFile_, g.settings_);
        return;
      }
      if (key != kEscapeKey) return;  // the menu's own typing goes to ImGui
    }
    g.controls_.key(key, action == GLFW_PRESS);
  });
  glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int) {
    Game& g = of(win);
    if (g.menuOpen_) return;
    const MouseButton b = button == GLFW_MOUSE_BUTTON_LEFT    ? MouseButton::Left
                          : button == GLFW_MOUSE_BUTTON_RIGHT ? MouseButton::Right
                                                              : MouseButton::Middle;
    g.controls_.button(b, action == GLFW_PRESS);
  });
  glfwSetCursorPosCallback(w, [](GLFWwindow* win, double x, double y) {
    Game& g = of(win);
    if (g.cursorKnown_ && !g.menuOpen_) g.controls_.mouseMoved(glm::dvec2(x, y) - g.lastCursor_);
    g.lastCursor_ = {x, y};
    g.cursorKnown_ = true;
  });
  glfwSetScrollCallback(w, [](GLFWwindow* win, double, double y) {
    Game& g = of(win);
    if (!g.menuOpen_) g.controls_.scrolled(y);
  });
  glfwSetWindowFocusCallback(w, [](GLFWwindow* win, int focused) {
    if (!focused) of(win).controls_.releaseAll();  // keys let go elsewhere never reach us
  });
}

void Game::setMenu(bool open) {
  menuOpen_ = open;
  controls_.releaseAll();
  cursorKnown_ = false;
  GLFWwindow* w = window_.handle();
  glfwSetInputMode(w, GLFW_CURSOR, open ? GLFW_CURSOR_NORMAL : GLFW_CURSOR_DISABLED);
  if (!open && glfwRawMouseMotionSupported()) glfwSetInputMode(w, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
}

void Game::playScript(double now) {
  for (int key : scriptTaps_) controls_.key(key, false);
  for (MouseButton b : buttonTaps_) controls_.button(b, false);
  scriptTaps_.clear();
  buttonTaps_.clear();
  for (const ScriptEvent& e : script_->due(now)) {
    switch (e.kind) {
      case ScriptEvent::Kind::Key:
        if (menuOpen_ && e.key != kEscapeKey) break;
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
        break;
    }
  }
}

void Game::handleInput(const FrameInput& in, double dt) {
  if (in.menuPressed) setMenu(!menuOpen_);
  if (menuOpen_) return;
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
  if (in.wasPressed(Action::DebugOverlay)) showOverlay_ = !showOverlay_;
  if (in.wasPressed(Action::Screenshot)) screenshotRequested_ = true;
  if (in.wasPressed(Action::DebugView)) debugView_ = (debugView_ + 1) % static_cast<int>(std::size(kDebugViewNames));
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

void Game::useBlocks(const FrameInput& in, double dt) {
  breakCooldown_ -= dt;
  placeCooldown_ -= dt;
  target_ = targetBlock(world_.world(), player_.eye(), player_.forward());
  if (!target_) return;
  if (in.wasPressed(MouseButton::Middle)) {
    const BlockId picked = world_.world().getBlock(target_->block);
    const auto slot = std::find(hotbar_.begin(), hotbar_.end(), picked);
    if (slot != hotbar_.end()) selected_ = static_cast<int>(slot - hotbar_.begin());
    else hotbar_[static_cast<std::size_t>(selected_)] = picked;
  }
  const bool breakNow = in.wasPressed(MouseButton::Left) || (in.isHeld(MouseButton::Left) && breakCooldown_ <= 0.0);
  if (breakNow) {
    if (world_.setBlock(target_->block, kAir)) edits_.push_back({target_->block, "air"});
    breakCooldown_ = kBreakRepeat;
    target_ = targetBlock(world_.world(), player_.eye(), player_.forward());
    return;
  }
  const bool placeNow = in.wasPressed(MouseButton::Right) || (in.isHeld(MouseButton::Right) && placeCooldown_ <= 0.0);
  if (!placeNow) return;
  placeCooldown_ = kPlaceRepeat;
  // A plant under the crosshair is replaced, as in Minecraft; anything else gets the block beside it.
  const BlockPos at = replaceable(blocks_[world_.world().getBlock(target_->block)]) ? target_->block : target_->place;
  const BlockId block = hotbar_[static_cast<std::size_t>(selected_)];
  const BlockType& type = blocks_[block];
  if (!inWorldHeight(at.y) || !replaceable(blocks_[world_.world().getBlock(at)])) return;
  if (type.shape == BlockShape::Cube) {
    const Box cell{glm::dvec3(at.x, at.y, at.z), glm::dvec3(at.x + 1, at.y + 1, at.z + 1)};
    const Box body = player_.box();
    const bool overlaps = body.min.x < cell.max.x && body.max.x > cell.min.x && body.min.y < cell.max.y &&
                          body.max.y > cell.min.y && body.min.z < cell.max.z && body.max.z > cell.min.z;
    if (overlaps) return;  // never inside the player
  } else if (!blocks_[world_.world().getBlock(at.offset(0, -1, 0))].isOpaqueCube()) {
    return;  // torches and plants stand on a full block
  }
  if (world_.setBlock(at, block)) edits_.push_back({at, type.name});
}

void Game::tickWorld(const FrameInput& in, int ticks) {
  MoveInput move;
  if (!menuOpen_) {
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

void Game::stream(Clock::time_point frameStart) {
  const glm::dvec3 p = player_.position();
  const ChunkPos centre = ChunkPos::of({static_cast<int>(std::floor(std::clamp(p.x, -3e7, 3e7))), 0,
                                        static_cast<int>(std::floor(std::clamp(p.z, -3e7, 3e7)))});
  for (const SectionMesh& mesh : world_.update(centre, frameStart + kWorldBudget)) renderer_.upload(mesh);
  if (spawnPending_) {
    const int x = static_cast<int>(std::floor(p.x)), z = static_cast<int>(std::floor(p.z));
    if (const auto y = world_.surfaceY(x, z)) {
      player_.teleport({x + 0.5, *y + 1.0, z + 0.5});
      spawnPending_ = false;
    }
  }
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
  if (target_ && !menuOpen_ && showHud_) {
    const BlockPos b = target_->block;
    frame.outline = WorldBox{glm::dvec3(b.x, b.y, b.z), glm::dvec3(b.x + 1, b.y + 1, b.z + 1)};
  }
  timings_.clear();
  renderer_.render(frame, window_.framebufferSize(), timed ? &timings_ : nullptr);
}

void Game::drawHud() {
  hud_->beginFrame();
  if (showHud_ && !menuOpen_) {
    hud_->crosshair();
    std::vector<Hud::Slot> slots;
    const BlockAssets& assets = renderer_.assets();
    const GLuint icons = renderer_.iconTexture();
    for (BlockId id : hotbar_) {
      Hud::Slot slot;
      slot.name = blocks_[id].name;
      slot.texture = icons;
      const int face = blocks_[id].shape == BlockShape::Cube ? static_cast<int>(Direction::Up) : 0;
      const int texture = assets.atlas.textureOf(id, face);
      const Atlas& atlas = assets.atlas.atlas;
      if (texture >= 0 && static_cast<std::size_t>(texture) < atlas.textures.size()) {
        const glm::vec4 rect = atlas.tileRect(atlas.textures[static_cast<std::size_t>(texture)].firstTile);
        slot.u0 = rect.x, slot.v0 = rect.y, slot.u1 = rect.z, slot.v1 = rect.w;
      }
      const Tint tint = blocks_[id].tint;
      const glm::vec3 colour = tint == Tint::Grass ? assets.tints.grass : tint == Tint::Foliage ? assets.tints.foliage
                               : tint == Tint::Water ? assets.tints.water : glm::vec3(1.0f);
      slot.r = colour.r, slot.g = colour.g, slot.b = colour.b;
      slots.push_back(std::move(slot));
    }
    hud_->hotbar(slots, selected_);
  }
  if (showOverlay_) hud_->overlay(overlayLeft(), overlayRight());
  if (menuOpen_) applyMenu(hud_->menu(settings_, renderer_.assets().packNames));
  hud_->endFrame();
}

void Game::applyMenu(const MenuResult& r) {
  if (r.viewChanged) world_.setViewDistance(settings_.viewDistance);
  if (r.rendererChanged) renderer_.applySettings(settings_);
  if (r.packsChanged) reloadPacks();
  if (r.settingsChanged) {
    window_.setVsync(settings_.vsync);
    saveSettings(settingsFile_, settings_);
  }
  if (r.save) save();
  if (r.resume) setMenu(false);
  if (r.quit) quit_ = true;
}

void Game::reloadPacks() {
  try {
    std::unique_ptr<BlockAssets> assets = renderer_.loadPacks(settings_.packs);
    world_.remeshAll(assets->table);
    renderer_.commit(std::move(assets));
    for (const PackProblem& p : renderer_.assets().atlas.problems) logWarning(p.message);
  } catch (const Error& e) {
    logError(std::string("packs not reloaded: ") + e.what());  // the old ones stay
  }
}

void Game::save() {
  Level& level = world_.level();
  level.playerPosition = player_.position();
  level.playerYaw = player_.yaw;
  level.playerPitch = player_.pitch;
  level.playerFlying = player_.flying;
  try {
    world_.save();
    logInfo("saved " + world_.dir().string());
  } catch (const std::exception& e) {
    logError(std::string("saving failed: ") + e.what());
  }
  sinceSave_ = 0.0;
}

std::vector<std::string> Game::overlayLeft() const {
  double total = 0.0;
  for (double t : frameTimes_) total += t;
  const double frameMs = frameTimes_.empty() ? 0.0 : 1000.0 * total / static_cast<double>(frameTimes_.size());
  std::vector<std::string> out;
  out.push_back(format("Terrasol  %.0f fps (%.1f ms a frame)", frameMs > 0.0 ? 1000.0 / frameMs : 0.0, frameMs));
  std::string passes = "ms per pass:";
  for (const PassTiming& t : timings_) passes += format(" %s %.2f", t.pass.c_str(), t.ms);
  out.push_back(passes);
  const glm::dvec3 p = player_.position();
  const BlockPos b{static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)), static_cast<int>(std::floor(p.z))};
  out.push_back(format("XYZ: %.3f / %.5f / %.3f", p.x, p.y, p.z));
  out.push_back(format("Block: %d %d %d  [%d %d %d in chunk %d %d, section %d]", b.x, b.y, b.z, localOf(b.x),
                       localOf(b.y), localOf(b.z), chunkOf(b.x), chunkOf(b.z), inWorldHeight(b.y) ? sectionOf(b.y) : -1));
  out.push_back(format("Facing: %s (%.1f / %.1f)", facingName(player_.yaw), player_.yaw, player_.pitch));
  const BlockPos eye{b.x, static_cast<int>(std::floor(player_.eye().y)), b.z};
  out.push_back(format("Light at the eye: %d block, %d sky", world_.light().lightAt(eye, LightChannel::Block),
                       world_.light().lightAt(eye, LightChannel::Sky)));
  out.push_back(format("%s%s%s", player_.flying ? "flying" : player_.onGround() ? "on ground" : "in the air",
                       player_.inWater() ? ", in water" : "", player_.sprinting() ? ", sprinting" : ""));
  const std::int64_t t = world_.level().time;
  out.push_back(format("Time: day %lld, %02lld:%02lld (tick %lld), x%d%s", static_cast<long long>(t / 24000),
                       static_cast<long long>((t % 24000 / 1000 + 6) % 24), static_cast<long long>(t % 1000 * 60 / 1000),
                       static_cast<long long>(t), kTimeSpeeds[timeSpeed_], timeStopped_ ? ", stopped" : ""));
  const WorldCounts c = world_.counts();
  const FrameStats& f = renderer_.lastFrame();
  out.push_back(format("Chunks: %zu loaded, %zu pending, %zu meshable", c.loaded, c.pending, c.meshable));
  out.push_back(format("Sections: %zu dirty, %zu meshing, %zu on GPU, %d drawn, %d culled, %d shadow casters",
                       c.meshDirty, c.meshInFlight, renderer_.sectionsOnGpu(), f.sectionsDrawn, f.sectionsCulled,
                       f.shadowCasters));
  return out;
}

std::vector<std::string> Game::overlayRight() const {
  std::vector<std::string> out;
  out.push_back(format("Memory: %.0f MB resident", static_cast<double>(residentBytes()) / (1024.0 * 1024.0)));
  out.push_back("GL: " + glRenderer_);
  const glm::ivec2 size = window_.framebufferSize();
  out.push_back(format("Display: %dx%d, view %d chunks, fov %.0f", size.x, size.y, settings_.viewDistance, settings_.fov));
  const SceneShadow& s = settings_.shadow;
  out.push_back(s.enabled ? format("Shadows: %s %d^2, %.0f blocks, pcf %d", s.mode.c_str(), s.resolution, s.distance, s.pcfSamples)
                          : std::string("Shadows: off"));
  out.push_back(format("Debug view (F4): %s", kDebugViewNames[debugView_]));
  if (target_) {
    const BlockPos b = target_->block;
    out.push_back(format("Targeted block: %d %d %d", b.x, b.y, b.z));
    out.push_back(blocks_[world_.world().getBlock(b)].name);
    out.push_back(format("Light at its face: %d block, %d sky", world_.light().lightAt(target_->place, LightChannel::Block),
                         world_.light().lightAt(target_->place, LightChannel::Sky)));
  }
  return out;
}

void Game::writeReport() {
  if (options_.report.empty()) return;
  // Probes need their chunks: stream around each until it is loaded and lit (at most 30 s).
  nlohmann::json probes = nlohmann::json::array();
  for (const BlockPos& p : options_.probes) {
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    const ChunkPos chunk = ChunkPos::of(p);
    while (Clock::now() < deadline && !(world_.world().isLoaded(chunk) && world_.counts().pending == 0)) {
      world_.update(chunk, Clock::now() + kWorldBudget);
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    const bool loaded = world_.world().isLoaded(chunk);
    probes.push_back({{"pos", {p.x, p.y, p.z}},
                      {"loaded", loaded},
                      {"block", blocks_[world_.world().getBlock(p)].name},
                      {"block_light", world_.light().lightAt(p, LightChannel::Block)},
                      {"sky_light", world_.light().lightAt(p, LightChannel::Sky)}});
  }
  nlohmann::json edits = nlohmann::json::array();
  for (const Edit& e : edits_) edits.push_back({{"pos", {e.pos.x, e.pos.y, e.pos.z}}, {"block", e.block}});
  const glm::dvec3 p = player_.position();
  const nlohmann::json report = {
      {"world", world_.dir().string()},
      {"time", world_.level().time},
      {"player", {{"position", {p.x, p.y, p.z}}, {"yaw", player_.yaw}, {"pitch", player_.pitch}, {"flying", player_.flying}}},
      {"edits", edits},
      {"probes", probes}};
  writeFileAtomically(options_.report, report.dump(2) + "\n");
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
    draw(showOverlay_);
    drawHud();
    window_.checkErrors("frame");
    const bool final = options_.frames && frame + 1 >= *options_.frames;
    const glm::ivec2 size = window_.framebufferSize();
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

bool Game::worldReady() const {
  const WorldCounts c = world_.counts();
  return !spawnPending_ && c.loaded > 0 && c.pending == 0 && c.meshDirty == 0 && c.meshInFlight == 0;
}

// A circle of 96 blocks around the spawn at 40 blocks above sea level, at sprint-flying speed.
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
  std::vector<double> sorted = frames;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted[sorted.size() / 2];
  const double p99 = sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(sorted.size()))) - 1)];
  const glm::ivec2 size = window_.framebufferSize();
  const SceneShadow& s = settings_.shadow;
  std::printf("benchmark: %zu frames in %.1f s at %dx%d, view %d chunks, shadows %s\n", frames.size(), t, size.x, size.y,
              settings_.viewDistance,
              s.enabled ? format("%s %d^2 over %.0f blocks, pcf %d", s.mode.c_str(), s.resolution, s.distance, s.pcfSamples).c_str()
                        : "off");
  std::printf("benchmark: median %.1f fps (%.2f ms), 1%% low %.1f fps (%.2f ms), mean %.1f fps\n", 1.0 / median,
              median * 1000.0, 1.0 / p99, p99 * 1000.0, static_cast<double>(frames.size()) / t);
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

}  // namespace

int playGame(GlfwWindow& window, const GameOptions& options) {
  Game game(window, options);
  return game.run();
}

}  // namespace terrasol
