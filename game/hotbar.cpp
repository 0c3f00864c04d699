#include "hotbar.h"

#include <algorithm>
#include <cmath>

namespace terrasol {

Hotbar::Hotbar(const BlockRegistry& blocks) {
  constexpr const char* kFirstStart[kSlots] = {"stone",      "stone_slab", "oak_stairs",
                                               "oak_planks", "oak_log",    "oak_fence",
                                               "glass_pane", "torch",      "oak_door"};
  for (int i = 0; i < kSlots; ++i) slots_[static_cast<std::size_t>(i)] = blocks.id(kFirstStart[i]);
}

void Hotbar::scroll(double notches) {
  const int steps = static_cast<int>(std::lround(-notches));
  selected_ = ((selected_ + steps) % kSlots + kSlots) % kSlots;
}

void Hotbar::pick(BlockId state) {
  const auto slot = std::find(slots_.begin(), slots_.end(), state);
  if (slot != slots_.end()) {
    selected_ = static_cast<int>(slot - slots_.begin());
  } else {
    put(selected_, state);
  }
}

}  // namespace terrasol
