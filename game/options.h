#pragma once
// Command line of the `terrasol` executable.

#include <cstdint>
#include <filesystem>
#include <glm/vec2.hpp>
#include <optional>
#include <string>
#include <vector>

#include "world/coords.h"

namespace terrasol {

// Where the game keeps its worlds (relative to the current directory), and the one it opens by default.
inline constexpr const char* kWorldsDir = "worlds";
inline constexpr const char* kDefaultWorldName = "world";

struct GameOptions {
  std::filesystem::path world;               // the save directory (created when missing)
  std::optional<std::uint64_t> seed;         // a new world's seed (default: from the clock)
  std::vector<std::filesystem::path> packs;  // stacked over the default pack, bottom first (this run)
  std::filesystem::path shaderpack;     // a shader pack drawing instead of Terrasol's pipeline (this run)
  std::filesystem::path settings;       // the settings file
  std::optional<int> frames;            // quit after this many frames (smoke tests)
  std::filesystem::path inputScript;    // replay these events (a fixed time step)
  std::optional<double> benchmark;      // seconds of the benchmark flight
  std::filesystem::path benchmarkPath;  // a scene file whose camera path is flown instead of the circle
  std::filesystem::path benchmarkJson;  // per-frame times and per-pass ms go here
  std::filesystem::path report;         // JSON at exit: player, edits, probes
  std::vector<BlockPos> probes;         // blocks whose block and light go into the report
  glm::ivec2 size{1280, 720};           // window size
  std::filesystem::path demoDir;        // where the headless demo goes when there is no display
  std::filesystem::path screenshot;     // with --frames: the last frame is saved here
  std::filesystem::path audioOut;       // play into this .wav instead of the speakers, in step with frames
  std::filesystem::path soundLog;       // every sound the game asks for, a JSON object per line
  bool demo = false;                    // fly the built-in demo path instead of playing
  bool help = false;
};

// Throws Error naming the bad argument.
GameOptions parseGameOptions(const std::vector<std::string>& args);
std::string gameUsage();

}  // namespace terrasol
