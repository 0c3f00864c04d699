#pragma once
// Minecraft's blocks as facts: data/minecraft_blocks.json, written by tools/blocktable from
// PrismarineJS minecraft-data (MIT; docs/world.md). Every block of one Minecraft version in
// Minecraft's order with its states in Minecraft's order, so a state's place in the table is its
// Minecraft block state id; the light each state emits, the light the block filters, and each state's
// collision boxes. Plain data: the block registry builds on it.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "world/block.h"
#include "world/face_coverage.h"

namespace terrasol {

struct TableBlock {
  // Name, properties and default state (relative to its first), opacity, the default state's
  // emission, whether light passes by its shape and whether it always stands in water. Drawn by its
  // blockstates (shape Model; cutout where Minecraft calls it transparent) until a blocks.json says
  // otherwise; Minecraft's air blocks (air, cave_air, void_air) have no shape.
  BlockType type;
  std::vector<std::uint8_t> emission;    // per state, 0..15
  std::vector<std::uint16_t> collision;  // per state: an index into BlockTable::shapes
};

struct BlockTable {
  std::string version;  // Minecraft's, "1.21.11"
  // Collision shapes in 1/16 of a block; the few boxes Minecraft puts on the half-sixteenth (chains,
  // bamboo) rounded outward. 0 is empty, 1 the whole cell.
  std::vector<std::vector<ShapeBox>> shapes;
  std::vector<TableBlock> blocks;

  // Throws Error naming the file, the block and the key that is wrong.
  static BlockTable fromJson(std::string_view text, const std::string& fileName);
  static BlockTable fromFile(const std::filesystem::path& file);
  // The table Terrasol ships: data/minecraft_blocks.json under the data root.
  static std::filesystem::path shippedFile();
};

}  // namespace terrasol
