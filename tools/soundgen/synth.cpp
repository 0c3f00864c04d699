#include "synth.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace terrasol::soundgen {
namespace {

constexpr float kTau = 2.0f * std::numbers::pi_v<float>;

struct Biquad {
  float b0 = 1, b1 = 0, b2 = 0, a1 = 0, a2 = 0, x1 = 0, x2 = 0, y1 = 0, y2 = 0;

  void set(Filter kind, float hz, float q, int rate) {
    const float w = kTau * std::clamp(hz, 10.0f, rate * 0.45f) / static_cast<float>(rate);
    const float c = std::cos(w), alpha = std::sin(w) / (2.0f * q);
    float n0 = 0, n1 = 0, n2 = 0;
    switch (kind) {
      case Filter::LowPass:
        n0 = n2 = (1 - c) / 2;
        n1 = 1 - c;
        break;
      case Filter::HighPass:
        n0 = n2 = (1 + c) / 2;
        n1 = -(1 + c);
        break;
      case Filter::BandPass:
        n0 = alpha;
        n2 = -alpha;
        break;
    }
    const float a0 = 1 + alpha;
    b0 = n0 / a0;
    b1 = n1 / a0;
    b2 = n2 / a0;
    a1 = -2 * c / a0;
    a2 = (1 - alpha) / a0;
  }
  float run(float x) {
    const float y = b0 * x + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
    x2 = x1;
    x1 = x;
    y2 = y1;
    y1 = y;
    return y;
  }
};

}  // namespace

std::uint64_t Rng::next() {
  s_ ^= s_ << 13;
  s_ ^= s_ >> 7;
  s_ ^= s_ << 17;
  return s_;
}

float Rng::unit() {
  return static_cast<float>(next() >> 40) / static_cast<float>(1ull << 24);
}

Wave filtered(const Wave& in, Filter kind, float hz, float q, int rate) {
  Biquad f;
  f.set(kind, hz, q, rate);
  Wave out(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) out[i] = f.run(in[i]);
  return out;
}

Wave swept(const Wave& in, float fromHz, float toHz, float q, int rate) {
  Biquad f;
  Wave out(in.size());
  constexpr std::size_t kStep = 32;  // coefficients move every 32 samples: smooth enough
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (i % kStep == 0) {
      const float t = static_cast<float>(i) / static_cast<float>(std::max<std::size_t>(in.size() - 1, 1));
      f.set(Filter::BandPass, fromHz * std::pow(toHz / fromHz, t), q, rate);
    }
    out[i] = f.run(in[i]);
  }
  return out;
}

Wave noise(int samples, Rng& rng) {
  Wave w(static_cast<std::size_t>(samples));
  for (float& s : w) s = rng.noise();
  return w;
}

void envelope(Wave& w, float attack, float decay, int rate) {
  for (std::size_t i = 0; i < w.size(); ++i) {
    const float t = static_cast<float>(i) / static_cast<float>(rate);
    const float rise = attack > 0 ? 1.0f - std::exp(-t / attack) : 1.0f;
    w[i] *= rise * std::exp(-t / decay);
  }
}

void strike(Wave& w, const std::vector<Mode>& modes, float at, int rate) {
  const auto start = static_cast<std::size_t>(at * static_cast<float>(rate));
  for (const Mode& m : modes) {
    for (std::size_t i = start; i < w.size(); ++i) {
      const float t = static_cast<float>(i - start) / static_cast<float>(rate);
      const float fall = std::exp(-t / m.decay);
      if (fall < 1e-4f) break;
      // A 2 ms rise: a struck body starts at once but never with a click.
      w[i] += m.amp * fall * std::min(1.0f, t / 0.002f) * std::sin(kTau * m.hz * t);
    }
  }
}

void grains(Wave& w, int count, float from, float to, float grainSeconds, float loudness, Rng& rng,
            int rate) {
  const int length = std::max(2, static_cast<int>(grainSeconds * static_cast<float>(rate)));
  for (int g = 0; g < count; ++g) {
    const auto start = static_cast<std::size_t>(rng.range(from, to) * static_cast<float>(rate));
    const float amp = loudness * rng.range(0.3f, 1.0f);
    for (int i = 0; i < length && start + static_cast<std::size_t>(i) < w.size(); ++i) {
      const float t = static_cast<float>(i) / static_cast<float>(length);
      w[start + static_cast<std::size_t>(i)] += amp * rng.noise() * (1.0f - t) * (1.0f - t);
    }
  }
}

void bubble(Wave& w, float at, float hz, float seconds, float amp, int rate) {
  const auto start = static_cast<std::size_t>(at * static_cast<float>(rate));
  float phase = 0.0f;
  const auto n = static_cast<std::size_t>(seconds * static_cast<float>(rate));
  for (std::size_t i = 0; i < n && start + i < w.size(); ++i) {
    const float t = static_cast<float>(i) / static_cast<float>(n);
    phase += kTau * hz * (1.0f + 1.5f * t) / static_cast<float>(rate);  // a bubble's pitch rises as it closes
    w[start + i] += amp * std::sin(phase) * std::sin(std::numbers::pi_v<float> * t);
  }
}

void add(Wave& to, const Wave& from, float gain, float at, int rate) {
  const auto start = static_cast<std::size_t>(std::max(0.0f, at) * static_cast<float>(rate));
  if (to.size() < start + from.size()) to.resize(start + from.size(), 0.0f);
  for (std::size_t i = 0; i < from.size(); ++i) to[start + i] += gain * from[i];
}

void normalise(Wave& w, float peak) {
  float most = 0.0f;
  for (float s : w) most = std::max(most, std::abs(s));
  if (most <= 0.0f) return;
  for (float& s : w) s *= peak / most;
}

void fadeEnds(Wave& w, float seconds, int rate) {
  const auto n = std::min(w.size() / 2, static_cast<std::size_t>(seconds * static_cast<float>(rate)));
  for (std::size_t i = 0; i < n; ++i) {
    const float g = static_cast<float>(i) / static_cast<float>(n);
    w[i] *= g;
    w[w.size() - 1 - i] *= g;
  }
}

void makeLoop(Wave& w, float seconds, int rate) {
  const auto n = std::min(w.size() / 2, static_cast<std::size_t>(seconds * static_cast<float>(rate)));
  const std::size_t tail = w.size() - n;
  for (std::size_t i = 0; i < n; ++i) {
    const float g =
        static_cast<float>(i) / static_cast<float>(n);  // equal power would bulge: noise is not coherent
    w[i] = w[i] * std::sqrt(g) + w[tail + i] * std::sqrt(1.0f - g);
  }
  w.resize(tail);
}

Wave reverb(const Wave& in, float seconds, float mix, int rate) {
  const float combMs[] = {29.7f, 37.1f, 41.1f, 43.7f}, allpassMs[] = {5.0f, 1.7f};
  Wave wet(in.size() + static_cast<std::size_t>(seconds * static_cast<float>(rate)), 0.0f);
  for (float ms : combMs) {
    const auto d = static_cast<std::size_t>(ms * 0.001f * static_cast<float>(rate));
    const float g = std::pow(0.001f, ms * 0.001f / seconds);  // -60 dB after `seconds`
    std::vector<float> line(d, 0.0f);
    for (std::size_t i = 0; i < wet.size(); ++i) {
      const float x = i < in.size() ? in[i] : 0.0f;
      const float y = line[i % d];
      line[i % d] = x + g * y;
      wet[i] += y * 0.25f;
    }
  }
  for (float ms : allpassMs) {
    const auto d = static_cast<std::size_t>(ms * 0.001f * static_cast<float>(rate));
    std::vector<float> line(d, 0.0f);
    for (std::size_t i = 0; i < wet.size(); ++i) {
      const float delayed = line[i % d];
      const float v = wet[i] + 0.7f * delayed;
      line[i % d] = v;
      wet[i] = delayed - 0.7f * v;
    }
  }
  Wave out(wet.size(), 0.0f);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = (i < in.size() ? in[i] : 0.0f) + mix * wet[i];
  return out;
}

}  // namespace terrasol::soundgen
