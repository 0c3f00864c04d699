#include "support/world_support.h"

#include "core/paths.h"

namespace terrasol::testing {

std::filesystem::path testOutputDir() {
  const std::filesystem::path dir = TERRASOL_TEST_OUTPUT_DIR;
  std::filesystem::create_directories(dir);
  return dir;
}

const BlockRegistry& defaultBlocks() {
  static const BlockRegistry blocks = BlockRegistry::load(resourcePackDir() / "default" / "blocks.json");
  return blocks;
}

const BlockShapes& handShapes() {
  static const BlockShapes shapes = [] {
    const BlockRegistry& blocks = defaultBlocks();
    BlockShapes s(blocks);
    s.setBoxes(blocks.id("stone_slab[type=bottom]"), {ShapeBox{{0, 0, 0}, {16, 8, 16}}});
    s.setBoxes(blocks.id("stone_slab[type=top]"), {ShapeBox{{0, 8, 0}, {16, 16, 16}}});
    s.setBoxes(blocks.id("stone_slab[type=double]"), {ShapeBox{}});
    // Straight stairs: a half-block slab and the step's half on the side they face (their back).
    for (const char* half : {"bottom", "top"})
      for (const char* facing : {"north", "south", "west", "east"}) {
        const std::string f = facing;
        const bool top = std::string(half) == "top";
        const ShapeBox slab{{0, top ? 8 : 0, 0}, {16, top ? 16 : 8, 16}};
        ShapeBox step{{0, top ? 0 : 8, 0}, {16, top ? 8 : 16, 16}};
        if (f == "north") step.to[2] = 8;
        if (f == "south") step.from[2] = 8;
        if (f == "west") step.to[0] = 8;
        if (f == "east") step.from[0] = 8;
        s.setBoxes(blocks.id("oak_stairs[facing=" + f + ",half=" + half + ",shape=straight]"), {slab, step});
      }
    return s;
  }();
  return shapes;
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
