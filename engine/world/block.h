#pragma once
// Block types as data: everything the light, mesh and render code needs to know about a block.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/tint.h"

namespace terrasol {

// A block state: what the world stores in a cell. Each block has one state per combination of its
// properties' values (one for a block without properties), numbered consecutively; 0 is always air.
using BlockId = std::uint16_t;
inline constexpr BlockId kAir = 0;

// Model: drawn by the models its blockstates file names (assets/minecraft/blockstates/<name>.json).
enum class BlockShape : std::uint8_t { None, Cube, Cross, Liquid, Torch, Model };
enum class RenderLayer : std::uint8_t { None, Opaque, Cutout, Translucent };

// Texture names per face in Direction order (west, east, down, up, north, south). Each face lists
// candidates, first found in the packs wins (e.g. "short_grass" then its pre-1.20.3 name "grass").
using FaceTextures = std::array<std::vector<std::string>, 6>;

// A property and the values it takes ("axis": "y", "x", "z"); the first is the default unless the
// block names another.
struct BlockProperty {
  std::string name;
  std::vector<std::string> values;
};

struct BlockType {
  std::string name;
  std::vector<BlockProperty> properties;  // by name, as Minecraft lists them
  BlockId firstState = 0;                 // its states are firstState .. firstState + stateCount - 1
  std::uint16_t stateCount = 1;
  BlockId defaultState = 0;
  BlockShape shape = BlockShape::None;
  RenderLayer layer = RenderLayer::None;
  std::uint8_t opacity = 0;   // light lost passing through, 0..15; 15 stops light
  std::uint8_t emission = 0;  // light level emitted, 0..15
  // Light stops at the sides its shape covers whole (vanilla's useShapeForLightOcclusion): a bottom
  // slab keeps sky light from the cell below it but lets it in through its open top half.
  bool shapeOccludesLight = false;
  // Gameplay. `placement`: the rule a placed state follows (game/placement.h; "" keeps the held
  // state); `wallVariant`: the block placed instead against a wall (a torch's wall torch);
  // `connects`: "fence", "pane" or "wall", joining its neighbours, or "gate", which fences and walls
  // join (world/connected_states.h);
  // `opens`: using it toggles its "open" property.
  std::string placement, wallVariant, connects;
  bool opens = false;
  // Collision (world/block_shapes.h): boxes reach up to `collisionHeight` (1/16, 0 keeps the shape's;
  // fences and walls 24), and none in states with `passableWhen` ("open=true": an open gate).
  std::uint8_t collisionHeight = 0;
  std::string passableWhen;
  Tint tint = Tint::None;
  FaceTextures textures;

  // A full opaque cube: hides neighbouring faces and is solid to walk on.
  bool isOpaqueCube() const { return shape == BlockShape::Cube && layer == RenderLayer::Opaque; }
};

}  // namespace terrasol
