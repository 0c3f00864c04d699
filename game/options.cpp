#include "options.h"

#include <charconv>

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

}  // namespace

std::string gameUsage() {
  return "usage: terrasol [options]\n"
         "  --frames N        quit after N frames (for smoke tests)\n"
         "  --size WxH        window size in pixels (default 1280x720)\n"
         "  --screenshot FILE save the last frame as an image (with --frames)\n"
         "  --demo-dir DIR    where to write the headless demo when there is no display\n"
         "                    (default: demo/ beside the executable)\n"
         "  --help            show this text\n";
}

GameOptions parseGameOptions(const std::vector<std::string>& args) {
  GameOptions options;
  options.demoDir = executableDir() / "demo";
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw Error(arg + ": missing value");
      return args[++i];
    };
    if (arg == "--help" || arg == "-h") {
      options.help = true;
    } else if (arg == "--frames") {
      options.frames = parseInt(arg, value(), 1);
    } else if (arg == "--size") {
      options.size = parseSize(arg, value());
    } else if (arg == "--screenshot") {
      options.screenshot = value();
    } else if (arg == "--demo-dir") {
      options.demoDir = value();
    } else {
      throw Error("unknown option '" + arg + "' (see --help)");
    }
  }
  if (!options.screenshot.empty() && !options.frames) throw Error("--screenshot needs --frames");
  return options;
}

}  // namespace terrasol
