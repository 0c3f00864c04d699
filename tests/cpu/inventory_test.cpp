// The creative inventory's search and key (game/inventory.h, game/controls.h).
#include "inventory.h"

#include <gtest/gtest.h>

#include <array>

#include "controls.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

TEST(Inventory, SearchFindsEveryWordCaseAndUnderscoresIgnored) {
  EXPECT_TRUE(matchesSearch("oak_stairs", ""));
  EXPECT_TRUE(matchesSearch("oak_stairs", "stairs"));
  EXPECT_TRUE(matchesSearch("oak_stairs", "Oak St"));
  EXPECT_TRUE(matchesSearch("oak_stairs", "  oak   stairs "));
  EXPECT_TRUE(matchesSearch("deepslate_diamond_ore", "diamond_ore"));
  EXPECT_FALSE(matchesSearch("oak_stairs", "birch"));
  EXPECT_FALSE(matchesSearch("oak_stairs", "oak slab")) << "every word must appear";
  EXPECT_FALSE(matchesSearch("stone", "stones"));
}

// Minecraft's tabs: each placeable block is in one, by family.
TEST(Inventory, BlocksFallIntoMinecraftsTabs) {
  const BlockRegistry& blocks = testing::defaultBlocks();
  const auto group = [&](const char* name) { return groupOf(blocks[blocks.id(name)]); };
  using G = InventoryGroup;
  for (const char* b :
       {"stone", "oak_planks", "oak_stairs", "iron_block", "deepslate_bricks", "polished_tuff",
        "cobbled_deepslate", "quartz_pillar", "oak_door", "copper_grate", "bricks"})
    EXPECT_EQ(group(b), G::Building) << b;
  for (const char* b :
       {"white_wool", "red_concrete", "blue_bed", "lime_candle", "glass", "terracotta", "black_shulker_box",
        "cyan_glazed_terracotta", "pink_stained_glass_pane", "white_banner"})
    EXPECT_EQ(group(b), G::Coloured) << b;
  for (const char* b : {"grass_block", "dirt", "oak_log", "oak_leaves", "diamond_ore", "poppy", "sunflower",
                        "tube_coral", "wheat", "ice", "pointed_dripstone", "vine", "deepslate",
                        "red_mushroom", "blue_orchid", "pink_petals", "torchflower", "redstone_ore"})
    EXPECT_EQ(group(b), G::Natural) << b;
  for (const char* b : {"crafting_table", "furnace", "chest", "anvil", "lantern", "torch", "oak_sign",
                        "flower_pot", "bell", "skeleton_skull", "ladder"})
    EXPECT_EQ(group(b), G::Functional) << b;
  for (const char* b : {"redstone_wire", "piston", "rail", "stone_button", "oak_pressure_plate", "lever",
                        "observer", "hopper", "tnt", "target", "redstone_lamp", "waxed_copper_bulb"})
    EXPECT_EQ(group(b), G::Redstone) << b;
  std::array<int, 5> counts{};
  for (std::size_t i = 1; i < blocks.blockCount(); ++i)
    ++counts[static_cast<std::size_t>(groupOf(blocks.block(i)))];
  for (int c : counts) EXPECT_GT(c, 40);
}

TEST(Inventory, EOpensItAsInMinecraft) {
  const KeyBindings keys;
  EXPECT_EQ(keys.key(Action::Inventory), 'E');
  EXPECT_EQ(actionNamed("inventory"), Action::Inventory);
}

}  // namespace
}  // namespace terrasol
