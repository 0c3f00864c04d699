// Fuzz target: a glTF model as a scene or the game would load it (.gltf text or .glb bytes; external
// files resolve against an empty directory). Bad input must end in terrasol::Error; anything else (a
// crash, another exception, a sanitizer report, a runaway allocation) is a bug.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "assets/gltf_model.h"
#include "core/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path empty =
      std::filesystem::temp_directory_path() / "terrasol-gltf-fuzz-empty";
  std::filesystem::create_directories(empty);
  try {
    terrasol::parseModel(std::vector<std::uint8_t>(data, data + size), "fuzz.gltf", empty);
  } catch (const terrasol::Error&) {
  }
  return 0;
}
