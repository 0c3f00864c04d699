#pragma once
// The creative inventory (E): every item as an icon in Minecraft's tabs (inventory.h), found by a
// search field across them all; clicking one puts it
// into the selected hotbar slot, dragging one onto a hotbar slot (shown below them) puts it there.
// Draws with ImGui inside the HUD's frame.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "item_icon.h"

namespace terrasol {

class InventoryScreen {
 public:
  // What the player did in the inventory this frame.
  struct Result {
    std::optional<std::pair<int, std::size_t>> place;  // put item `second` into hotbar slot `first`
    std::optional<int> select;                         // a hotbar slot clicked
  };
  Result draw(const std::vector<ItemIcon>& items, const std::vector<ItemIcon>& hotbar, int selected);
  // A text field has the keyboard: letters are typing, not game keys.
  bool typing() const;

 private:
  std::string search_;  // kept while the inventory is closed
  int group_ = -1;      // the tab shown: an InventoryGroup, -1 for all
};

}  // namespace terrasol
