// terrasol: the game. Opens (or creates) a world and plays it in a window; with no display it says so
// and renders a few frames of a flight over the generated world headless instead.

#include <cstdio>
#include <exception>

#include "core/log.h"
#include "demo.h"
#include "game.h"
#include "options.h"
#include "platform/glfw/glfw_window.h"
#include "scene_render/scene_render.h"
#include "screenshot.h"

namespace terrasol {
namespace {

// The demo flight in the window (also what the window test compares with the headless render).
int flyDemo(GlfwWindow& window, const GameOptions& options) {
  SceneRenderer scene(demoScene(window.framebufferSize()));
  for (int frame = 0; !window.shouldClose(); ++frame) {
    window.pollEvents();
    // A fixed step when the frame count is fixed, so smoke-test screenshots are reproducible.
    const double seconds = options.frames ? frame * kFixedStep : window.time();
    scene.draw(demoFrame(seconds), 0, window.framebufferSize());
    window.checkErrors("frame");
    const bool last = options.frames && frame + 1 >= *options.frames;
    if (last && !options.screenshot.empty()) saveScreenshot(options.screenshot, window.framebufferSize());
    window.swapBuffers();
    if (last) break;
  }
  return 0;
}

int run(const GameOptions& options) {
  try {
    GlfwWindow window("Terrasol", options.size);
    logInfo("OpenGL: " + window.description());
    return options.demo ? flyDemo(window, options) : playGame(window, options);
  } catch (const NoDisplayError& e) {
    if (options.benchmark || !options.inputScript.empty()) throw;  // these need the real game
    constexpr int kDemoFrames = 8;
    std::printf(
        "terrasol: %s.\nNo window can be opened here, so rendering a %d-frame demo headless instead...\n",
        e.what(), kDemoFrames);
    std::fflush(stdout);
    const auto dir = renderHeadlessDemo(options.demoDir, kDemoFrames, {640, 360});
    std::printf("terrasol: wrote %d demo frames to %s/frame_0000.png ... frame_%04d.png\n", kDemoFrames,
                dir.string().c_str(), kDemoFrames - 1);
    return 0;
  }
}

}  // namespace
}  // namespace terrasol

int main(int argc, char** argv) {
  try {
    const auto options = terrasol::parseGameOptions({argv + 1, argv + argc});
    if (options.help) {
      std::fputs(terrasol::gameUsage().c_str(), stdout);
      return 0;
    }
    return terrasol::run(options);
  } catch (const std::exception& e) {
    terrasol::logError(e.what());
    return 1;
  }
}
