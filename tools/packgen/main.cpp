// terrasol-packgen: writes Terrasol's default resource pack.
//   terrasol-packgen [DIR]   (default: resourcepacks/default of the source tree)

#include <cstdio>

#include "core/paths.h"
#include "core/tool_main.h"
#include "packgen.h"

int main(int argc, char** argv) {
  return terrasol::guardedMain("terrasol-packgen", [&] {
    const auto dir = argc > 1 ? std::filesystem::path(argv[1]) : terrasol::resourcePackDir() / "default";
    terrasol::packgen::writeDefaultPack(dir);
    std::printf("wrote the default pack's textures to %s\n", dir.string().c_str());
    return 0;
  });
}
