// Sound events from resource packs (assets/sound_events.h): stacking with and without "replace",
// weights and events naming events, and bad files and entries reported while the rest still plays.

#include "assets/sound_events.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "support/pack_builder.h"

namespace terrasol {
namespace {

using testing::PackBuilder;
using testing::stackOf;

bool mentions(const std::vector<std::string>& problems, const std::string& a, const std::string& b) {
  return std::any_of(problems.begin(), problems.end(), [&](const std::string& p) {
    return p.find(a) != std::string::npos && p.find(b) != std::string::npos;
  });
}

TEST(SoundEvents, APackReplacesOrAddsToTheEventsBelowIt) {
  PackBuilder base("sounds_base"), top("sounds_top");
  base.asset("sounds.json", R"({
    "block.stone.break": {"subtitle": "subtitles.block.generic.break", "sounds": ["dig/stone1", "dig/stone2"]},
    "block.grass.step": {"sounds": ["step/grass1"]}
  })");
  top.asset("sounds.json", R"({
    "block.stone.break": {"replace": true, "sounds": [{"name": "mypack:crack", "volume": 0.5, "pitch": 1.2}]},
    "block.grass.step": {"sounds": ["step/grass2"]}
  })");
  std::vector<std::string> problems;
  const SoundEvents events = SoundEvents::load(stackOf({base.dir(), top.dir()}), problems);
  EXPECT_TRUE(problems.empty()) << problems.front();
  const SoundEvent* stone = events.find("block.stone.break");
  ASSERT_NE(stone, nullptr);
  ASSERT_EQ(stone->sounds.size(), 1u) << "replaced";
  EXPECT_EQ(stone->subtitle, "subtitles.block.generic.break") << "kept from below: the top pack names none";
  const std::optional<SoundPick> crack = events.pick("block.stone.break", 12345u);
  ASSERT_TRUE(crack);
  EXPECT_EQ(crack->file, "assets/mypack/sounds/crack.ogg");
  EXPECT_FLOAT_EQ(crack->volume, 0.5f);
  EXPECT_FLOAT_EQ(crack->pitch, 1.2f);
  EXPECT_EQ(crack->reach, kDefaultSoundReach);
  ASSERT_EQ(events.find("block.grass.step")->sounds.size(), 2u) << "added to";
  EXPECT_EQ(events.find("block.grass.step")->sounds[1].name, "minecraft:step/grass2");
  EXPECT_FALSE(events.pick("block.wood.break", 1u)) << "no such event";
}

TEST(SoundEvents, WeightsChooseAndEventsNameEvents) {
  SoundEvents events;
  std::vector<std::string> problems;
  events.merge(R"({
    "ambient.cave": {"sounds": [{"name": "ambient/cave/cave1", "weight": 3, "attenuation_distance": 32},
                                {"name": "ambient/cave/cave2", "weight": 1}]},
    "music.game": {"sounds": [{"name": "ambient.cave", "type": "event", "volume": 0.5},
                              {"name": "music/calm1", "stream": true, "weight": 0}]},
    "loop.a": {"sounds": [{"name": "loop.b", "type": "event"}]},
    "loop.b": {"sounds": [{"name": "minecraft:loop.a", "type": "event"}]},
    "empty": {"sounds": []}
  })",
               "sounds.json", problems);
  ASSERT_TRUE(problems.empty()) << problems.front();
  std::map<std::string, int> counts;
  std::uint32_t state = 1;
  for (int i = 0; i < 4000; ++i) {
    state = state * 1664525u + 1013904223u;
    const std::optional<SoundPick> p = events.pick("music.game", state);
    ASSERT_TRUE(p);
    EXPECT_FLOAT_EQ(p->volume, 0.5f) << "the event entry's volume carries to what it picks";
    EXPECT_FALSE(p->stream) << "weight 0 is never picked";
    ++counts[p->file];
  }
  const int one = counts["assets/minecraft/sounds/ambient/cave/cave1.ogg"];
  const int two = counts["assets/minecraft/sounds/ambient/cave/cave2.ogg"];
  EXPECT_EQ(one + two, 4000);
  EXPECT_NEAR(static_cast<double>(one) / 4000.0, 0.75, 0.03);
  EXPECT_EQ(events.pick("ambient.cave", 0u)->reach, 32.0f);
  EXPECT_FALSE(events.pick("loop.a", 7u)) << "events that only name each other play nothing, and end";
  EXPECT_FALSE(events.pick("empty", 7u));
}

TEST(SoundEvents, BadFilesAndEntriesAreNamedAndTheRestPlays) {
  SoundEvents events;
  std::vector<std::string> problems;
  events.merge(R"({ "block.stone.break": { "sounds": ["dig/stone1"] )", "broken/sounds.json", problems);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("broken/sounds.json"), std::string::npos) << problems[0];
  EXPECT_EQ(events.size(), 0u);

  problems.clear();
  events.merge(R"({
    "block.stone.break": {"sounds": ["dig/stone1", {"name": "dig/stone2", "volume": "loud"}, {"pitch": 1}]},
    "block.wood.break": {"sounds": "dig/wood1"},
    "block.sand.break": {"sound": ["dig/sand1"]},
    "block.glass.break": {"sounds": [{"name": "random/glass1", "type": "noise"}, "random/glass2"]}
  })",
               "pack/sounds.json", problems);
  EXPECT_EQ(problems.size(), 5u);
  EXPECT_TRUE(mentions(problems, "pack/sounds.json", "block.stone.break.sounds[1].volume"));
  EXPECT_TRUE(mentions(problems, "pack/sounds.json", "block.stone.break.sounds[2]"));
  EXPECT_TRUE(mentions(problems, "pack/sounds.json", "block.wood.break.sounds"));
  EXPECT_TRUE(mentions(problems, "pack/sounds.json", "block.sand.break"));
  EXPECT_TRUE(mentions(problems, "pack/sounds.json", "block.glass.break.sounds[0].type"));
  // What was good still plays.
  EXPECT_EQ(events.find("block.stone.break")->sounds.size(), 1u);
  EXPECT_EQ(events.pick("block.glass.break", 3u)->file, "assets/minecraft/sounds/random/glass2.ogg");
  EXPECT_EQ(events.find("block.wood.break"), nullptr);
}

}  // namespace
}  // namespace terrasol
