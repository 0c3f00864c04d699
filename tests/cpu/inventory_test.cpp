// The creative inventory's search and key (game/inventory.h, game/controls.h).
#include "inventory.h"

#include <gtest/gtest.h>

#include "controls.h"

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

TEST(Inventory, EOpensItAsInMinecraft) {
  const KeyBindings keys;
  EXPECT_EQ(keys.key(Action::Inventory), 'E');
  EXPECT_EQ(actionNamed("inventory"), Action::Inventory);
}

}  // namespace
}  // namespace terrasol
