// Inventory icons: every block the inventory offers gets one, drawn from its model and textures.
#include "render/block_icons.h"

#include "core/paths.h"
#include "mesh/block_icon_mesh.h"
#include "scene/block_atlas.h"
#include "support/gl_test.h"
#include "support/golden.h"

namespace terrasol {
namespace {

class BlockIconsTest : public testing::GlTest {};

// Each icon covers a good part of its cell (no empty or missing-texture icon slips through unseen),
// and the sheet looks as it did (a golden, looked at).
TEST_F(BlockIconsTest, EveryBlockGetsAnIcon) {
  const BlockRegistry& blocks = testing::defaultBlocks();
  PackStack packs;
  packs.push(ResourcePack::open(resourcePackDir() / "default"));
  const BlockAtlas atlas = buildBlockAtlas(blocks, packs);
  ASSERT_TRUE(atlas.problems.empty());
  const BlockMeshTable table = meshTableOf(blocks, atlas);
  const std::vector<BlockId> states = iconStates(blocks, atlas.placeholders);
  std::vector<SectionMesh> meshes;
  for (const BlockId s : states) meshes.push_back(iconMesh(table, blocks, s));
  constexpr int kCell = 32;
  const BlockIcons icons(ShaderPreprocessor(shaderDir()), atlas.atlas, atlas.tints, meshes, kCell);
  context_->checkErrors("drawing the icons");
  ASSERT_EQ(icons.count(), states.size());
  const Image sheet = icons.read();
  for (std::size_t i = 0; i < states.size(); ++i) {
    // The cell, read through the uv the HUD uses (v runs up the texture, rows are read top first).
    const glm::vec4 uv = icons.uv(i);
    const int x0 = static_cast<int>(uv.x * static_cast<float>(sheet.width) + 0.5f);
    const int y0 = sheet.height - static_cast<int>(uv.y * static_cast<float>(sheet.height) + 0.5f);
    int covered = 0;
    for (int y = y0; y < y0 + kCell; ++y)
      for (int x = x0; x < x0 + kCell; ++x) covered += sheet.pixel(x, y)[3] > 0;
    // A torch, the thinnest, covers about 3 %; a cube about 60 %.
    EXPECT_GT(covered, kCell * kCell / 50) << blocks.stateName(states[i]);
  }
  EXPECT_TRUE(testing::matchesGolden(sheet, "block_icons"));
}

}  // namespace
}  // namespace terrasol
