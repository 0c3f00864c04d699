// The game's sound, heard without speakers: a scripted play (tests/scripts/game_sounds.json) on a
// flat world writes what it plays to a .wav through OpenAL Soft's loopback device, in step with its
// frames, and every sound it asks for to a log. The right events fire at the script's ticks, each is
// heard where the log says it starts, a door to the right is louder on the right, and where nothing
// happens there is silence.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>

#include "audio/wav_file.h"
#include "support/audio_levels.h"
#include "support/game_run.h"

namespace terrasol {
namespace {

using testing::GameDir;
using testing::runGame;

struct Heard {
  std::string event;
  std::int64_t tick = 0;
  std::size_t sample = 0;
  double z = 0.0;
};

using testing::Levels;
using testing::levels;

// Plays tests/scripts/`script` on a fresh flat world of grass in `game`, into game.dir/heard.wav; the
// sounds it asked for whose event `keep` takes, each checked to have played a file.
std::vector<Heard> play(const GameDir& game, const std::string& script,
                        const std::function<bool(const std::string&)>& keep) {
  std::filesystem::create_directories(game.dir / "world");
  std::ofstream(game.dir / "world" / "level.json")
      << R"({ "version": 1, "generator": "flat", "seed": 1, "time": 6000,
              "player": { "position": [0.5, 64, 0.5], "yaw": 0, "pitch": 0, "flying": false } })";
  const auto log = game.dir / "sounds.jsonl";
  EXPECT_EQ(
      runGame(game.common + " --input-script " + std::string(TERRASOL_SOURCE_DIR) + "/tests/scripts/" +
              script + " --audio-out " + (game.dir / "heard.wav").string() + " --sound-log " + log.string()),
      0);
  std::vector<Heard> heard;
  std::istringstream lines(readTextFile(log));
  for (std::string line; std::getline(lines, line);) {
    const nlohmann::json j = nlohmann::json::parse(line);
    const std::string event = j["event"].get<std::string>();
    if (!keep(event)) continue;
    EXPECT_FALSE(j["file"].is_null()) << event << " played nothing";
    heard.push_back(
        {event, j["tick"].get<std::int64_t>(), j["sample"].get<std::size_t>(), j["at"][2].get<double>()});
  }
  return heard;
}

TEST(GameSound, AScriptedPlayIsHeardAtItsTicks) {
  const GameDir game("game_sound", 512, 32, R"({ "music": 0 })");
  // Music (at volume 0 here) comes when it will.
  const std::vector<Heard> heard =
      play(game, "game_sounds.json", [](const std::string& event) { return event.starts_with("block."); });
  const auto wavFile = game.dir / "heard.wav", log = game.dir / "sounds.jsonl";
  // What the script does, in order, and when (ticks after the first break: the script's seconds x 20).
  const std::vector<std::pair<std::string, int>> expected = {
      {"block.grass.break", 0},  {"block.stone.place", 6},      {"block.grass.break", 14},
      {"block.stone.place", 20}, {"block.grass.break", 28},     {"block.stone.place", 34},
      {"block.stone.step", -1},  {"block.stone.step", -1},      {"block.grass.step", -1},
      {"block.wood.place", 74},  {"block.wooden_door.open", 82}};
  ASSERT_EQ(heard.size(), expected.size()) << readTextFile(log);
  const std::int64_t start = heard[0].tick;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(heard[i].event, expected[i].first) << i;
    if (expected[i].second >= 0) {
      EXPECT_NEAR(static_cast<double>(heard[i].tick - start), expected[i].second, 1.0) << heard[i].event;
    } else {  // steps: while walking (the script's 2.5 to 3.7 s, and the few ticks it takes to stop)
      EXPECT_GE(heard[i].tick - start, 40) << heard[i].event;
      EXPECT_LE(heard[i].tick - start, 70) << heard[i].event;
    }
  }
  // Stone underfoot over the three set cells, grass beyond them.
  EXPECT_LT(heard[7].z, 4.0);
  EXPECT_GT(heard[8].z, 4.0);

  const Pcm wav = readWav(wavFile);
  ASSERT_EQ(wav.channels, 2);
  const std::size_t tick = static_cast<std::size_t>(wav.rate / 20);
  // Every sound is heard where it starts; those in front of the player equally on both sides.
  for (const Heard& h : heard) {
    const Levels l = levels(wav, h.sample, 0.1);
    EXPECT_GT(l.both(), 150.0) << h.event << " at tick " << h.tick << " is not heard";
    if (h.event.find("break") != std::string::npos || h.event.find("place") != std::string::npos) {
      EXPECT_LT(std::abs(l.left - l.right), 0.25 * (l.left + l.right)) << h.event << " is in front";
    }
  }
  // The player turns to the east a tick after opening the door to the south: it is on the right.
  const Levels door = levels(wav, heard.back().sample + 2 * tick, 0.4);
  EXPECT_GT(door.right, 1.5 * door.left) << door.left << " left, " << door.right << " right";
  // Silence before the first sound and for the last second (OpenAL Soft's dither is +-1).
  EXPECT_LT(levels(wav, 0, static_cast<double>(heard[0].sample - tick) / wav.rate).both(), 3.0);
  const std::size_t quiet = heard.back().sample + 28 * tick;
  ASSERT_LT(quiet, wav.frames());
  EXPECT_LT(levels(wav, quiet, static_cast<double>(wav.frames() - quiet) / wav.rate).both(), 3.0);
}

// With survival digging on, holding the button on a block hits it every 4th tick until it breaks:
// the grass block (hardness 0.6) in 3 ticks from the click, a hit on the first; after 5 ticks' pause
// and a tick to start on it, the dirt under it (ticks as logged after each frame: +-1).
// With it off (the test above) no hit is heard: blocks break at the click.
TEST(GameSound, SurvivalDiggingHitsTheBlockUntilItBreaks) {
  const GameDir game("game_sound_survival", 512, 32, R"({ "music": 0 })", R"(, "survival_digging": true)");
  const std::vector<Heard> heard = play(game, "survival_dig.json", [](const std::string& event) {
    return event.ends_with(".hit") || event.ends_with(".break") || event.ends_with(".place");
  });
  ASSERT_GE(heard.size(), 4u) << readTextFile(game.dir / "sounds.jsonl");
  EXPECT_EQ(heard[0].event, "block.grass.hit");
  EXPECT_EQ(heard[1].event, "block.grass.break") << "a right click while digging places nothing";
  EXPECT_NEAR(static_cast<double>(heard[1].tick - heard[0].tick), 2.0, 1.0)
      << "ticks 1 and 3 of the grass block's 3";
  EXPECT_EQ(heard[2].event, "block.gravel.hit") << "dirt sounds as gravel";
  EXPECT_NEAR(static_cast<double>(heard[2].tick - heard[1].tick), 7.0, 0.5) << "5 ticks' pause, 1 to start";
  EXPECT_EQ(heard[3].event, "block.gravel.break");
  EXPECT_NEAR(static_cast<double>(heard[3].tick - heard[2].tick), 2.0, 1.0);
}

}  // namespace
}  // namespace terrasol
