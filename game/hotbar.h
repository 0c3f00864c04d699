#pragma once
// The nine hotbar slots and the selected one, as Minecraft's: number keys and the wheel select, the
// middle click picks a block into the bar. Plain C++.

#include <array>
#include <cstddef>

#include "world/block_registry.h"

namespace terrasol {

class Hotbar {
 public:
  static constexpr int kSlots = 9;

  // The slots from the first start: stone, stone slab, oak stairs, planks, log, fence, glass pane,
  // torch, door.
  explicit Hotbar(const BlockRegistry& blocks);

  int selected() const { return selected_; }
  BlockId held() const { return at(selected_); }
  BlockId at(int slot) const { return slots_[static_cast<std::size_t>(slot)]; }
  const std::array<BlockId, kSlots>& slots() const { return slots_; }

  void select(int slot) { selected_ = slot; }
  // Wheel notches (+ up): down moves to the next slot, as in Minecraft, wrapping round.
  void scroll(double notches);
  void put(int slot, BlockId state) { slots_[static_cast<std::size_t>(slot)] = state; }
  // The middle click: selects the slot already holding `state`, or puts it into the selected one.
  void pick(BlockId state);

 private:
  std::array<BlockId, kSlots> slots_{};
  int selected_ = 0;
};

}  // namespace terrasol
