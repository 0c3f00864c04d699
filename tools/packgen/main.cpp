// terrasol-packgen: writes Terrasol's default resource pack.
//   terrasol-packgen [DIR]   (default: resourcepacks/default of the source tree)

#include <cstdio>
#include <exception>

#include "core/paths.h"
#include "packgen.h"

int main(int argc, char** argv) {
  try {
    const auto dir = argc > 1 ? std::filesystem::path(argv[1]) : terrasol::resourcePackDir() / "default";
    terrasol::packgen::writeDefaultPack(dir);
    std::printf("wrote the default pack's textures to %s\n", dir.string().c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "terrasol-packgen: %s\n", e.what());
    return 1;
  }
}
