// Music: quiet piano-like melodies over slow pads, made from a seed, as calm as a sandbox wants.
// A day track in C major pentatonic and a night track in A minor, each about a minute and a half,
// streamed (music.game and music.game.night).

#include <cmath>
#include <numbers>

#include "soundgen.h"

namespace terrasol::soundgen {
namespace {

constexpr int kRate = 32000;
constexpr float kTau = 2.0f * std::numbers::pi_v<float>;

float hz(int midi) {
  return 440.0f * std::pow(2.0f, static_cast<float>(midi - 69) / 12.0f);
}

// A struck string: harmonics that fade the faster the higher they are, slightly stretched.
void pianoNote(Wave& w, float at, int midi, float seconds, float amp) {
  const float f = hz(midi);
  const auto start = static_cast<std::size_t>(at * kRate);
  const auto n = static_cast<std::size_t>(seconds * kRate);
  for (int h = 1; h <= 6; ++h) {
    const float partial = f * static_cast<float>(h) * (1.0f + 0.0004f * static_cast<float>(h * h));
    if (partial > kRate * 0.45f) break;
    const float a = amp / std::pow(static_cast<float>(h), 1.6f);
    const float decay = seconds * 0.45f / static_cast<float>(h);
    for (std::size_t i = 0; i < n && start + i < w.size(); ++i) {
      const float t = static_cast<float>(i) / kRate;
      w[start + i] += a * std::exp(-t / decay) * std::min(1.0f, t / 0.004f) * std::sin(kTau * partial * t);
    }
  }
}

// A pad: the chord's notes as soft sines that swell in and out over the bar.
void padChord(Wave& w, float at, const std::vector<int>& notes, float seconds, float amp) {
  const auto start = static_cast<std::size_t>(at * kRate);
  const auto n = static_cast<std::size_t>(seconds * kRate);
  for (int midi : notes) {
    const float f = hz(midi);
    for (std::size_t i = 0; i < n && start + i < w.size(); ++i) {
      const float t = static_cast<float>(i) / kRate;
      const float k = static_cast<float>(i) / static_cast<float>(n);
      const float swell = std::sin(std::numbers::pi_v<float> * k);
      w[start + i] += amp * swell * swell * (std::sin(kTau * f * t) + 0.2f * std::sin(kTau * 2.0f * f * t));
    }
  }
}

struct Piece {
  const char* name;
  std::uint64_t seed;
  float bpm;
  std::vector<int> scale;                // melody notes, MIDI
  std::vector<std::vector<int>> chords;  // a chord a bar, looping
  int bars;
  float rest;  // chance a beat is silent
};

Wave compose(const Piece& p) {
  Rng r(p.seed);
  const float beat = 60.0f / p.bpm, bar = beat * 4.0f;
  const float seconds = bar * static_cast<float>(p.bars) + 4.0f;
  Wave w(static_cast<std::size_t>(seconds * kRate), 0.0f);
  int step = static_cast<int>(p.scale.size()) / 2;
  std::vector<int> phrase;  // the first phrase's steps, answered later
  for (int b = 0; b < p.bars; ++b) {
    const std::vector<int>& chord = p.chords[static_cast<std::size_t>(b) % p.chords.size()];
    padChord(w, bar * static_cast<float>(b), chord, bar * 1.1f, 0.035f);
    pianoNote(w, bar * static_cast<float>(b), chord[0] - 12, bar * 1.2f, 0.12f);  // the bass
    if (b < 2 || b >= p.bars - 1) continue;  // pads alone to begin and end
    for (int q = 0; q < 4; ++q) {
      const std::size_t beatIndex = static_cast<std::size_t>((b % 4) * 4 + q);
      if (r.unit() < p.rest) continue;
      // Every other four bars answer the first phrase, a step apart: tunes that recur.
      if (b % 8 >= 4 && beatIndex < phrase.size()) {
        step = std::clamp(phrase[beatIndex] + 1, 0, static_cast<int>(p.scale.size()) - 1);
      } else {
        step = std::clamp(step + static_cast<int>(r.range(-2.49f, 2.49f)), 0,
                          static_cast<int>(p.scale.size()) - 1);
        if (phrase.size() < 16) phrase.push_back(step);
      }
      const float at = bar * static_cast<float>(b) + beat * static_cast<float>(q) + r.range(0.0f, 0.02f);
      pianoNote(w, at, p.scale[static_cast<std::size_t>(step)], beat * 3.0f, r.range(0.16f, 0.24f));
      if (r.unit() < 0.25f)  // a grace note on the off-beat
        pianoNote(w, at + beat * 0.5f, p.scale[static_cast<std::size_t>(std::max(step - 1, 0))], beat * 2.0f,
                  0.1f);
    }
  }
  w = reverb(w, 2.2f, 0.35f, kRate);
  fadeEnds(w, 2.0f, kRate);
  normalise(w, 0.7f);
  return w;
}

const Piece kDay{"music/game/meadow",
                 11,
                 66.0f,
                 {60, 62, 64, 67, 69, 72, 74, 76, 79, 81},
                 {{48 + 12, 52 + 12, 55 + 12},
                  {45 + 12, 48 + 12, 52 + 12},
                  {41 + 12, 45 + 12, 48 + 12},
                  {43 + 12, 47 + 12, 50 + 12}},
                 24,
                 0.3f};
const Piece kNight{"music/game/nightfall",
                   23,
                   54.0f,
                   {57, 60, 62, 64, 67, 69, 72, 74, 76},
                   {{45 + 12, 48 + 12, 52 + 12},
                    {41 + 12, 45 + 12, 48 + 12},
                    {48 + 12, 52 + 12, 55 + 12},
                    {40 + 12, 43 + 12, 47 + 12}},
                   20,
                   0.45f};

}  // namespace

void music(Catalogue& c) {
  for (const Piece* p : {&kDay, &kNight}) c.files.push_back({p->name, compose(*p), 1, kRate, 0.1f});
  c.event("music.game", {kDay.name}, 1.0f, 1.0f, true);
  c.event("music.game.night", {kNight.name}, 1.0f, 1.0f, true);
}

}  // namespace terrasol::soundgen
