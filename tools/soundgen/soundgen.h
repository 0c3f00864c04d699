#pragma once
// The default pack's sounds: every file Terrasol's events need, synthesised (block materials,
// doors, water, lava, caves, wind, under water, music), and the sounds.json naming them.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "synth.h"

namespace terrasol::soundgen {

struct SoundFile {
  std::string name;  // under assets/minecraft/sounds/, without ".ogg": "dig/stone1"
  Wave samples;      // interleaved when stereo
  int channels = 1, rate = 22050;
  float quality = 0.2f;  // Vorbis: ~45 kbit/s mono at 22 kHz
};

struct Catalogue {
  std::vector<SoundFile> files;
  nlohmann::json events = nlohmann::json::object();  // sounds.json

  // An event whose entries are `files` with the given volume and pitch.
  void event(const std::string& name, const std::vector<std::string>& files, float volume = 1.0f,
             float pitch = 1.0f, bool stream = false);
};

inline constexpr int kEffectRate = 22050;

// The five actions of each plain sound group (world/block_sounds.h).
void blockSounds(Catalogue& c);
// Doors, fluids, caves, wind and under water.
void worldSounds(Catalogue& c);
void music(Catalogue& c);

// Writes the files and sounds.json into the pack folder `pack` (its assets/minecraft/).
void writeSounds(const Catalogue& c, const std::filesystem::path& pack);

}  // namespace terrasol::soundgen
