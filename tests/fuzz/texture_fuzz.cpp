// Fuzz target: a block texture as a pack would deliver it. The input is PNG bytes, optionally followed
// by "\n--mcmeta--\n" and the texture's .png.mcmeta text. Bad input must end in terrasol::Error;
// anything else (a crash, another exception, a sanitizer report, a huge allocation) is a bug.

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "assets/texture_loader.h"
#include "assets/texture_meta.h"
#include "core/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kSeparator = "\n--mcmeta--\n";
  const std::size_t cut = input.find(kSeparator);
  const std::string_view png = input.substr(0, cut);
  int width = 16, height = 16;
  try {
    const terrasol::Image image = terrasol::decodeImage(std::vector<std::uint8_t>(png.begin(), png.end()),
                                                        "fuzz.png", terrasol::kTextureLimits);
    width = image.width;
    height = image.height;
  } catch (const terrasol::Error&) {
  }
  if (cut != std::string_view::npos) {
    try {
      terrasol::parseAnimation(std::string(input.substr(cut + kSeparator.size())), width, height,
                               "fuzz.png.mcmeta");
    } catch (const terrasol::Error&) {
    }
  }
  return 0;
}
