#include "support/world_support.h"

#include "core/paths.h"

namespace terrasol::testing {

std::filesystem::path testOutputDir() {
  const std::filesystem::path dir = TERRASOL_TEST_OUTPUT_DIR;
  std::filesystem::create_directories(dir);
  return dir;
}

const BlockRegistry& defaultBlocks() {
  static const BlockRegistry blocks = BlockRegistry::fromFile(resourcePackDir() / "default" / "blocks.json");
  return blocks;
}

std::filesystem::path scratchDir(const std::string& name) {
  const auto dir = testOutputDir() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

bool sameBlocks(const Chunk& a, const Chunk& b) {
  for (int y = kMinY; y < kMaxY; ++y)
    for (int z = 0; z < 16; ++z)
      for (int x = 0; x < 16; ++x)
        if (a.get(x, y, z) != b.get(x, y, z)) return false;
  return true;
}

}  // namespace terrasol::testing
