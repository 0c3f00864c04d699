#include "options.h"

#include <charconv>
#include <cstdlib>

#include "core/error.h"
#include "core/paths.h"

namespace terrasol {
namespace {

int parseInt(const std::string& option, const std::string& text, int min) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < min) {
    throw Error(option + ": expected an integer >= " + std::to_string(min) + ", got '" + text + "'");
  }
  return value;
}

glm::ivec2 parseSize(const std::string& option, const std::string& text) {
  const auto x = text.find('x');
  if (x == std::string::npos) throw Error(option + ": expected WIDTHxHEIGHT, got '" + text + "'");
  return {parseInt(option, text.substr(0, x), 1), parseInt(option, text.substr(x + 1), 1)};
}

std::uint64_t parseSeed(const std::string& option, const std::string& text) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) {
    throw Error(option + ": expected a whole number from 0 to 18446744073709551615, got '" + text + "'");
  }
  return value;
}

BlockPos parseBlock(const std::string& option, const std::string& text) {
  int v[3] = {0, 0, 0};
  const char* p = text.data();
  const char* end = text.data() + text.size();
  for (int i = 0; i < 3; ++i) {
    const auto [next, ec] = std::from_chars(p, end, v[i]);
    const bool last = i == 2;
    if (ec != std::errc() || (last ? next != end : (next == end || *next != ','))) {
      throw Error(option + ": expected X,Y,Z in whole blocks, got '" + text + "'");
    }
    p = next + 1;
  }
  return {v[0], v[1], v[2]};
}

double parseSeconds(const std::string& option, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(v > 0.0) || v > 3600.0) {
    throw Error(option + ": expected seconds from 0 to 3600, got '" + text + "'");
  }
  return v;
}

}  // namespace

std::string gameUsage() {
  return "usage: terrasol [options]\n"
         "  --world DIR       the world to open, created when missing (default: worlds/world); a\n"
         "                    Minecraft Java save opens read-only, its edits kept in worlds/minecraft-*\n"
         "  --seed N          a new world's seed (default: from the clock)\n"
         "  --pack PATH       a resource pack (folder, .zip or Minecraft's .jar) over the default one;\n"
         "                    repeat to stack, last on top (this run; the menu's list is saved in the\n"
         "                    settings)\n"
         "  --shaderpack PATH an OptiFine/Iris shader pack (folder or .zip) drawing instead of Terrasol's\n"
         "                    pipeline (this run; the menu's Shader packs tab saves its choice)\n"
         "  --settings FILE   the settings file (default: ~/.config/terrasol/settings.json)\n"
         "  --input-script F  replay timed key and mouse events from JSON (see game/input_script.h)\n"
         "  --benchmark [PATH.json] [S]\n"
         "                    fly the built-in circle, or the camera path of a scene file (benchmarks/\n"
         "                    flight.json, still.json), for S seconds (default 20) at the current settings "
         "and\n"
         "                    print frames per second (median and 1% low) and ms per pass; nothing is saved\n"
         "  --benchmark-json F  with --benchmark: write every frame's time and what it did, and ms per pass\n"
         "  --report FILE     write the player, the edits and the probes as JSON at exit\n"
         "  --probe X,Y,Z     a block whose id and light go into the report (repeatable)\n"
         "  --frames N        quit after N frames (for smoke tests); with --input-script, N frames of\n"
         "                    the script, whose clock starts once the world has loaded\n"
         "  --demo            fly the built-in demo path over seed 1 instead of playing\n"
         "  --size WxH        window size in pixels (default 1280x720)\n"
         "  --screenshot FILE save the last frame as an image (with --frames)\n"
         "  --demo-dir DIR    where to write the headless demo when there is no display\n"
         "                    (default: demo/ beside the executable)\n"
         "  --audio-out F.wav play into this file instead of the speakers, in step with the frames (no\n"
         "                    sound card needed; with --input-script the file is the same every run)\n"
         "  --sound-log FILE  write every sound the game asks for, with its tick, as JSON lines\n"
         "  --help            show this text\n";
}

GameOptions parseGameOptions(const std::vector<std::string>& args) {
  GameOptions options;
  options.demoDir = executableDir() / "demo";
  options.world = std::filesystem::path(kWorldsDir) / kDefaultWorldName;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw Error(arg + ": missing value");
      return args[++i];
    };
    if (arg == "--help" || arg == "-h") {
      options.help = true;
    } else if (arg == "--world") {
      options.world = value();
    } else if (arg == "--seed") {
      options.seed = parseSeed(arg, value());
    } else if (arg == "--pack") {
      options.packs.emplace_back(value());
    } else if (arg == "--shaderpack") {
      options.shaderpack = value();
    } else if (arg == "--settings") {
      options.settings = value();
    } else if (arg == "--input-script") {
      options.inputScript = value();
    } else if (arg == "--benchmark") {
      auto next = [&] { return i + 1 < args.size() && !args[i + 1].starts_with("--"); };
      if (next() && args[i + 1].ends_with(".json")) options.benchmarkPath = value();
      options.benchmark = next() ? parseSeconds(arg, value()) : 20.0;
    } else if (arg == "--benchmark-json") {
      options.benchmarkJson = value();
    } else if (arg == "--report") {
      options.report = value();
    } else if (arg == "--probe") {
      options.probes.push_back(parseBlock(arg, value()));
    } else if (arg == "--demo") {
      options.demo = true;
    } else if (arg == "--frames") {
      options.frames = parseInt(arg, value(), 1);
    } else if (arg == "--size") {
      options.size = parseSize(arg, value());
    } else if (arg == "--screenshot") {
      options.screenshot = value();
    } else if (arg == "--audio-out") {
      options.audioOut = value();
    } else if (arg == "--sound-log") {
      options.soundLog = value();
    } else if (arg == "--demo-dir") {
      options.demoDir = value();
    } else {
      throw Error("unknown option '" + arg + "' (see --help)");
    }
  }
  if (!options.benchmarkJson.empty() && !options.benchmark) throw Error("--benchmark-json needs --benchmark");
  if (!options.screenshot.empty() && !options.frames && !options.benchmark) {
    throw Error("--screenshot needs --frames or --benchmark");
  }
  return options;
}

}  // namespace terrasol
