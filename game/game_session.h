#pragma once
// The game session behind playGame (game.h), shared by its source files: game.cpp (input, physics,
// editing, the frame loop, saves), game_overlay.cpp (the F3 overlay and --report), game_benchmark.cpp
// (--benchmark). Internal to the game; nothing outside game/ includes it.

#include <array>
#include <chrono>
#include <deque>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "controls.h"
#include "render/dynamic_resolution.h"
#include "game_renderer.h"
#include "game_props.h"
#include "pipeline/streamed_world.h"
#include "hud.h"
#include "input_script.h"
#include "options.h"
#include "player.h"
#include "settings.h"
#include "targeting.h"

struct GLFWwindow;

namespace terrasol {

class GlfwWindow;

namespace session {

using Clock = std::chrono::steady_clock;

inline constexpr auto kWorldBudget = std::chrono::milliseconds(4);  // main-thread light work per frame
inline constexpr int kTimeSpeeds[] = {1, 10, 100};

// A fresh temporary directory for --benchmark's throwaway world.
std::filesystem::path benchmarkWorldDir();

// printf into a std::string (overlay lines are short).
template <class... Args>
std::string format(const char* fmt, Args... args) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, fmt, args...);
  return buffer;
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
  static Game& of(GLFWwindow* w);  // the Game a window callback belongs to
  void installCallbacks();
  // Opens or closes the Esc menu or the inventory: while either is open the cursor is free and the
  // keyboard and mouse go to them.
  void setScreens(bool menu, bool inventory);
  bool screenOpen() const { return menuOpen_ || inventoryOpen_; }
  void playScript(double now);
  void handleInput(const FrameInput& in, double dt);
  void useBlocks(const FrameInput& in, double dt);
  // Sets a block as the player does: recorded among the edits, and stairs beside it turned into
  // corners (world/connected_states.h). False when nothing changed.
  bool editBlock(const BlockPos& pos, BlockId state);
  // Whether `state` placed at `at` would stand in the player (its collision boxes).
  bool blocksPlayer(const BlockPos& at, BlockId state) const;
  void tickWorld(const FrameInput& in, int ticks);
  int stream(Clock::time_point frameStart);  // the number of section meshes uploaded
  void draw(bool timed);
  // After a drawn frame of `seconds`: dynamic resolution's next scale.
  void frameDone(double seconds);
  // The first start (no settings file): times a few empty frames and picks settings for the machine.
  void probeMachine();
  void drawHud();
  Hud::Slot slotOf(BlockId state);  // its block's inventory icon
  std::vector<Hud::Slot> hotbarSlots();
  void applyMenu(const MenuResult& r);
  // Places `model` (relative to the world folder, or absolute) standing in the targeted free cell.
  void placeProp(const std::string& model);
  std::vector<std::string> propFiles() const;  // the world's props/ folder: what the menu offers
  void reloadPacks();
  void save();
  void writeReport();
  std::vector<std::string> overlayLeft() const;
  std::vector<std::string> overlayRight() const;
  glm::dvec3 benchmarkEye(double t) const;
  bool worldReady() const;
  int runBenchmark();
  // The pixels there are to draw: none while minimised (GlfwWindow::minimised), whatever X11 says.
  glm::ivec2 drawableSize() const;

  GlfwWindow& window_;
  GameOptions options_;
  std::filesystem::path settingsFile_;
  GameSettings settings_;
  BlockRegistry blocks_;
  BlockShapes shapes_;  // from the default pack's models: resource packs do not change collision
  GameRenderer renderer_;
  std::filesystem::path benchmarkDir_;  // a throwaway world for --benchmark
  StreamedWorld world_;
  std::unique_ptr<GameProps> props_;  // after the world: props light from it
  std::string selectedProp_;          // the model the place-prop key places
  Player player_;
  Controls controls_;
  std::optional<Hud> hud_;
  std::optional<ScriptPlayer> script_;
  std::vector<int> scriptTaps_;       // keys tapped this frame: released next frame
  std::vector<MouseButton> buttonTaps_;

  bool menuOpen_ = false, inventoryOpen_ = false, showHud_ = true, showOverlay_ = false, quit_ = false;
  bool hidden_ = false;  // the last frame had no pixels to draw
  int framesDrawn_ = 0, framesHidden_ = 0;
  bool spawnPending_ = false;
  int selected_ = 0;
  std::array<BlockId, 9> hotbar_{};
  DynamicResolution resolution_;  // the render scale while settings_.targetFps holds a rate
  int debugView_ = 0;
  int timeSpeed_ = 0;  // index into kTimeSpeeds
  bool timeStopped_ = false;
  double tickAccumulator_ = 0.0, gameClock_ = 0.0, lastJumpPress_ = -1.0, sinceSave_ = 0.0;
  double breakCooldown_ = 0.0, placeCooldown_ = 0.0;
  glm::dvec2 lastCursor_{0.0};
  bool cursorKnown_ = false;
  std::optional<Target> target_;
  std::optional<int> targetProp_;  // a drawn prop nearer than the targeted block: GameProps index
  std::vector<Edit> edits_;
  std::vector<PassTiming> timings_;
  std::vector<double> frameTimes_;  // seconds, the last second's
  std::deque<float> frameGraph_;     // ms, the last 240 frames' (the F3 graph)
  bool screenshotRequested_ = false;
  bool scriptStarted_ = false;
  double scriptClock_ = 0.0;  // script time: starts when the world is ready
  std::string glRenderer_;
};

}  // namespace session
}  // namespace terrasol
