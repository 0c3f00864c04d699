// First-start settings (game/first_run.h) and their record in the settings file.
#include "first_run.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

TEST(FirstRun, SoftwareRenderingGetsLightSettingsThatStillShowShadows) {
  const GameSettings s = firstRunSettings({"llvmpipe (LLVM 15.0.6, 256 bits)", 6.0});
  EXPECT_EQ(s.viewDistance, 4);
  EXPECT_TRUE(s.shadow.enabled);
  EXPECT_EQ(s.shadow.resolution, 1024);
  EXPECT_FALSE(s.reflections.enabled);
  EXPECT_EQ(s.targetFps, 30);
  EXPECT_EQ(s.antialiasing, Antialiasing::Fxaa);
  ASSERT_TRUE(s.firstRun);
  EXPECT_NE(s.firstRun->choice.find("software"), std::string::npos);
  EXPECT_NE(s.firstRun->choice.find("the medium preset"), std::string::npos);
  const GameSettings slow = firstRunSettings({"llvmpipe (LLVM 15.0.6, 256 bits)", 20.0});
  EXPECT_EQ(slow.viewDistance, 3) << "slow even when empty";
  EXPECT_TRUE(slow.shadow.enabled);
  EXPECT_EQ(slow.antialiasing, Antialiasing::None);
  EXPECT_EQ(slow.shadow.updateFrames, 8) << "what a preset does not decide stays";
}

TEST(FirstRun, AGpuGetsTheFullSettings) {
  const GameSettings s = firstRunSettings({"NVIDIA H200/PCIe/SSE2", 0.4});
  EXPECT_EQ(s.viewDistance, 12);
  EXPECT_EQ(s.shadow.resolution, 4096);
  EXPECT_TRUE(s.reflections.enabled);
  EXPECT_EQ(s.antialiasing, Antialiasing::Taa);
  EXPECT_TRUE(s.bloom.enabled);
  EXPECT_EQ(s.targetFps, 60);
  EXPECT_FALSE(softwareRenderer("AMD Radeon RX 7600 (radeonsi, navi33, LLVM 15.0.6)"));
  EXPECT_TRUE(softwareRenderer("softpipe"));
}

TEST(FirstRun, TheChoiceIsKeptInTheSettingsFile) {
  const GameSettings chosen = firstRunSettings({"llvmpipe (LLVM 15.0.6, 256 bits)", 7.5});
  const auto file = testing::scratchDir("first_run") / "settings.json";
  saveSettings(file, chosen);
  const GameSettings back = loadSettings(file);
  ASSERT_TRUE(back.firstRun);
  EXPECT_EQ(*back.firstRun, *chosen.firstRun);
  EXPECT_EQ(back.targetFps, 30);
  EXPECT_FLOAT_EQ(back.renderScale, 1.0f);
  EXPECT_THROW(parseSettings(R"({"render_scale": 2})", "s.json"), Error);
  EXPECT_THROW(parseSettings(R"({"first_run": {"gl": ""}})", "s.json"), Error);
}

}  // namespace
}  // namespace terrasol
