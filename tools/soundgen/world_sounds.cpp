// The world's sounds: doors, trapdoors and gates; water and lava; caves; wind; under water.

#include <cmath>
#include <numbers>

#include "soundgen.h"

namespace terrasol::soundgen {
namespace {

constexpr int kRate = kEffectRate;

int samples(float seconds) {
  return static_cast<int>(seconds * kRate);
}

// A hinge's creak: a train of stick-slip pulses whose rate wanders, through a wooden or metal body.
Wave creak(float seconds, float fromHz, float toHz, float bodyHz, float q, Rng& r) {
  Wave pulses(static_cast<std::size_t>(samples(seconds)), 0.0f);
  float t = 0.0f;
  while (t < seconds) {
    const float k = t / seconds;
    const float rate = fromHz + (toHz - fromHz) * k + r.range(-8.0f, 8.0f);
    const auto i = static_cast<std::size_t>(t * kRate);
    if (i < pulses.size()) pulses[i] += r.range(0.6f, 1.0f) * std::sin(std::numbers::pi_v<float> * k);
    t += 1.0f / std::max(rate, 20.0f);
  }
  Wave w = filtered(pulses, Filter::BandPass, bodyHz, q, kRate);
  add(w, filtered(pulses, Filter::BandPass, bodyHz * 2.1f, q, kRate), 0.5f, 0, kRate);
  return w;
}

Wave knock(float hz, float decay, Rng& r) {
  Wave w(static_cast<std::size_t>(samples(decay * 6)), 0.0f);
  strike(w, {{hz, decay, 1.0f}, {hz * 2.4f, decay * 0.6f, 0.5f}, {hz * 4.1f, decay * 0.3f, 0.25f}}, 0, kRate);
  Wave n = filtered(noise(samples(0.05f), r), Filter::BandPass, hz * 4, 1.0f, kRate);
  envelope(n, 0.0005f, 0.01f, kRate);
  add(w, n, 0.4f, 0, kRate);
  return w;
}

Wave finished(Wave w, float peak) {
  fadeEnds(w, 0.004f, kRate);
  normalise(w, peak);
  return w;
}

void doors(Catalogue& c) {
  std::vector<std::string> woodOpen, woodClose, ironOpen, ironClose;
  for (int v = 1; v <= 2; ++v) {
    Rng r(100 + static_cast<std::uint64_t>(v));
    Wave open = creak(0.45f, r.range(60, 80), r.range(120, 150), r.range(700, 900), 6.0f, r);
    normalise(open, 1.0f);  // the hinge is the sound; the knock only ends it
    add(open, knock(r.range(160, 200), 0.05f, r), 0.5f, 0.42f, kRate);
    woodOpen.push_back("block/door/wood_open" + std::to_string(v));
    c.files.push_back({woodOpen.back(), finished(open, 0.8f)});
    Wave close = knock(r.range(140, 180), 0.07f, r);
    add(close, knock(r.range(900, 1100), 0.015f, r), 0.4f, 0.06f, kRate);  // the latch
    woodClose.push_back("block/door/wood_close" + std::to_string(v));
    c.files.push_back({woodClose.back(), finished(close, 0.9f)});

    Wave ironO = creak(0.5f, r.range(90, 110), r.range(150, 190), r.range(1400, 1800), 10.0f, r);
    normalise(ironO, 1.0f);
    Wave clang(static_cast<std::size_t>(samples(0.6f)), 0.0f);
    strike(clang, {{r.range(300, 340), 0.2f, 1.0f}, {830, 0.12f, 0.5f}, {1650, 0.08f, 0.3f}}, 0, kRate);
    add(ironO, clang, 0.5f, 0.45f, kRate);
    ironOpen.push_back("block/door/iron_open" + std::to_string(v));
    c.files.push_back({ironOpen.back(), finished(ironO, 0.8f)});
    Wave ironC(static_cast<std::size_t>(samples(0.7f)), 0.0f);
    strike(ironC,
           {{r.range(260, 300), 0.25f, 1.0f}, {740, 0.15f, 0.6f}, {1520, 0.1f, 0.35f}, {2900, 0.05f, 0.2f}},
           0, kRate);
    ironClose.push_back("block/door/iron_close" + std::to_string(v));
    c.files.push_back({ironClose.back(), finished(ironC, 0.9f)});
  }
  // Trapdoors and gates are the doors' sounds, lighter and higher; copper a brighter iron.
  c.event("block.wooden_door.open", woodOpen);
  c.event("block.wooden_door.close", woodClose);
  c.event("block.wooden_trapdoor.open", woodOpen, 0.9f, 1.15f);
  c.event("block.wooden_trapdoor.close", woodClose, 0.9f, 1.15f);
  c.event("block.fence_gate.open", woodOpen, 0.9f, 1.3f);
  c.event("block.fence_gate.close", woodClose, 0.9f, 1.3f);
  c.event("block.iron_door.open", ironOpen);
  c.event("block.iron_door.close", ironClose);
  c.event("block.iron_trapdoor.open", ironOpen, 0.9f, 1.15f);
  c.event("block.iron_trapdoor.close", ironClose, 0.9f, 1.15f);
  c.event("block.copper_door.open", ironOpen, 1.0f, 1.2f);
  c.event("block.copper_door.close", ironClose, 1.0f, 1.2f);
  c.event("block.copper_trapdoor.open", ironOpen, 0.9f, 1.35f);
  c.event("block.copper_trapdoor.close", ironClose, 0.9f, 1.35f);
}

void fluids(Catalogue& c) {
  std::vector<std::string> water, pop, lava;
  for (int v = 1; v <= 3; ++v) {
    Rng r(200 + static_cast<std::uint64_t>(v));
    // A brook: bubbles over a soft wash.
    Wave w = filtered(noise(samples(2.5f), r), Filter::BandPass, 600, 0.5f, kRate);
    for (float& s : w) s *= 0.15f;
    for (int b = 0; b < 40; ++b)
      bubble(w, r.range(0.0f, 2.3f), r.range(300, 900), r.range(0.02f, 0.06f), r.range(0.2f, 0.6f), kRate);
    fadeEnds(w, 0.3f, kRate);
    water.push_back("liquid/water" + std::to_string(v));
    c.files.push_back({water.back(), finished(std::move(w), 0.7f)});

    Wave p(static_cast<std::size_t>(samples(0.25f)), 0.0f);
    bubble(p, 0.0f, r.range(120, 180), 0.06f, 1.0f, kRate);
    Wave click = filtered(noise(samples(0.03f), r), Filter::HighPass, 2000, 0.7f, kRate);
    envelope(click, 0.0005f, 0.006f, kRate);
    add(p, click, 0.5f, 0.05f, kRate);
    pop.push_back("liquid/lavapop" + std::to_string(v));
    c.files.push_back({pop.back(), finished(std::move(p), 0.8f)});

    // Lava's murmur: slow, thick bubbling under a low roar.
    Wave l = filtered(noise(samples(2.0f), r), Filter::LowPass, 250, 0.7f, kRate);
    for (int b = 0; b < 12; ++b)
      bubble(l, r.range(0.0f, 1.8f), r.range(60, 140), r.range(0.08f, 0.15f), r.range(1.0f, 2.0f), kRate);
    fadeEnds(l, 0.3f, kRate);
    lava.push_back("liquid/lava" + std::to_string(v));
    c.files.push_back({lava.back(), finished(std::move(l), 0.7f)});
  }
  c.event("block.water.ambient", water);
  c.event("block.lava.pop", pop);
  c.event("block.lava.ambient", lava);
}

// Caves: a low swell and a distant, hollow moan.
void caves(Catalogue& c) {
  std::vector<std::string> names;
  for (int v = 1; v <= 3; ++v) {
    Rng r(300 + static_cast<std::uint64_t>(v));
    const float seconds = r.range(5.0f, 7.0f);
    Wave w = swept(noise(samples(seconds), r), r.range(150, 250), r.range(400, 700), 8.0f, kRate);
    Wave drone(w.size(), 0.0f);
    strike(drone, {{r.range(55, 75), seconds * 0.5f, 0.08f}, {r.range(80, 110), seconds * 0.4f, 0.05f}}, 0,
           kRate);
    add(w, drone, 1.0f, 0, kRate);
    for (std::size_t i = 0; i < w.size(); ++i) {
      const float k = static_cast<float>(i) / static_cast<float>(w.size());
      w[i] *= std::sin(std::numbers::pi_v<float> * k);  // swells and fades
    }
    w = reverb(w, 2.5f, 0.6f, kRate);
    names.push_back("ambient/cave/cave" + std::to_string(v));
    c.files.push_back({names.back(), finished(std::move(w), 0.7f)});
  }
  c.event("ambient.cave", names, 0.8f);
}

// Wind: low noise in gusts, a seamless loop.
void wind(Catalogue& c) {
  Rng r(400);
  const float seconds = 12.0f;
  Wave w = filtered(noise(samples(seconds + 1.0f), r), Filter::LowPass, 500, 0.7f, kRate);
  Wave whistle = swept(noise(samples(seconds + 1.0f), r), 700, 400, 6.0f, kRate);
  add(w, whistle, 0.3f, 0, kRate);
  for (std::size_t i = 0; i < w.size(); ++i) {
    const float t = static_cast<float>(i) / kRate;
    w[i] *= 0.55f + 0.3f * std::sin(t * 0.9f) + 0.15f * std::sin(t * 2.3f + 1.0f);  // gusts
  }
  makeLoop(w, 1.0f, kRate);
  c.files.push_back({"ambient/weather/wind", finished(std::move(w), 0.6f)});
  c.event("ambient.wind", {"ambient/weather/wind"});
}

// Under water: a muffled rumble with bubbles (looped), a plunge and a surfacing.
void underwater(Catalogue& c) {
  Rng r(500);
  Wave loop = filtered(noise(samples(9.0f), r), Filter::LowPass, 180, 0.7f, kRate);
  for (int b = 0; b < 25; ++b)
    bubble(loop, r.range(0.0f, 8.8f), r.range(200, 500), r.range(0.03f, 0.07f), r.range(0.05f, 0.15f), kRate);
  makeLoop(loop, 1.0f, kRate);
  c.files.push_back({"ambient/underwater/loop", finished(std::move(loop), 0.5f)});
  c.event("ambient.underwater.loop", {"ambient/underwater/loop"});

  Wave enter = swept(noise(samples(0.9f), r), 3000, 300, 1.5f, kRate);
  envelope(enter, 0.01f, 0.2f, kRate);
  for (int b = 0; b < 20; ++b)
    bubble(enter, r.range(0.1f, 0.7f), r.range(300, 800), r.range(0.02f, 0.05f), 0.3f, kRate);
  c.files.push_back({"ambient/underwater/enter", finished(std::move(enter), 0.8f)});
  c.event("ambient.underwater.enter", {"ambient/underwater/enter"});

  Wave exit = swept(noise(samples(0.6f), r), 500, 2500, 1.5f, kRate);
  envelope(exit, 0.02f, 0.12f, kRate);
  c.files.push_back({"ambient/underwater/exit", finished(std::move(exit), 0.7f)});
  c.event("ambient.underwater.exit", {"ambient/underwater/exit"});
}

}  // namespace

void worldSounds(Catalogue& c) {
  doors(c);
  fluids(c);
  caves(c);
  wind(c);
  underwater(c);
}

}  // namespace terrasol::soundgen
