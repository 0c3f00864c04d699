// Audio benchmarks: the main thread's share of a frame with 64 sounds playing (following the
// listener, freeing finished voices, a new sound every few frames), and the mixer's share, which
// with speakers runs on OpenAL Soft's own thread.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "audio/audio_engine.h"
#include "core/paths.h"

namespace terrasol {
namespace {

constexpr int kPlaying = 64;

// An engine on a loopback device with the default pack and `kPlaying` long sounds round the listener.
std::unique_ptr<AudioEngine> busyEngine() {
  auto owned = std::make_unique<AudioEngine>(AudioOutput::Loopback);
  AudioEngine& engine = *owned;
  PackStack packs;
  packs.push(ResourcePack::open(resourcePackDir() / "default"));
  std::vector<std::string> problems;
  engine.setPacks(packs, problems);
  engine.setListener({0.0f, 65.6f, 0.0f}, {0.0f, 0.0f, -1.0f}, {0.0f, 1.0f, 0.0f});
  for (int i = 0; i < kPlaying; ++i) {
    SoundPlay s;
    s.event = "ambient.cave";  // 5 to 9 s long: they play through the benchmark's frames
    s.category = SoundCategory::Ambient;
    const float a = static_cast<float>(i) * 0.1f;
    s.at = {std::cos(a) * 8.0f, 64.0f, std::sin(a) * 8.0f};
    engine.play(s, static_cast<std::uint32_t>(i));
  }
  return owned;
}

// What the game's frame asks of the engine: the listener moved and update(), with the 64 sounds
// playing; arg 1 adds a step every 8 frames, and since a loopback device mixes only when asked,
// nothing ends: the steps pile up until all 247 voices are busy and each new one takes the quietest's.
void BM_AudioMainThreadFrame(benchmark::State& state) {
  const bool steps = state.range(0) != 0;
  const std::unique_ptr<AudioEngine> owned = busyEngine();
  AudioEngine& engine = *owned;
  int frame = 0;
  for (auto _ : state) {
    const float t = static_cast<float>(frame) / 60.0f;
    engine.setListener({std::sin(t), 65.6f, std::cos(t)}, {std::cos(t), 0.0f, -std::sin(t)}, {0, 1, 0});
    if (steps && frame % 8 == 0) {
      SoundPlay step;
      step.event = "block.stone.step";
      step.at = {std::sin(t), 64.0f, std::cos(t)};
      step.volume = 0.15f;
      engine.play(step, static_cast<std::uint32_t>(frame));
    }
    engine.update();
    ++frame;
  }
  state.counters["playing"] = engine.stats().playing;
}
BENCHMARK(BM_AudioMainThreadFrame)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// The mixer: a 60 Hz frame's worth of 44.1 kHz stereo from the 64 voices.
void BM_AudioMixFrame(benchmark::State& state) {
  const std::unique_ptr<AudioEngine> owned = busyEngine();
  AudioEngine& engine = *owned;
  std::vector<std::int16_t> mix(2 * 735);
  for (auto _ : state) {
    engine.render(mix);
    benchmark::DoNotOptimize(mix.data());
  }
  state.counters["playing"] = engine.stats().playing;
}
BENCHMARK(BM_AudioMixFrame)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace terrasol
