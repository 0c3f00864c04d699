#pragma once
// The playable game in a window, as a few owned parts wired together: the block content, the
// renderer, the world being played, block interaction, input routing, the screens (HUD, menu,
// inventory), the F3 overlay and, for scripted runs, the input script. One frameStep() runs a frame
// for play, scripts and the benchmark alike.

#include <chrono>
#include <optional>

#include "block_interaction.h"
#include "debug_overlay.h"
#include "far_terrain.h"
#include "game_audio.h"
#include "game_renderer.h"
#include "game_report.h"
#include "game_ui.h"
#include "input_router.h"
#include "options.h"
#include "play_world.h"
#include "render/dynamic_resolution.h"
#include "script_driver.h"
#include "settings.h"

namespace terrasol {

class GlfwWindow;

using Clock = std::chrono::steady_clock;

// What one frame does (Game::frameStep). Play does everything; the benchmark places the camera itself
// and times frames until they are on screen.
struct FrameStep {
  bool play = true;         // input, the script, ticks and autosave
  bool hud = true;          // the HUD and screens over the picture
  bool passTimes = false;   // ms per pass, with a glFinish after each pass and after the HUD
  bool finish = false;      // glFinish after the swap: a frame is done when it is on screen
  bool pace = true;         // its time moves dynamic resolution and the F3 graph
  bool screenshot = false;  // --screenshot takes this frame
};

// When a frame's stages ended.
struct FrameTimes {
  Clock::time_point start, streamed, drawn, hud, done;
  int uploads = 0;  // section meshes uploaded
  double seconds() const { return std::chrono::duration<double>(done - start).count(); }
};

// The frame loop's state from one frame to the next.
struct FrameState {
  double clock = 0.0;            // game seconds
  double tickAccumulator = 0.0;  // seconds not yet run as ticks
  double sinceSave = 0.0;
  FrameCounts counts;
  bool hidden = false;                    // the last frame had no pixels to draw
  bool quit = false, screenshot = false;  // asked for by the menu, a key or the script
  DynamicResolution resolution;           // the render scale while the settings hold a target fps
  bool readySaid = false;                 // the log said the world round the player was ready
};

class Game {
 public:
  Game(GlfwWindow& window, const GameOptions& options);
  // Plays until the window closes, the menu's quit, the script's "quit" or --frames; saves the world
  // and the settings, writes --report. Returns the exit code.
  int run();
  // One frame of `dt` game seconds.
  FrameTimes frameStep(double dt, const FrameStep& step = {});

  // What the benchmark drives and reads.
  GlfwWindow& window() { return window_; }
  PlayWorld& world() { return world_; }
  const GameSettings& settings() const { return settings_.values; }
  const GameRenderer& renderer() const { return renderer_; }
  DebugOverlay& overlay() { return overlay_; }
  GameUi& ui() { return ui_; }
  float renderScale() const;

 private:
  void playInput(double dt);
  void runCommand(const ScriptEvent& command);
  void handleInput(const FrameInput& in, double dt);
  void draw(bool timed);
  // The loading screen, until the world round the player is first ready.
  void drawLoading(glm::ivec2 size);
  void drawHud();
  void applyMenu(const MenuResult& r);
  void reloadPacks();
  // Far terrain for the settings, packs and world now (after any of them changes).
  void resetFarTerrain();
  void save();
  // The first start (no settings file): times a few empty frames and picks settings for the machine.
  void probeMachine();
  // The pixels there are to draw: none while minimised (GlfwWindow::minimised), whatever X11 says.
  glm::ivec2 drawableSize() const;

  Clock::time_point started_ = Clock::now();  // before the blocks, the renderer and the world
  GlfwWindow& window_;
  GameOptions options_;
  SettingsFile settings_;
  BlockContent content_;
  GameRenderer renderer_;
  PlayWorld world_;
  BlockInteraction interaction_;
  InputRouter input_;  // before the UI: ImGui's callbacks chain to the router's
  GameUi ui_;
  DebugOverlay overlay_;
  GameAudio audio_;
  std::unique_ptr<FarTerrain> far_;  // settings "lod"; null when off
  FrameState frames_;
  std::optional<ScriptDriver> script_;
};

// Plays until the window closes, the menu's quit, a script's "quit" or --frames. Returns the exit code.
int playGame(GlfwWindow& window, const GameOptions& options);

}  // namespace terrasol
