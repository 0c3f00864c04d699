#pragma once
// The table of block types, loaded from JSON (resourcepacks/default/blocks.json). Immutable after
// loading, so worker threads read it freely.

#include <filesystem>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "world/block.h"

namespace terrasol {

class BlockRegistry {
 public:
  // Throws Error naming the file, the block (by index and name) and the key that is wrong.
  static BlockRegistry fromFile(const std::filesystem::path& file);
  static BlockRegistry fromJson(std::string_view json, const std::string& fileName);

  const BlockType& operator[](BlockId id) const { return types_[id]; }
  std::size_t size() const { return types_.size(); }
  // Throws Error for an unknown name.
  BlockId id(std::string_view name) const;
  // kAir when unknown; `found` tells.
  BlockId find(std::string_view name, bool* found = nullptr) const;

  // Per-id tables for hot loops (light, meshing): one byte each, indexed by BlockId.
  const std::vector<std::uint8_t>& opacities() const { return opacity_; }
  const std::vector<std::uint8_t>& emissions() const { return emission_; }
  // 1 where the block is an opaque cube (hides neighbouring faces, darkens corners).
  const std::vector<std::uint8_t>& opaqueCubes() const { return opaqueCube_; }

 private:
  std::vector<BlockType> types_;
  std::unordered_map<std::string, BlockId> byName_;
  std::vector<std::uint8_t> opacity_;
  std::vector<std::uint8_t> emission_;
  std::vector<std::uint8_t> opaqueCube_;
};

}  // namespace terrasol
