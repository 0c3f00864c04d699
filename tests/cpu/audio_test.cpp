// The audio engine without a sound card: OpenAL Soft's loopback device renders what plays into
// memory, so these tests hear it. Also the default pack's sounds (every event the game fires has
// one and every file decodes), .wav files, and which voice a sound takes when voices run out.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <set>

#include "ambience.h"
#include "audio/audio_engine.h"
#include "audio/ogg_file.h"
#include "audio/voice_pool.h"
#include "audio/wav_file.h"
#include "core/paths.h"
#include "music_timer.h"
#include "soundgen.h"
#include "support/audio_levels.h"
#include "support/pack_builder.h"
#include "support/world_support.h"
#include "world/block_sounds.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;

std::vector<std::uint8_t> bytesOf(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

PackStack defaultPack() {
  return testing::stackOf({resourcePackDir() / "default"});
}

using testing::Levels;

Levels rms(std::span<const std::int16_t> stereo) {
  return testing::levels(stereo);
}

TEST(VoicePool, TheQuietestGivesWayToALouderSound) {
  VoicePool pool(3);
  EXPECT_EQ(pool.claim(0.5f), 0);
  EXPECT_EQ(pool.claim(0.2f), 1);
  EXPECT_EQ(pool.claim(0.9f), 2);
  EXPECT_EQ(pool.busyCount(), 3);
  EXPECT_FALSE(pool.claim(0.1f));  // quieter than all that play: not played
  EXPECT_EQ(pool.claim(0.3f), 1);  // takes the 0.2 voice
  pool.release(0);
  EXPECT_EQ(pool.claim(0.01f), 0);  // a free voice takes any sound
}

TEST(WavFile, WritesAndReadsBack) {
  const std::filesystem::path file = testing::testOutputDir() / "roundtrip.wav";
  const std::vector<std::int16_t> samples = {0, 1, -1, 32767, -32768, 1234, -4321, 7};
  {
    WavWriter w(file, 2, 44100);
    w.write(samples);
  }
  const Pcm back = readWav(file);
  EXPECT_EQ(back.channels, 2);
  EXPECT_EQ(back.rate, 44100);
  EXPECT_EQ(back.samples, samples);
  std::ofstream(testing::testOutputDir() / "not.wav") << "RIFF but not really";
  try {
    readWav(testing::testOutputDir() / "not.wav");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not.wav"), std::string::npos) << e.what();
  }
}

TEST(OggFile, BadBytesAreAnErrorNamingTheFile) {
  try {
    decodeOgg({'O', 'g', 'g', 'S', 0, 1, 2}, "pack/sounds/bad.ogg");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("pack/sounds/bad.ogg"), std::string::npos) << e.what();
  }
}

// Every sound the game can ask for is in the default pack, and every file it names decodes to
// sound: no silence, no clipping, no NaN.
TEST(DefaultPackSounds, EveryEventTheGameFiresHasASound) {
  std::vector<std::string> problems;
  const SoundEvents events = SoundEvents::load(defaultPack(), problems);
  EXPECT_TRUE(problems.empty()) << problems.front();
  std::vector<std::string> fired;
  for (const SoundGroup& g : soundGroups()) {
    if (g.like != g.name || g.name == kSilentSoundGroup) continue;
    for (std::string_view action : {"break", "place", "step", "hit", "fall"})
      fired.push_back("block." + std::string(g.name) + "." + std::string(action));
  }
  for (std::size_t i = 0; i < defaultBlocks().blockCount(); ++i) {
    const std::string_view kind = openSoundKind(defaultBlocks().block(i).name);
    if (kind.empty()) continue;
    fired.push_back("block." + std::string(kind) + ".open");
    fired.push_back("block." + std::string(kind) + ".close");
  }
  for (std::string_view e : kAmbienceEvents) fired.emplace_back(e);
  fired.emplace_back(MusicTimer::kDay);
  fired.emplace_back(MusicTimer::kNight);
  for (const std::string& e : fired) {
    const auto pick = events.pick(e, 12345);
    EXPECT_TRUE(pick) << e;
    if (pick) {
      EXPECT_TRUE(std::filesystem::exists(resourcePackDir() / "default" / pick->file)) << pick->file;
    }
  }
  EXPECT_GT(fired.size(), 90u);
}

TEST(DefaultPackSounds, EveryFileDecodesToSound) {
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(resourcePackDir() / "default" /
                                                                         "assets" / "minecraft" / "sounds")) {
    if (entry.path().extension() != ".ogg") continue;
    ++files;
    const Pcm pcm = decodeOgg(bytesOf(entry.path()), entry.path().string());
    ASSERT_GT(pcm.frames(), 1000u) << entry.path();
    double sum = 0.0;
    int peak = 0;
    for (std::int16_t s : pcm.samples) {
      sum += static_cast<double>(s) * s;
      peak = std::max(peak, std::abs(static_cast<int>(s)));
    }
    const double level = std::sqrt(sum / static_cast<double>(pcm.samples.size())) / 32768.0;
    EXPECT_GT(level, 0.01) << entry.path() << " is all but silent";
    EXPECT_LT(peak, 32767) << entry.path() << " clips";
  }
  EXPECT_GE(files, 100);
}

// resourcepacks/default's sounds are what tools/soundgen makes: the same events, the same files, each
// as long as the generator makes it (the bytes may differ where the encoder's float sums do).
TEST(DefaultPackSounds, MatchTheGenerator) {
  soundgen::Catalogue made;
  soundgen::blockSounds(made);
  soundgen::worldSounds(made);
  soundgen::music(made);
  const std::filesystem::path root = resourcePackDir() / "default" / "assets" / "minecraft";
  EXPECT_EQ(made.events, nlohmann::json::parse(readTextFile(root / "sounds.json")))
      << "run build/terrasol-soundgen resourcepacks/default";
  std::set<std::string> committed;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root / "sounds"))
    if (entry.path().extension() == ".ogg")
      committed.insert(std::filesystem::relative(entry.path(), root / "sounds").replace_extension().string());
  std::set<std::string> names;
  for (const soundgen::SoundFile& f : made.files) {
    names.insert(f.name);
    const Pcm pcm = decodeOgg(bytesOf(root / "sounds" / (f.name + ".ogg")), f.name);
    EXPECT_EQ(pcm.frames(), f.samples.size() / static_cast<std::size_t>(f.channels)) << f.name;
  }
  EXPECT_EQ(names, committed);
}

// A sound to the listener's right is louder on the right; one past its reach plays nothing; nothing
// playing is silence.
TEST(AudioEngine, PositionalSoundsArePannedAndFadeWithDistance) {
  AudioEngine engine(AudioOutput::Loopback);
  std::vector<std::string> problems;
  engine.setPacks(defaultPack(), problems);
  engine.setListener({0, 64, 0}, {0, 0, -1}, {0, 1, 0});  // looking north: east (+x) is on the right
  std::vector<std::int16_t> out(44100);                   // half a second of stereo
  engine.render(out);
  EXPECT_LT(rms(out).left + rms(out).right, 2.0);  // OpenAL Soft dithers its 16-bit output: ±1 at most

  auto heard = [&](glm::vec3 at) {
    SoundPlay s;
    s.event = "block.stone.break";
    s.at = at;
    EXPECT_TRUE(engine.play(s, 1));
    engine.render(out);
    engine.update();
    std::vector<std::int16_t> rest(44100 * 2);
    engine.render(rest);  // let it end
    engine.update();
    return rms(out);
  };
  const Levels right = heard({4, 64, 0}), left = heard({-4, 64, 0}), far = heard({0, 64, -12});
  EXPECT_GT(right.right, 1.5 * right.left);
  EXPECT_GT(left.left, 1.5 * left.right);
  const Levels near = heard({0, 64, -2});
  EXPECT_GT(near.left + near.right, 2.0 * (far.left + far.right));  // 1 - 2/16 against 1 - 12/16
  EXPECT_EQ(engine.stats().playing, 0);

  SoundPlay beyond;
  beyond.event = "block.stone.break";
  beyond.at = {0, 64, -20};  // past the 16-block reach
  EXPECT_FALSE(engine.play(beyond, 1));
  SoundPlay unknown;
  unknown.event = "block.no_such.break";
  EXPECT_FALSE(engine.play(unknown, 1));
  unknown.fallback = "block.stone.break";
  unknown.at = {0, 64, -1};
  EXPECT_TRUE(engine.play(unknown, 1));
}

TEST(AudioEngine, VolumesAndTheVoiceLimit) {
  AudioEngine engine(AudioOutput::Loopback, 8);
  std::vector<std::string> problems;
  engine.setPacks(defaultPack(), problems);
  engine.setListener({0, 0, 0}, {0, 0, -1}, {0, 1, 0});
  SoundPlay s;
  s.event = "block.metal.break";
  for (int i = 0; i < 12; ++i) {
    s.at = {0, 0, -static_cast<float>(i)};
    engine.play(s, static_cast<std::uint32_t>(i));
  }
  EXPECT_EQ(engine.stats().playing, 8);
  EXPECT_EQ(engine.stats().dropped, 4);  // the farthest, quietest ones
  std::vector<std::int16_t> out(4410);
  AudioVolumes volumes;
  volumes.blocks = 0.0f;
  engine.setVolumes(volumes);
  engine.render(out);
  EXPECT_LT(rms(out).left, 1.0);  // blocks at 0: dither alone
  EXPECT_FALSE(engine.play(s, 1));
}

// Under water the blocks' and ambience's sounds lose their highs (EFX's low-pass); music keeps them.
TEST(AudioEngine, UnderWaterSoundsAreMuffled) {
  AudioEngine engine(AudioOutput::Loopback);
  std::vector<std::string> problems;
  engine.setPacks(defaultPack(), problems);
  // How bright: the energy of the sample-to-sample change against the energy, over a glass break.
  auto brightness = [&](bool underwater) {
    engine.setUnderwater(underwater);
    SoundPlay glass;
    glass.event = "block.glass.break";
    glass.positional = false;
    EXPECT_TRUE(engine.play(glass, 3));
    std::vector<std::int16_t> out(44100);
    engine.render(out);
    engine.update();
    double change = 0.0, level = 0.0;
    for (std::size_t i = 2; i < out.size(); i += 2) {
      change += std::pow(static_cast<double>(out[i]) - out[i - 2], 2.0);
      level += std::pow(static_cast<double>(out[i]), 2.0);
    }
    std::vector<std::int16_t> rest(44100 * 2);
    engine.render(rest);
    engine.update();
    return change / std::max(level, 1.0);
  };
  const double dry = brightness(false), wet = brightness(true);
  EXPECT_LT(wet, 0.6 * dry) << dry << " in the air, " << wet << " under water";
}

// A pack whose sounds.json replaces block.stone.break changes what breaking stone plays.
TEST(AudioEngine, APackReplacesAnEvent) {
  testing::PackBuilder pack("sound_replace_pack");
  const auto glass = bytesOf(resourcePackDir() / "default/assets/minecraft/sounds/dig/glass1.ogg");
  pack.asset("sounds/custom/crash.ogg", std::string(glass.begin(), glass.end()));
  pack.asset("sounds.json", R"({"block.stone.break": {"replace": true, "sounds": ["custom/crash"]}})");
  AudioEngine engine(AudioOutput::Loopback);
  std::vector<std::string> problems;
  engine.setPacks(testing::stackOf({resourcePackDir() / "default", pack.dir()}), problems);
  EXPECT_TRUE(problems.empty());
  SoundPlay s;
  s.event = "block.stone.break";
  s.positional = false;
  for (std::uint32_t r = 0; r < 20; ++r)
    EXPECT_EQ(engine.play(s, r), "assets/minecraft/sounds/custom/crash.ogg");
  s.event = "block.stone.step";  // untouched events keep the default pack's
  EXPECT_NE(engine.play(s, 0)->find("step/stone"), std::string::npos);
}

// An event carries as far as its attenuation_distance says (16 blocks when it says nothing), and a
// volume over 1 carries farther in proportion, as in Minecraft.
TEST(AudioEngine, AnEventsReachIsItsAttenuationDistance) {
  testing::PackBuilder pack("sound_reach_pack");
  pack.asset("sounds.json", R"({
    "block.stone.break": {"replace": true, "sounds": [{"name": "dig/stone1", "attenuation_distance": 4}]},
    "block.wood.break": {"replace": true, "sounds": [{"name": "dig/wood1", "volume": 2}]}})");
  AudioEngine engine(AudioOutput::Loopback);
  std::vector<std::string> problems;
  engine.setPacks(testing::stackOf({resourcePackDir() / "default", pack.dir()}), problems);
  ASSERT_TRUE(problems.empty()) << problems.front();
  engine.setListener({0, 0, 0}, {0, 0, -1}, {0, 1, 0});
  auto plays = [&](const char* event, float distance) {
    SoundPlay s;
    s.event = event;
    s.at = {0, 0, -distance};
    return engine.play(s, 0).has_value();
  };
  EXPECT_TRUE(plays("block.stone.break", 3.5f));
  EXPECT_FALSE(plays("block.stone.break", 4.5f));
  EXPECT_TRUE(plays("block.gravel.break", 15.5f));
  EXPECT_FALSE(plays("block.gravel.break", 16.5f));
  EXPECT_TRUE(plays("block.wood.break", 31.5f));  // volume 2: twice the reach
  EXPECT_FALSE(plays("block.wood.break", 32.5f));
}

// A missing file is reported once with its name and plays nothing; the rest still plays.
TEST(AudioEngine, AMissingFileIsReportedAndSilent) {
  testing::PackBuilder pack("sound_missing_pack");
  pack.asset("sounds.json", R"({"block.stone.break": {"replace": true, "sounds": ["custom/absent"]}})");
  AudioEngine engine(AudioOutput::Loopback);
  std::vector<std::string> problems;
  engine.setPacks(testing::stackOf({resourcePackDir() / "default", pack.dir()}), problems);
  SoundPlay s;
  s.event = "block.stone.break";
  s.positional = false;
  EXPECT_FALSE(engine.play(s, 0));
  EXPECT_FALSE(engine.play(s, 0));
  const std::vector<std::string> said = engine.takeProblems();
  ASSERT_EQ(said.size(), 1u);
  EXPECT_NE(said[0].find("sounds/custom/absent.ogg"), std::string::npos) << said[0];
  s.event = "block.wood.break";
  EXPECT_TRUE(engine.play(s, 0));
}

// Music streams through small buffers and plays to its end, in step with what is rendered.
TEST(AudioEngine, MusicStreamsToItsEnd) {
  AudioEngine engine(AudioOutput::Loopback);
  std::vector<std::string> problems;
  engine.setPacks(defaultPack(), problems);
  ASSERT_EQ(engine.playMusic(MusicTimer::kDay, 0), "assets/minecraft/sounds/music/game/meadow.ogg");
  std::vector<std::int16_t> second(44100 * 2);
  double quiet = 0.0;
  int seconds = 0;
  for (; seconds < 200 && engine.musicPlaying(); ++seconds) {
    for (int i = 0; i < 20; ++i) {  // 20 frames a second, each with its update
      engine.render(std::span(second).subspan(static_cast<std::size_t>(i) * 4410, 4410));
      engine.update();
    }
    if (seconds > 3 && seconds < 80 && rms(second).left < 50.0) quiet += 1.0;
  }
  EXPECT_GT(seconds, 85);  // the track is about a minute and a half
  EXPECT_LT(seconds, 110);
  EXPECT_EQ(quiet, 0.0);  // no second in its middle without sound: no gaps
}

}  // namespace
}  // namespace terrasol
