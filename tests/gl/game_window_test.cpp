// The game in a real window (GLX under Xvfb): `terrasol --frames N` exits 0, and its last frame is
// the same picture the headless EGL path renders for the same moment of the flight.

#include <cstdlib>

#include "demo.h"
#include "scene_render.h"
#include "support/gl_test.h"
#include "support/golden.h"

namespace terrasol {
namespace {

class GameWindowTest : public testing::GlTest {};

TEST_F(GameWindowTest, WindowShowsWhatHeadlessRenders) {
  constexpr int kFrames = 5;
  const auto screenshot = testing::testOutputDir() / "game_window.png";
  std::filesystem::remove(screenshot);
  const std::string command = std::string(TERRASOL_XVFB_RUN) + " -a -s '-screen 0 640x480x24' " +
                              TERRASOL_GAME_EXE + " --frames " + std::to_string(kFrames) +
                              " --size 320x180 --screenshot " + screenshot.string();
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Image window = loadImage(screenshot);

  SceneRenderer scene(demoScene({320, 180}));
  const Image headless = scene.renderFrame(demoFrame((kFrames - 1) * kFixedStep)).image;

  const ImageComparison cmp = compareImages(window, headless, {});
  EXPECT_TRUE(cmp.matches) << cmp.failingPercent << " % of pixels differ, max " << cmp.maxError * 255.0;
}

}  // namespace
}  // namespace terrasol
