#pragma once
// Each block state's shape as boxes in 1/16 of a block: what a player collides with and what the
// targeting ray hits and the outline draws. A full cube's is the whole cell; plants, torches, liquids
// and air have none. Model blocks' boxes come from their models (scene/block_atlas.h, the default
// pack's: as in Minecraft, a resource pack does not change how a block collides). Immutable once
// built; the world points at it (World::setShapes).

#include <array>
#include <bitset>
#include <cstdint>
#include <vector>

#include "world/block_registry.h"
#include "world/face_coverage.h"

namespace terrasol {

class BlockShapes {
 public:
  // Opaque and see-through cubes a full box, every other state none; Minecraft's blocks collide as
  // Minecraft's table says.
  explicit BlockShapes(const BlockRegistry& blocks);

  const std::vector<ShapeBox>& boxes(BlockId state) const { return boxes_[state]; }
  // Whether the state's shape is the whole cell (a cube, glass, a double slab).
  bool wholeCell(BlockId state) const { return boxes_[state].size() == 1 && boxes_[state][0] == ShapeBox{}; }
  void setBoxes(BlockId state, std::vector<ShapeBox> boxes);
  // What a player collides with: Minecraft's boxes for its blocks (world/block_table.h); for a block a
  // pack adds, the boxes raised to the block's collision height (a fence's 1.5 blocks), none for a
  // passable state (an open gate) and without flat ones (a ladder's plane).
  const std::vector<ShapeBox>& collision(BlockId state) const { return collision_[state]; }

  // Light through shaped blocks, as vanilla's useShapeForLightOcclusion decides it: light moves from a
  // cell to its neighbour unless the parts of the side between them that their shapes cover make up
  // the whole side together (a bottom slab's bottom alone; a bottom slab's side with a top slab's
  // beside it). Only blocks whose shape occludes light (BlockType::shapeOccludesLight) take part.
  // Per state and side (Direction order), its covered part as an index into lightFaceMasks(); 0 is
  // nothing covered.
  const std::vector<std::array<std::uint8_t, 6>>& lightFaces() const { return lightFaces_; }
  const std::vector<SideMask>& lightFaceMasks() const { return faceMasks_; }
  // Per state, the sides covered whole (bits by Direction), which stop light on their own.
  const std::vector<std::uint8_t>& lightSides() const { return lightSides_; }
  // Per state, 1 for an opaque cube: BlockRegistry::opaqueCubes, and the states of opaque model
  // blocks whose shape is the whole cell (a double slab, a log lying on its side): they hide their
  // neighbours' faces and darken corners as cubes do.
  const std::vector<std::uint8_t>& opaqueCubes() const { return opaqueCubes_; }

 private:
  void collideWithBoxes(BlockId state);

  std::vector<std::vector<ShapeBox>> boxes_, collision_;
  std::vector<std::uint8_t> collisionHeight_;  // per state: BlockType::collisionHeight, 0 when passable
  std::vector<bool> shapeOccludesLight_, opaqueModel_;
  std::vector<std::uint8_t> lightSides_, opaqueCubes_;
  std::vector<std::array<std::uint8_t, 6>> lightFaces_;
  std::vector<SideMask> faceMasks_{SideMask{}};  // index 0: nothing covered
  std::vector<bool> minecraftCollision_;
};

}  // namespace terrasol
