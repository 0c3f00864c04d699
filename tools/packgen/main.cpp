// terrasol-packgen: writes Terrasol's default resource pack, or the extreme-materials test pack.
//   terrasol-packgen [DIR]                        (default: resourcepacks/default of the source tree)
//   terrasol-packgen --extreme-materials DIR      (tests/packs/extreme_materials)

#include <cstdio>
#include <string>

#include "core/paths.h"
#include "core/tool_main.h"
#include "extreme_pack.h"
#include "packgen.h"

int main(int argc, char** argv) {
  return terrasol::guardedMain("terrasol-packgen", [&] {
    if (argc > 2 && std::string(argv[1]) == "--extreme-materials") {
      terrasol::packgen::writeExtremeMaterialsPack(argv[2]);
      std::printf("wrote the extreme-materials pack to %s\n", argv[2]);
      return 0;
    }
    const auto dir = argc > 1 ? std::filesystem::path(argv[1]) : terrasol::resourcePackDir() / "default";
    terrasol::packgen::writeDefaultPack(dir);
    std::printf("wrote the default pack's textures to %s\n", dir.string().c_str());
    return 0;
  });
}
