#include "world/section.h"

#include <algorithm>
#include <utility>

namespace terrasol {

Section::Section(const Section& other)
    : blocks_(other.blocks_ ? std::make_unique<Blocks>(*other.blocks_) : nullptr), uniform_(other.uniform_) {}

Section& Section::operator=(const Section& other) {
  if (this != &other) *this = Section(other);
  return *this;
}

Section::Blocks& Section::mutableBlocks() {
  if (!blocks_) {
    blocks_ = std::make_unique<Blocks>();
    blocks_->fill(uniform_);
  }
  return *blocks_;
}

BlockId Section::set(int x, int y, int z, BlockId id) {
  if (!blocks_) {
    if (id == uniform_) return id;
    mutableBlocks();
  }
  BlockId& slot = (*blocks_)[index(x, y, z)];
  return std::exchange(slot, id);
}

bool Section::compact() {
  if (!blocks_) return true;
  const BlockId first = (*blocks_)[0];
  if (!std::all_of(blocks_->begin(), blocks_->end(), [first](BlockId b) { return b == first; })) return false;
  fill(first);
  return true;
}

}  // namespace terrasol
