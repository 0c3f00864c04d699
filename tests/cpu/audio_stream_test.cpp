// Music with speakers: it streams on a thread of its own, so a main thread busy for seconds leaves
// no gap, and a first play's file is decoded in the background. OpenAL Soft's "wave" backend stands
// in for the speakers: it mixes in real time on its own thread into a .wav.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>

#include "audio/audio_engine.h"
#include "audio/wav_file.h"
#include "core/paths.h"
#include "music_timer.h"
#include "support/audio_levels.h"
#include "support/pack_builder.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

// With speakers the music streams on a thread of its own: a main thread busy for 2.5 s (loading
// chunks) leaves no gap. OpenAL Soft's "wave" backend stands in for the speakers: it mixes in real
// time on its own thread into a .wav. It is chosen by a config file read once per process, so this
// test has a binary of its own: OpenAL Soft starts with the wave backend in every run of it.
TEST(AudioEngine, MusicPlaysOnWhileTheMainThreadStalls) {
  const std::filesystem::path dir = testing::testOutputDir() / "wave_backend";
  std::filesystem::create_directories(dir);
  const std::filesystem::path conf = dir / "alsoft.conf", out = dir / "music.wav";
  std::filesystem::remove(out);
  std::ofstream(conf) << "[general]\ndrivers = wave\nsample-type = int16\nchannels = stereo\n[wave]\nfile = "
                      << out.string() << "\n";
  setenv("ALSOFT_CONF", conf.c_str(), 1);
  auto engine = std::make_unique<AudioEngine>(AudioOutput::Speakers);
  ASSERT_TRUE(std::filesystem::exists(out)) << "OpenAL Soft did not open its wave backend";
  std::vector<std::string> problems;
  engine->setPacks(testing::stackOf({resourcePackDir() / "default"}), problems);
  ASSERT_TRUE(engine->playMusic(MusicTimer::kDay, 0));
  // With speakers a file is decoded in the background: the sound is promised at once and starts at
  // the first update after its file is ready.
  SoundPlay step;
  step.event = "block.gravel.break";
  step.positional = false;
  EXPECT_TRUE(engine->play(step, 0));
  EXPECT_EQ(engine->stats().playing, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));  // no update(): the main thread is busy
  int started = 0;
  for (int i = 0; i < 25; ++i) {
    engine->update();
    started = std::max(started, engine->stats().playing);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_EQ(started, 1);
  EXPECT_TRUE(engine->musicPlaying());
  EXPECT_EQ(engine->stats().musicUnderruns, 0);
  engine.reset();  // closes the file
  const Pcm wav = readWav(out);
  ASSERT_GT(wav.frames(), static_cast<std::size_t>(wav.rate) * 5 / 2);  // the stall and the updates after
  // Every quarter second after the first heard (the track's first notes) and before the end.
  const std::size_t quarter = static_cast<std::size_t>(wav.rate / 4);
  std::size_t first = 0;
  while (first < wav.frames() && std::abs(wav.samples[first * 2]) < 20) ++first;
  for (std::size_t at = first + quarter; at + 2 * quarter < wav.frames(); at += quarter) {
    EXPECT_GT(testing::levels(wav, at, 0.25).left, 20.0)
        << "a gap at " << static_cast<double>(at) / wav.rate << " s";
  }
}

}  // namespace
}  // namespace terrasol
