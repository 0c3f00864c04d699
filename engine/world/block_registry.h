#pragma once
// The table of block types, loaded from JSON (resourcepacks/default/blocks.json). Immutable after
// loading, so worker threads read it freely.

#include <filesystem>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/state_values.h"
#include "world/block.h"

namespace terrasol {

class BlockRegistry {
 public:
  // Throws Error naming the file, the block (by index and name) and the key that is wrong.
  static BlockRegistry fromFile(const std::filesystem::path& file);
  static BlockRegistry fromJson(std::string_view json, const std::string& fileName);

  // The block type of a state.
  const BlockType& operator[](BlockId state) const { return types_[blockOf_[state]]; }
  // How many states there are: tables indexed by BlockId are this long.
  std::size_t size() const { return blockOf_.size(); }
  std::size_t blockCount() const { return types_.size(); }
  const BlockType& block(std::size_t index) const { return types_[index]; }
  // The index of a state's block type (0 .. blockCount() - 1).
  std::size_t blockIndex(BlockId state) const { return blockOf_[state]; }

  // A state named as Minecraft's commands name it: "stone", "oak_log[axis=x]"; properties left out
  // keep their default. Throws Error saying what is unknown or malformed.
  BlockId id(std::string_view name) const;
  // The same without throwing: kAir for an unknown block; `found` is false when anything was unknown
  // or malformed (a known block's default state then stands in) and `problem` says what.
  BlockId find(std::string_view name, bool* found = nullptr, std::string* problem = nullptr) const;
  // "oak_log[axis=x]" (every property, by name); a block without properties is just its name.
  std::string stateName(BlockId state) const;
  StateValues stateValues(BlockId state) const;
  // The state with `property` set to `value`; nothing when its block has no such property or value.
  std::optional<BlockId> with(BlockId state, std::string_view property, std::string_view value) const;

  // Per-state tables for hot loops (light, meshing): one byte each, indexed by BlockId.
  const std::vector<std::uint8_t>& opacities() const { return opacity_; }
  const std::vector<std::uint8_t>& emissions() const { return emission_; }
  // 1 where the block is an opaque cube (hides neighbouring faces, darkens corners).
  const std::vector<std::uint8_t>& opaqueCubes() const { return opaqueCube_; }

 private:
  // Appends the next block read, its defaultState relative to its first; throws Error for a bad one.
  void add(BlockType type);

  std::vector<BlockType> types_;
  std::vector<std::uint16_t> blockOf_;  // per state: its block's index in types_
  std::unordered_map<std::string, BlockId> byName_;
  std::vector<std::uint8_t> opacity_;
  std::vector<std::uint8_t> emission_;
  std::vector<std::uint8_t> opaqueCube_;
};

}  // namespace terrasol
