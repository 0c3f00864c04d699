#pragma once
// Running the game itself in tests: under Xvfb, in a fresh folder with small, quick settings.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/error.h"
#include "support/world_support.h"

namespace terrasol::testing {

// The game with `arguments`, in a virtual display; its exit code.
inline int runGame(const std::string& arguments) {
  const std::string command =
      std::string(TERRASOL_XVFB_RUN) + " -a -s '-screen 0 640x480x24' " + TERRASOL_GAME_EXE + " " + arguments;
  return std::system(command.c_str());
}

inline nlohmann::json readJson(const std::filesystem::path& file) {
  return nlohmann::json::parse(readTextFile(file));
}

// A fresh folder for one run of the game, with small, quick settings: 2 chunks of view, a small
// shadow map, and silent (master volume 0: tests on a machine with speakers make no sound) unless
// `sound` says otherwise; `more` adds settings (", \"key\": value"). `common` holds the arguments every
// run in it takes.
struct GameDir {
  explicit GameDir(const std::string& name, int shadowResolution = 512, int shadowDistance = 32,
                   const std::string& sound = R"({ "master": 0 })", const std::string& more = "")
      : dir(testOutputDir() / name), settings(dir / "settings.json") {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::ofstream(settings) << R"({ "view_distance": 2, "shadow": { "resolution": )" << shadowResolution
                            << R"(, "distance": )" << shadowDistance << R"( }, "sound": )" << sound << more
                            << " }";
    common = "--world " + (dir / "world").string() + " --settings " + settings.string() + " --size 320x180";
  }
  std::filesystem::path dir, settings;
  std::string common;
};

}  // namespace terrasol::testing
