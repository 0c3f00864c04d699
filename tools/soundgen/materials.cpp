// Block sounds by material: a dig (breaking and placing) and a step (steps, hits, falls), each in
// four variants. Each material is a mix of the same parts in its own measure: a thump, a struck
// body's ring, grains, a rustle, a squelch.

#include <functional>

#include "soundgen.h"

namespace terrasol::soundgen {
namespace {

constexpr int kRate = kEffectRate;
constexpr int kVariants = 4;

int samples(float seconds) {
  return static_cast<int>(seconds * kRate);
}

// A burst of band-passed noise: an impact's body.
Wave burst(float seconds, float hz, float q, float attack, float decay, Rng& rng) {
  Wave w = filtered(noise(samples(seconds), rng), Filter::BandPass, hz, q, kRate);
  envelope(w, attack, decay, kRate);
  return w;
}

Wave thump(float seconds, float hz, float decay, Rng& rng) {
  Wave w(static_cast<std::size_t>(samples(seconds)), 0.0f);
  strike(w, {{hz * rng.range(0.9f, 1.1f), decay, 1.0f}, {hz * 2.3f, decay * 0.5f, 0.3f}}, 0.0f, kRate);
  return w;
}

Wave grainBed(float seconds, int count, float hz, float grain, Rng& rng) {
  Wave w(static_cast<std::size_t>(samples(seconds)), 0.0f);
  grains(w, count, 0.0f, seconds * 0.7f, grain, 1.0f, rng, kRate);
  w = filtered(w, Filter::BandPass, hz, 0.9f, kRate);
  envelope(w, 0.004f, seconds * 0.35f, kRate);
  return w;
}

Wave stoneDig(Rng& r) {
  Wave w = burst(0.35f, r.range(700, 1000), 0.9f, 0.001f, 0.05f, r);
  add(w, thump(0.3f, r.range(110, 150), 0.06f, r), 0.6f, 0, kRate);
  add(w, grainBed(0.35f, 14, 2600, 0.004f, r), 0.5f, 0.01f, kRate);
  return w;
}
Wave stoneStep(Rng& r) {
  Wave w = burst(0.16f, r.range(1200, 1700), 1.2f, 0.001f, 0.025f, r);
  add(w, thump(0.15f, r.range(130, 170), 0.03f, r), 0.5f, 0, kRate);
  return w;
}

// A struck body (wood's knock, metal's clang) and the click of the blow.
struct Click {
  float seconds, hz, q, decay, gain;
};
Wave knocked(float seconds, const std::vector<Mode>& modes, const Click& click, Rng& r) {
  Wave w(static_cast<std::size_t>(samples(seconds)), 0.0f);
  strike(w, modes, 0, kRate);
  add(w, burst(click.seconds, click.hz, click.q, 0.001f, click.decay, r), click.gain, 0, kRate);
  return w;
}

Wave woodDig(Rng& r) {
  const float f = r.range(180, 240);
  return knocked(
      0.4f, {{f, 0.09f, 1.0f}, {f * 2.31f, 0.06f, 0.6f}, {f * 3.9f, 0.04f, 0.35f}, {f * 5.4f, 0.025f, 0.2f}},
      {0.2f, r.range(500, 800), 1.0f, 0.03f, 0.5f}, r);
}
Wave woodStep(Rng& r) {
  const float f = r.range(150, 200);
  return knocked(0.2f, {{f, 0.05f, 1.0f}, {f * 2.4f, 0.03f, 0.5f}}, {0.1f, 900, 1.2f, 0.015f, 0.3f}, r);
}

Wave gravelDig(Rng& r) {
  Wave w = grainBed(0.45f, 70, r.range(2200, 3200), 0.006f, r);
  add(w, thump(0.3f, r.range(90, 120), 0.05f, r), 0.3f, 0, kRate);
  return w;
}
Wave gravelStep(Rng& r) {
  return grainBed(0.22f, 26, r.range(2500, 3500), 0.005f, r);
}

// Blades brushing: high noise in a few overlapping swishes.
Wave rustle(float seconds, int swishes, Rng& r) {
  Wave w(static_cast<std::size_t>(samples(seconds)), 0.0f);
  for (int i = 0; i < swishes; ++i) {
    Wave s = filtered(noise(samples(seconds * 0.5f), r), Filter::HighPass, r.range(1800, 3000), 0.7f, kRate);
    s = filtered(s, Filter::LowPass, 7000, 0.7f, kRate);
    envelope(s, seconds * 0.08f, seconds * 0.12f, kRate);
    add(w, s, r.range(0.5f, 1.0f), r.range(0.0f, seconds * 0.4f), kRate);
  }
  return w;
}
Wave grassDig(Rng& r) {
  return rustle(0.4f, 4, r);
}
Wave grassStep(Rng& r) {
  return rustle(0.22f, 2, r);
}

Wave sandDig(Rng& r) {
  Wave w(static_cast<std::size_t>(samples(0.45f)), 0.0f);
  grains(w, 400, 0.0f, 0.3f, 0.002f, 0.5f, r, kRate);
  w = filtered(w, Filter::LowPass, r.range(3000, 4000), 0.7f, kRate);
  envelope(w, 0.03f, 0.12f, kRate);
  return w;
}
Wave sandStep(Rng& r) {
  Wave w(static_cast<std::size_t>(samples(0.25f)), 0.0f);
  grains(w, 160, 0.0f, 0.15f, 0.002f, 0.5f, r, kRate);
  w = filtered(w, Filter::LowPass, r.range(3500, 4500), 0.7f, kRate);
  envelope(w, 0.02f, 0.06f, kRate);
  return w;
}

// Snow squeaks and crunches: dense grains through a narrow band that rises as it packs.
Wave snowy(float seconds, int count, Rng& r) {
  Wave w(static_cast<std::size_t>(samples(seconds)), 0.0f);
  grains(w, count, 0.0f, seconds * 0.6f, 0.003f, 1.0f, r, kRate);
  Wave squeak = swept(w, r.range(900, 1200), r.range(1600, 2200), 3.0f, kRate);
  w = filtered(w, Filter::LowPass, 2500, 0.7f, kRate);
  add(w, squeak, 0.8f, 0, kRate);
  envelope(w, 0.01f, seconds * 0.3f, kRate);
  return w;
}
Wave snowDig(Rng& r) {
  return snowy(0.4f, 90, r);
}
Wave snowStep(Rng& r) {
  return snowy(0.22f, 40, r);
}

// Glass rings high and shatters: many short pings over a bright burst.
Wave glassDig(Rng& r) {
  Wave w = burst(0.6f, 5000, 0.6f, 0.001f, 0.05f, r);
  for (int i = 0; i < 14; ++i) {
    Wave ping(static_cast<std::size_t>(samples(0.6f)), 0.0f);
    const float f = r.range(2500, 7500);
    strike(ping, {{f, r.range(0.05f, 0.2f), 1.0f}, {f * 1.53f, 0.05f, 0.4f}}, 0, kRate);
    add(w, ping, r.range(0.1f, 0.35f), r.range(0.0f, 0.25f), kRate);
  }
  return w;
}
Wave glassStep(Rng& r) {
  Wave w = stoneStep(r);
  Wave ping(static_cast<std::size_t>(samples(0.2f)), 0.0f);
  strike(ping, {{r.range(3000, 4000), 0.04f, 1.0f}}, 0, kRate);
  add(w, ping, 0.25f, 0, kRate);
  return w;
}

// Metal: an inharmonic clang that rings on.
Wave metalDig(Rng& r) {
  const float f = r.range(380, 480);
  return knocked(
      0.8f, {{f, 0.35f, 1.0f}, {f * 2.76f, 0.25f, 0.6f}, {f * 5.40f, 0.15f, 0.4f}, {f * 8.93f, 0.08f, 0.25f}},
      {0.1f, 2000, 1.0f, 0.015f, 0.5f}, r);
}
Wave metalStep(Rng& r) {
  const float f = r.range(600, 750);
  return knocked(0.3f, {{f, 0.09f, 1.0f}, {f * 2.76f, 0.06f, 0.5f}}, {0.08f, 1500, 1.0f, 0.01f, 0.5f}, r);
}

// Wool: a soft, muffled pat.
Wave woolDig(Rng& r) {
  Wave w = filtered(noise(samples(0.35f), r), Filter::LowPass, r.range(500, 700), 0.7f, kRate);
  envelope(w, 0.01f, 0.06f, kRate);
  return w;
}
Wave woolStep(Rng& r) {
  Wave w = filtered(noise(samples(0.2f), r), Filter::LowPass, r.range(350, 450), 0.7f, kRate);
  envelope(w, 0.008f, 0.035f, kRate);
  return w;
}

// Slime and mud squelch: a band sweeping through the low voice of wet noise.
Wave squelch(float seconds, float from, float to, Rng& r) {
  Wave w = swept(noise(samples(seconds), r), from, to, 4.0f, kRate);
  envelope(w, seconds * 0.1f, seconds * 0.25f, kRate);
  Wave body = filtered(noise(samples(seconds), r), Filter::LowPass, 300, 0.7f, kRate);
  envelope(body, 0.005f, seconds * 0.15f, kRate);
  add(w, body, 0.6f, 0, kRate);
  return w;
}
Wave slimeDig(Rng& r) {
  return squelch(0.4f, r.range(250, 350), r.range(900, 1200), r);
}
Wave slimeStep(Rng& r) {
  return squelch(0.22f, r.range(300, 400), r.range(800, 1000), r);
}
Wave mudDig(Rng& r) {
  return squelch(0.4f, r.range(150, 220), r.range(400, 550), r);
}
Wave mudStep(Rng& r) {
  return squelch(0.22f, r.range(160, 220), r.range(350, 450), r);
}

// Amethyst chimes: a bell's partials, bright and long.
Wave chime(float seconds, float decay, Rng& r) {
  Wave w(static_cast<std::size_t>(samples(seconds)), 0.0f);
  const float f = r.range(1100, 1500);
  strike(w,
         {{f, decay, 1.0f},
          {f * 1.58f, decay * 0.8f, 0.6f},
          {f * 2.24f, decay * 0.6f, 0.45f},
          {f * 3.1f, decay * 0.4f, 0.3f}},
         0, kRate);
  add(w, burst(0.05f, 6000, 1.0f, 0.001f, 0.006f, r), 0.3f, 0, kRate);
  return w;
}
Wave amethystDig(Rng& r) {
  return chime(0.9f, 0.3f, r);
}
Wave amethystStep(Rng& r) {
  return chime(0.4f, 0.1f, r);
}

// Netherrack crumbles: dull grains over a soft thump.
Wave netherrackDig(Rng& r) {
  Wave w = grainBed(0.4f, 50, r.range(1200, 1700), 0.007f, r);
  add(w, thump(0.3f, r.range(90, 120), 0.05f, r), 0.5f, 0, kRate);
  return w;
}
Wave netherrackStep(Rng& r) {
  return grainBed(0.2f, 18, r.range(1300, 1800), 0.006f, r);
}

struct Material {
  const char* name;  // the plain sound group
  std::function<Wave(Rng&)> dig, step;
};

const Material kMaterials[] = {
    {"stone", stoneDig, stoneStep},
    {"wood", woodDig, woodStep},
    {"gravel", gravelDig, gravelStep},
    {"grass", grassDig, grassStep},
    {"sand", sandDig, sandStep},
    {"snow", snowDig, snowStep},
    {"glass", glassDig, glassStep},
    {"metal", metalDig, metalStep},
    {"wool", woolDig, woolStep},
    {"slime_block", slimeDig, slimeStep},
    {"mud", mudDig, mudStep},
    {"amethyst_block", amethystDig, amethystStep},
    {"netherrack", netherrackDig, netherrackStep},
};

// The file names of one material's variants: "dig/stone1".."dig/stone4".
std::vector<std::string> variants(Catalogue& c, const std::string& folder, const std::string& material,
                                  const std::function<Wave(Rng&)>& make, std::uint64_t seed) {
  std::vector<std::string> names;
  for (int v = 1; v <= kVariants; ++v) {
    Rng rng(seed * 16 + static_cast<std::uint64_t>(v));
    Wave w = make(rng);
    fadeEnds(w, 0.004f, kRate);
    normalise(w, 0.9f);
    names.push_back(folder + "/" + material + std::to_string(v));
    c.files.push_back({names.back(), std::move(w)});
  }
  return names;
}

}  // namespace

void blockSounds(Catalogue& c) {
  std::uint64_t seed = 1;
  for (const Material& m : kMaterials) {
    const std::vector<std::string> dig = variants(c, "dig", m.name, m.dig, seed++);
    const std::vector<std::string> step = variants(c, "step", m.name, m.step, seed++);
    const std::string group = std::string("block.") + m.name;
    c.event(group + ".break", dig);
    c.event(group + ".place", dig);
    c.event(group + ".step", step);
    c.event(group + ".hit", step, 0.5f);
    c.event(group + ".fall", step);
  }
}

}  // namespace terrasol::soundgen
