#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <thread>

#include "benchmark.h"
#include "core/log.h"
#include "core/paths.h"
#include "demo.h"
#include "game.h"
#include "platform/glfw/glfw_window.h"
#include "scene_render/eye_light.h"
#include "scene_render/under_water.h"
#include "screenshot.h"
#include "shader_pack_list.h"

// The frame loop: one frame's input, ticks, streaming, drawing and HUD, and the run of frames.

namespace terrasol {
namespace {

constexpr auto kWorldBudget = std::chrono::milliseconds(4);     // main-thread light work per frame
constexpr auto kLoadingBudget = std::chrono::milliseconds(30);  // and while the loading screen shows
constexpr double kAutosaveSeconds = 300.0;

}  // namespace

int Game::run() {
  if (options_.benchmark) return runBenchmark(*this, options_);
  const bool fixed = script_ || options_.frames;
  const double step = script_ ? script_->step() : kFixedStep;
  double last = window_.time();
  for (int counted = 0; !window_.shouldClose() && !frames_.quit;) {
    const double now = window_.time();
    const double dt = fixed ? step : std::clamp(now - last, 0.0, 0.25);
    last = now;
    // A script starts once the world round the player is in, as a player waits for it to load, and
    // --frames counts its frames from there: a scripted run ends at the same moment on every machine.
    const bool counts = !script_ || script_->startIf(world_.ready());
    const bool final = counts && options_.frames && counted + 1 >= *options_.frames;
    frameStep(dt, {.screenshot = final && !options_.screenshot.empty()});
    if (final) break;
    counted += counts;
  }
  save();
  settings_.save();
  if (!options_.report.empty())
    writeReport(
        options_.report, world_, options_.probes, frames_.counts, input_.screen(), interaction_.hotbar(),
        {renderer_.shaderPack() ? renderer_.shaderPack()->packName() : "", renderer_.shaderPackError()});
  return 0;
}

FrameTimes Game::frameStep(double dt, const FrameStep& step) {
  FrameTimes t;
  t.start = Clock::now();
  window_.pollEvents();
  if (step.play) playInput(dt);
  // Until the world round the player is first ready the game shows a loading screen: no world is
  // drawn (on a software renderer the half-built world's frames took most of the load time), and
  // the main thread gives light the time a frame would have taken.
  const bool loading = !frames_.readySaid;
  t.uploads = world_.stream(t.start + (loading ? kLoadingBudget : kWorldBudget));
  if (!frames_.readySaid && world_.ready()) {
    frames_.readySaid = true;
    logInfo("the world round the player is loaded, lit and meshed, " +
            std::to_string(std::chrono::duration<double>(Clock::now() - started_).count()).substr(0, 4) +
            " s after the game began loading its blocks");
  }
  t.streamed = Clock::now();
  const glm::ivec2 size = drawableSize();
  if (const bool hidden = size.x <= 0 || size.y <= 0; hidden != frames_.hidden) {
    frames_.hidden = hidden;
    logInfo(hidden ? "window minimised: drawing paused, the world goes on"
                   : "window restored: drawing again");
  }
  ++(frames_.hidden ? frames_.counts.minimised : frames_.counts.drawn);
  if (!frames_.hidden && loading) {
    drawLoading(size);
    t.drawn = Clock::now();
  } else if (!frames_.hidden) {
    draw(step.passTimes || overlay_.shown());
    t.drawn = Clock::now();
    if (step.hud) drawHud();
    if (step.passTimes) glFinish();
  } else if (step.play && !script_ && !options_.frames) {
    std::this_thread::sleep_for(std::chrono::milliseconds(16));  // no swap to pace the loop
  }
  t.hud = Clock::now();
  window_.checkErrors("frame");
  if (frames_.screenshot || step.screenshot) {
    saveScreenshot(step.screenshot ? options_.screenshot : screenshotName(), size);
    frames_.screenshot = false;
  }
  window_.swapBuffers();
  if (step.finish) glFinish();
  t.done = Clock::now();
  if (step.play) overlay_.frameTime(t.seconds());
  if (step.pace && !frames_.hidden) {
    const GameSettings& s = settings_.values;
    overlay_.drawnFrameTime(t.seconds());
    frames_.resolution.setMaxScale(s.renderScale);
    if (s.targetFps > 0) frames_.resolution.update(t.seconds() * 1000.0, s.targetFps);
  }
  if (step.play && (frames_.sinceSave += dt) >= kAutosaveSeconds) save();
  return t;
}

void Game::playInput(double dt) {
  frames_.clock += dt;
  if (script_ && script_->started()) {
    for (const ScriptEvent& command : script_->play(dt, input_, world_.player())) runCommand(command);
  }
  const FrameInput in = input_.take();
  handleInput(in, dt);
  world_.tick(in, input_.screenOpen(), Player::ticksFor(frames_.tickAccumulator, dt), [&] {
    audio_.tick(world_, interaction_.digTick(!input_.screenOpen() && in.isHeld(MouseButton::Left), world_));
  });
  const Player& player = world_.player();
  audio_.frame(world_, player.eyeAt(frames_.tickAccumulator * kTicksPerSecond), player.forward(), dt);
}

void Game::handleInput(const FrameInput& in, double dt) {
  if (in.menuPressed)
    input_.show(input_.screenOpen() ? Screen::None : Screen::Menu);  // Esc closes what is open
  if (input_.screenOpen()) return;
  if (in.wasPressed(Action::Inventory)) return input_.show(Screen::Inventory);
  const double sensitivity = settings_.values.mouseSensitivity;
  world_.player().look(static_cast<float>(in.mouseDelta.x * sensitivity),
                       static_cast<float>(in.mouseDelta.y * sensitivity));
  Hotbar& hotbar = interaction_.hotbar();
  for (int i = 0; i < Hotbar::kSlots; ++i) {
    if (in.wasPressed(static_cast<Action>(static_cast<int>(Action::Hotbar1) + i))) hotbar.select(i);
  }
  if (in.scroll != 0.0) hotbar.scroll(in.scroll);
  if (in.wasPressed(Action::HideHud)) ui_.toggleHud();
  if (in.wasPressed(Action::PlaceProp)) interaction_.placeProp(ui_.selectedProp(), world_);
  if (in.wasPressed(Action::DebugOverlay)) overlay_.toggle();
  if (in.wasPressed(Action::Screenshot)) frames_.screenshot = true;
  if (in.wasPressed(Action::DebugView)) overlay_.nextView();
  if (in.wasPressed(Action::TimeFaster)) world_.time().faster();
  if (in.wasPressed(Action::TimeStop)) world_.time().toggleStop();
  if (in.wasPressed(Action::TimeSet)) world_.level().time = TimeControls::nextPreset(world_.level().time);
  if (in.wasPressed(Action::Jump)) world_.jumpPressed(frames_.clock);
  interaction_.update(in, dt, world_);
}

void Game::drawLoading(glm::ivec2 size) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, size.x, size.y);
  glClearColor(0.08f, 0.09f, 0.11f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const WorldCounts c = world_.streamed().counts();
  ui_.begin();
  ui_.loading("Loading the world: " + std::to_string(c.loaded) + " chunks, " + std::to_string(c.pending) +
              " to come");
  ui_.notice(frames_.clock);
  ui_.end();
}

void Game::draw(bool timed) {
  const GameSettings& s = settings_.values;
  const Player& player = world_.player();
  FrameInputs frame;
  frame.cameraPosition = player.eyeAt(frames_.tickAccumulator * kTicksPerSecond);
  frame.cameraLookAt = frame.cameraPosition + player.forward();
  frame.fovDegrees = s.fov;
  frame.ticks = world_.level().time;
  frame.sunPathRotation = s.sunPathRotation;
  frame.viewDistance = static_cast<float>(s.viewDistance * kChunkSize);
  if (far_) {
    far_->update(frame.cameraPosition, s.viewDistance, world_, renderer_.lod());
    frame.lod = &renderer_.lod();
    frame.lodShadows = s.lod.shadows;
    frame.viewDistance = static_cast<float>(std::max(s.viewDistance, far_->distance()) * kChunkSize);
  }
  frame.debugView = overlay_.view();
  frame.reuseShadowMap = true;
  frame.props = &world_.props().placed().gpu();
  frame.underWater = underWaterAt(world_.world(), world_.light(), frame.cameraPosition);
  frame.eyeLight = eyeLightAt(world_.light(), frame.cameraPosition);
  frame.renderScale = renderScale();
  if (!input_.screenOpen() && ui_.hudShown()) frame.outline = interaction_.outline(world_);
  frame.crack = interaction_.crack();
  overlay_.timings().clear();
  renderer_.render(frame, drawableSize(), timed ? &overlay_.timings() : nullptr);
}

void Game::drawHud() {
  ui_.begin();
  if (ui_.hudShown() && !input_.screenOpen()) ui_.crosshairAndHotbar(renderer_, interaction_.hotbar());
  if (ui_.hudShown()) ui_.notice(frames_.clock);
  if (overlay_.shown()) {
    const std::deque<float>& graph = overlay_.graph();
    std::vector<std::string> left =
        overlay_.left(world_, renderer_, far_ ? std::optional(far_->stats()) : std::nullopt);
    left.push_back(audio_.overlayLine());
    ui_.overlay(
        std::move(left),
        overlay_.right(world_, settings_.values, drawableSize(), renderScale(), interaction_.target()),
        {graph.begin(), graph.end()});
  }
  if (input_.screen() == Screen::Menu) {
    // Listed while the menu shows, so a pack dropped into the folder appears at once.
    const ShaderPackChoices shaderPacks{findShaderPacks({kShaderPacksDir, shaderPackDir()}),
                                        renderer_.shaderPackError()};
    applyMenu(ui_.menu(renderer_.assets().packNames, shaderPacks, world_.propFiles()));
  }
  if (input_.screen() == Screen::Inventory) ui_.inventory(renderer_, interaction_.hotbar());
  ui_.end();
}

}  // namespace terrasol
