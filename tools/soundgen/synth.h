#pragma once
// The few building blocks the default pack's sounds are made of: noise, filters, envelopes,
// struck resonances and grains. Mono float samples in -1..1; deterministic for a seed.

#include <cstdint>
#include <vector>

namespace terrasol::soundgen {

using Wave = std::vector<float>;

// A small, fast generator with a fixed sequence per seed.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : s_(seed * 0x9E3779B97F4A7C15ull + 1) {}
  std::uint64_t next();
  float unit();  // 0..1
  float range(float lo, float hi) { return lo + (hi - lo) * unit(); }
  float noise() { return unit() * 2.0f - 1.0f; }

 private:
  std::uint64_t s_;
};

// RBJ's biquads, run over a whole wave.
enum class Filter { LowPass, HighPass, BandPass };
Wave filtered(const Wave& in, Filter kind, float hz, float q, int rate);
// A band-pass whose centre moves from `fromHz` to `toHz` over the wave (squelches, swishes).
Wave swept(const Wave& in, float fromHz, float toHz, float q, int rate);

Wave noise(int samples, Rng& rng);
// Rises over `attack` seconds, then falls by e every `decay` seconds.
void envelope(Wave& w, float attack, float decay, int rate);
// A struck body: damped sines at `hz` with their decays (s) and amplitudes, starting at `at`.
struct Mode {
  float hz, decay, amp;
};
void strike(Wave& w, const std::vector<Mode>& modes, float at, int rate);
// `count` short noise clicks (grains of gravel, sand, snow) spread over [from, to) seconds.
void grains(Wave& w, int count, float from, float to, float grainSeconds, float loudness, Rng& rng, int rate);
// A rising blip, as a bubble makes.
void bubble(Wave& w, float at, float hz, float seconds, float amp, int rate);

void add(Wave& to, const Wave& from, float gain, float at, int rate);
// Scaled so the loudest sample is `peak`.
void normalise(Wave& w, float peak);
// Fades its ends over `seconds` (no clicks where it starts and stops).
void fadeEnds(Wave& w, float seconds, int rate);
// Its end blended into its start over `seconds`, and that much shorter: a seamless loop.
void makeLoop(Wave& w, float seconds, int rate);
// A room's tail: Schroeder's four combs and two all-passes, `mix` of it added.
Wave reverb(const Wave& in, float seconds, float mix, int rate);

}  // namespace terrasol::soundgen
