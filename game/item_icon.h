#pragma once
// A hotbar slot or inventory item as the HUD draws it: the block's name and its icon.

#include <string>

namespace terrasol {

struct ItemIcon {
  std::string name;
  int group = 0;                         // the inventory tab it is in (inventory.h's InventoryGroup)
  unsigned texture = 0;                  // GL texture; 0: an empty slot
  float u0 = 0, v0 = 0, u1 = 0, v1 = 0;  // the icon's cell, top left to bottom right
  float r = 1, g = 1, b = 1;             // tint
};

}  // namespace terrasol
