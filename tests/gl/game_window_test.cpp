// The game in a real window (GLX under Xvfb). `terrasol --demo --frames N` shows the same picture the
// headless EGL path renders for that moment of the flight; a scripted play walks, breaks a block,
// places a torch, saves and quits, and a second run of the same world finds both edits and the
// torch's light.

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "demo.h"
#include "scene_render/scene_render.h"
#include "support/game_run.h"
#include "support/gl_test.h"
#include "support/gltf_box.h"
#include "support/golden.h"

namespace terrasol {
namespace {

class GameWindowTest : public testing::GlTest {};

using testing::GameDir;
using testing::readJson;
using testing::runGame;

TEST_F(GameWindowTest, WindowShowsWhatHeadlessRenders) {
  constexpr int kFrames = 5;
  const auto screenshot = testing::testOutputDir() / "game_window.png";
  std::filesystem::remove(screenshot);
  ASSERT_EQ(runGame("--demo --frames " + std::to_string(kFrames) + " --size 320x180 --screenshot " +
                    screenshot.string()),
            0);
  const Image window = loadImage(screenshot);

  // The same frames in the same order: the shadow map's centre keeps its place until the camera has
  // moved far enough, so the last frame depends on the ones before it.
  SceneRenderer scene(demoScene({320, 180}));
  Image headless;
  for (int frame = 0; frame < kFrames; ++frame)
    headless = scene.renderFrame(demoFrame(frame * kFixedStep)).image;

  const ImageComparison cmp = compareImages(window, headless, {});
  EXPECT_TRUE(cmp.matches) << cmp.failingPercent << " % of pixels differ, max " << cmp.maxError * 255.0;
}

TEST_F(GameWindowTest, ScriptedPlayEditsSavesAndTheNextRunFindsTheEditsAndTheLight) {
  const GameDir game("game_smoke");
  const auto& dir = game.dir;
  const std::string& common = game.common;

  const auto first = dir / "first.json";
  ASSERT_EQ(runGame(common + " --seed 1 --input-script " + std::string(TERRASOL_SOURCE_DIR) +
                    "/tests/scripts/game_smoke.json --report " + first.string()),
            0);
  const nlohmann::json played = readJson(first);
  const auto& pos = played["player"]["position"];
  EXPECT_GT(std::hypot(pos[0].get<double>() - 0.5, pos[2].get<double>() - 0.5), 2.0)
      << "the player walked from the spawn";
  // The last edit of each cell is what the world must hold.
  std::map<std::array<int, 3>, std::string> edited;
  for (const auto& e : played["edits"]) {
    edited[{e["pos"][0].get<int>(), e["pos"][1].get<int>(), e["pos"][2].get<int>()}] =
        e["block"].get<std::string>();
  }
  const auto count = [&](const std::string& block) {
    return std::count_if(edited.begin(), edited.end(), [&](const auto& e) { return e.second == block; });
  };
  ASSERT_GE(count("air"), 1) << played.dump();
  ASSERT_EQ(count("torch"), 1) << played.dump();

  const auto second = dir / "second.json";
  std::string probes;
  for (const auto& [p, block] : edited) {
    probes += " --probe " + std::to_string(p[0]) + "," + std::to_string(p[1]) + "," + std::to_string(p[2]);
  }
  ASSERT_EQ(runGame(common + " --seed 99 --frames 3" + probes + " --report " + second.string()), 0);
  const nlohmann::json reopened = readJson(second);
  ASSERT_EQ(reopened["probes"].size(), edited.size());
  auto expected = edited.begin();
  for (const auto& probe : reopened["probes"]) {
    EXPECT_TRUE(probe["loaded"].get<bool>());
    EXPECT_EQ(probe["block"], expected->second) << probe.dump();
    if (expected->second == "torch") {
      EXPECT_EQ(probe["block_light"], 14) << "the torch's light is back";
    }
    ++expected;
  }
  const auto& back = reopened["player"]["position"];
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(back[i].get<double>(), pos[i].get<double>(), 0.01) << "the player is where they saved";
  // Kept, plus the few ticks the second run's frames took (wall-clock time: a busy machine takes more).
  const std::int64_t kept = reopened["time"].get<std::int64_t>() - played["time"].get<std::int64_t>();
  EXPECT_GE(kept, 0) << "the world time is kept";
  EXPECT_LT(kept, 40) << "the world time is kept";
}

// E opens the creative inventory over the frozen game: every block's icon and the hotbar below. A
// void world at noon behind it, so the picture depends on nothing streamed.
TEST_F(GameWindowTest, TheInventoryKeyOpensTheInventory) {
  const GameDir game("game_inventory");
  std::filesystem::create_directories(game.dir / "world");
  std::ofstream(game.dir / "world" / "level.json")
      << R"({ "version": 1, "generator": "void", "seed": 1, "time": 6000,
              "player": { "position": [0.5, 100, 0.5], "yaw": 0, "pitch": 0, "flying": true } })";
  const auto script = game.dir / "script.json";
  std::ofstream(script) << R"({ "step": 0.05, "events": [ { "t": 0.1, "key": "E" } ] })";
  const auto report = game.dir / "report.json";
  const auto shot = game.dir / "inventory.png";
  ASSERT_EQ(runGame(game.common + " --size 480x270 --input-script " + script.string() +
                    " --frames 10 --screenshot " + shot.string() + " --report " + report.string()),
            0);
  EXPECT_EQ(readJson(report)["screen"], "inventory");
  EXPECT_TRUE(testing::matchesGolden(loadImage(shot), "game_inventory"));
}

TEST_F(GameWindowTest, APlacedPropIsLitSavedAndBackInTheNextRun) {
  const GameDir game("game_prop");
  const auto& dir = game.dir;
  std::filesystem::create_directories(dir / "world" / "props");
  // One model from the world's props folder (relative, as the menu offers it), one from anywhere.
  testing::writeBoxGltf(dir / "world" / "props");
  std::filesystem::create_directories(dir / "elsewhere");
  const auto elsewhere = testing::writeBoxGltf(
      dir / "elsewhere", {{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0.8, 1}}}}});
  const auto script = dir / "script.json";
  std::ofstream(script) << R"({ "step": 0.05, "events": [
      { "t": 0.0, "look": [0, 60] },
      { "t": 0.2, "command": "place_prop", "model": "props/box.gltf" },
      { "t": 0.4, "look": [180, 60] },
      { "t": 0.6, "command": "place_prop", "model": ")" +
                               elsewhere.string() + R"(" },
      { "t": 0.8, "look": [-45, 30] },
      { "t": 1.1, "command": "save" },
      { "t": 1.2, "command": "quit" } ] })";
  const std::string& common = game.common;
  const auto first = dir / "first.json";
  ASSERT_EQ(
      runGame("--seed 5 " + common + " --input-script " + script.string() + " --report " + first.string()),
      0);
  const nlohmann::json placed = readJson(first);
  ASSERT_EQ(placed["props"].size(), 2u) << placed.dump();
  EXPECT_EQ(placed["props"][0]["model"], "props/box.gltf");
  for (const auto& p : placed["props"]) {
    EXPECT_GT(p["light"][1].get<double>(), 0.5) << "outdoors by day: sky light at its vertices " << p.dump();
  }
  // The save keeps them; the next run draws them where they were.
  const auto second = dir / "second.json";
  ASSERT_EQ(runGame(common + " --frames 3 --report " + second.string()), 0);
  const nlohmann::json reopened = readJson(second);
  ASSERT_EQ(reopened["props"].size(), 2u) << reopened.dump();
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(reopened["props"][i]["model"], placed["props"][i]["model"]);
    EXPECT_EQ(reopened["props"][i]["position"], placed["props"][i]["position"]);
  }
  // A prop whose model went missing stays in the level, undrawn, and the game runs on.
  std::filesystem::rename(dir / "world" / "props" / "box.gltf", dir / "box.gltf");
  const auto third = dir / "third.json";
  ASSERT_EQ(runGame(common + " --frames 2 --report " + third.string()), 0);
  EXPECT_EQ(readJson(third)["props"].size(), 1u);
  EXPECT_EQ(readJson(dir / "world" / "level.json")["props"].size(), 2u)
      << "the broken one is kept for when the file comes back";
  // Back again, the box is where it was; looking at it as when it was placed and breaking removes it.
  std::filesystem::rename(dir / "box.gltf", dir / "world" / "props" / "box.gltf");
  const auto removeScript = dir / "remove.json";
  std::ofstream(removeScript) << R"({ "step": 0.05, "events": [
      { "t": 0.0, "look": [0, 60] }, { "t": 0.2, "button": "left" },
      { "t": 0.4, "command": "save" }, { "t": 0.5, "command": "quit" } ] })";
  const auto fourth = dir / "fourth.json";
  ASSERT_EQ(runGame(common + " --input-script " + removeScript.string() + " --report " + fourth.string()), 0);
  const nlohmann::json removed = readJson(fourth);
  ASSERT_EQ(removed["props"].size(), 1u) << removed.dump();
  EXPECT_NE(removed["props"][0]["model"], "props/box.gltf");
  EXPECT_TRUE(removed["edits"].empty()) << "the click took the prop, not the block behind it";
  EXPECT_EQ(readJson(dir / "world" / "level.json")["props"].size(), 1u);
}

TEST_F(GameWindowTest, AMinimisedWindowDrawsNothingWhileTheWorldGoesOnAndComesBack) {
  const GameDir game("game_minimise", 256, 16);
  const auto& dir = game.dir;
  const auto report = dir / "report.json", log = dir / "log.txt";
  // Under a window manager (twm), started in the game's virtual display before the game; screenshots
  // land in the working directory.
  const std::string command = "cd " + dir.string() + " && " + TERRASOL_XVFB_RUN +
                              " -a -s '-screen 0 640x480x24' sh -c '" + "LC_ALL=C " + TERRASOL_TWM + " -f " +
                              TERRASOL_SOURCE_DIR + "/tests/scripts/twmrc 2>/dev/null & sleep 1; exec " +
                              TERRASOL_GAME_EXE + " " + game.common + " --seed 3 --input-script " +
                              TERRASOL_SOURCE_DIR + "/tests/scripts/game_minimise.json --report " +
                              report.string() + "' > " + log.string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << readTextFile(log);
  const std::string output = readTextFile(log);
  EXPECT_NE(output.find("window minimised"), std::string::npos) << output;
  EXPECT_NE(output.find("no screenshot: the window has no pixels"), std::string::npos) << output;
  EXPECT_NE(output.find("window restored"), std::string::npos) << output;
  EXPECT_EQ(output.find("error: GL:"), std::string::npos) << output;
  EXPECT_EQ(output.find("warning: GL:"), std::string::npos) << output;
  const nlohmann::json played = readJson(report);
  // 0.5 s of 0.05 s steps at least while minimised (the restore takes effect when the manager maps it).
  EXPECT_GE(played["frames"]["minimised"].get<int>(), 10) << played.dump();
  EXPECT_GE(played["frames"]["drawn"].get<int>(), 10) << played.dump();
  EXPECT_GE(played["time"].get<std::int64_t>(), 40) << "2 s of play are 40 ticks, minimised or not";
  // Only the screenshot after the restore was taken, and it shows the world.
  std::vector<std::filesystem::path> shots;
  for (const auto& e : std::filesystem::directory_iterator(dir / "screenshots")) shots.push_back(e.path());
  ASSERT_EQ(shots.size(), 1u);
  const Image shot = loadImage(shots[0]);
  EXPECT_EQ(shot.width, 320);
  EXPECT_GT(*std::max_element(shot.rgba.begin(), shot.rgba.end()), 50)
      << "the restored window draws the world again";
}

// --shaderpack draws the game through a shader pack (its picture is not Terrasol's); one that does not
// build leaves Terrasol's pipeline drawing, and the game says why. (Pictures of two runs are not
// compared pixel for pixel: the game's frames follow the machine's pace.)
TEST_F(GameWindowTest, AShaderPackDrawsTheGameAndABrokenOneFallsBack) {
  const auto run = [&](const std::string& name, const std::string& pack) {
    const GameDir game(name);
    const auto report = game.dir / "report.json";
    EXPECT_EQ(runGame(game.common + " --seed 1 --frames 30 --report " + report.string() + pack), 0) << name;
    return readJson(report);
  };
  const nlohmann::json own = run("game_no_shaderpack", "");
  EXPECT_EQ(own["shader_pack"], "");
  const nlohmann::json example =
      run("game_example_shaderpack",
          " --shaderpack " + std::string(TERRASOL_SOURCE_DIR) + "/shaderpacks/terrasol-example");
  EXPECT_EQ(example["shader_pack"], "terrasol-example");
  EXPECT_EQ(example["shader_pack_error"], "");
  EXPECT_GT(example["frames"]["drawn"].get<int>(), 0);

  const auto broken = testing::testOutputDir() / "broken_shaderpack";
  std::filesystem::create_directories(broken / "shaders");
  std::ofstream(broken / "shaders" / "final.vsh")
      << "#version 120\nvoid main() { gl_Position = ftransform(); }\n";
  std::ofstream(broken / "shaders" / "final.fsh")
      << "#version 120\nvoid main() { gl_FragColor = nothing; }\n";
  const nlohmann::json fallback = run("game_broken_shaderpack", " --shaderpack " + broken.string());
  EXPECT_EQ(fallback["shader_pack"], "") << "Terrasol's pipeline drew";
  EXPECT_NE(fallback["shader_pack_error"].get<std::string>().find("final.fsh:2"), std::string::npos)
      << fallback["shader_pack_error"];
  EXPECT_GT(fallback["frames"]["drawn"].get<int>(), 0);
}

}  // namespace
}  // namespace terrasol
