#pragma once
// Command line of the `terrasol` executable.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace terrasol {

struct GameOptions {
  std::optional<int> frames;                 // quit after this many frames (smoke tests)
  glm::ivec2 size{1280, 720};                // window size
  std::filesystem::path demoDir;             // where the headless demo goes when there is no display
  std::filesystem::path screenshot;          // with --frames: the last frame is saved here
  bool help = false;
};

// Throws Error naming the bad argument.
GameOptions parseGameOptions(const std::vector<std::string>& args);
std::string gameUsage();

}  // namespace terrasol
