#pragma once
// The table of block types: Minecraft's (world/block_table.h, so a Minecraft block's states carry
// Minecraft's state ids), with a pack's blocks.json over it (resourcepacks/default/blocks.json: how
// each block looks and the game's rules for it, and the blocks the pack adds after Minecraft's).
// Immutable after loading, so worker threads read it freely.

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/state_values.h"
#include "world/block.h"
#include "world/block_table.h"

namespace terrasol {

class BlockRegistry {
 public:
  // Throws Error naming the file, the block (by index and name) and the key that is wrong.
  static BlockRegistry load(const BlockTable& table, std::string_view blocksJson,
                            const std::string& fileName);
  // The shipped table (BlockTable::shippedFile) with `blocksJson` over it.
  static BlockRegistry load(const std::filesystem::path& blocksJson);
  // A pack's blocks.json alone, air first: small registries for tests.
  static BlockRegistry fromJson(std::string_view json, const std::string& fileName);

  // Appends blocks a resource pack adds (scene/pack_blocks.h), while loading, before the registry is
  // shared. Each type's defaultState is relative to its first state. Throws Error for a known name.
  void addPackBlocks(std::vector<BlockType> types);
  // How many blocks came from Minecraft's table and blocks.json; those after them a pack added.
  std::size_t blocksBeforePacks() const { return blocksBeforePacks_; }

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
  // The textures of a state's faces: its block's, with the "textures_when" that hold for it over them.
  FaceTextures faceTextures(BlockId state) const;
  // The state with `property` set to `value`; nothing when its block has no such property or value.
  std::optional<BlockId> with(BlockId state, std::string_view property, std::string_view value) const;

  // How many blocks come from Minecraft's table: blocks 0 .. minecraftBlockCount() - 1.
  std::size_t minecraftBlockCount() const { return minecraftBlocks_; }

  // Per-state tables for hot loops (light, meshing): one byte each, indexed by BlockId. A state that
  // holds water filters light as water does.
  const std::vector<std::uint8_t>& opacities() const { return opacity_; }
  const std::vector<std::uint8_t>& emissions() const { return emission_; }
  // 1 where the block is an opaque cube (hides neighbouring faces, darkens corners).
  const std::vector<std::uint8_t>& opaqueCubes() const { return opaqueCube_; }
  // 1 where the cell holds water besides its block: "waterlogged=true", and blocks always in water.
  const std::vector<std::uint8_t>& holdsWater() const { return water_; }
  // The water that such cells hold: water's default state; kAir where there is no "water" block.
  BlockId waterState() const { return waterState_; }
  // Minecraft's collision boxes for a Minecraft block's state; null for a block a pack added.
  const std::vector<ShapeBox>* minecraftCollision(BlockId state) const {
    const std::uint16_t shape = collision_[state];
    return shape == kNoShape ? nullptr : &shapes_[shape];
  }

 private:
  static constexpr std::uint16_t kNoShape = 0xffff;
  // Appends a block, its defaultState relative to its first; `emission` and `collision` per state
  // (empty: the type's emission, no Minecraft collision). Throws Error for a bad one.
  void add(BlockType type, const std::vector<std::uint8_t>& emission = {},
           const std::vector<std::uint16_t>& collision = {});
  // blocks.json over the blocks added so far: looks and rules for known ones, the rest added.
  void overlay(const nlohmann::json& blocksJson);
  // Minecraft's blocks blocks.json gives no rule: the rule their properties imply, and the wall forms
  // of standing blocks (signs, banners, heads, coral fans, torches).
  void implyPlacements();
  // The per-state tables, once every block is known.
  void finish();

  std::vector<BlockType> types_;
  std::vector<std::uint16_t> blockOf_;  // per state: its block's index in types_
  std::unordered_map<std::string, BlockId> byName_;
  std::vector<std::uint8_t> opacity_;
  std::vector<std::uint8_t> emission_;
  std::vector<std::uint8_t> opaqueCube_;
  std::vector<std::uint8_t> water_;
  std::vector<std::uint16_t> collision_;  // per state: an index into shapes_, or kNoShape
  std::vector<std::vector<ShapeBox>> shapes_;
  std::size_t minecraftBlocks_ = 0;
  BlockId waterState_ = kAir;
  std::size_t blocksBeforePacks_ = 0;
};

}  // namespace terrasol
