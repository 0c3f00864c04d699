#pragma once
// Block types as data: everything the light, mesh and render code needs to know about a block.

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/enum_names.h"
#include "core/tint.h"

namespace terrasol {

// A block state: what the world stores in a cell. Each block has one state per combination of its
// properties' values (one for a block without properties), numbered consecutively; 0 is always air.
using BlockId = std::uint16_t;
inline constexpr BlockId kAir = 0;
inline constexpr float kUnbreakable = -1.0f;  // BlockType::hardness of what no digging breaks

// Model: drawn by the models its blockstates file names (assets/minecraft/blockstates/<name>.json).
enum class BlockShape : std::uint8_t { None, Cube, Cross, Liquid, Torch, Model };
enum class RenderLayer : std::uint8_t { None, Opaque, Cutout, Translucent };

// blocks.json's "placement": the rule a placed state follows (game/placement.h); None, the key
// absent, keeps the held state.
enum class PlacementRule : std::uint8_t {
  None,
  Stairs,
  Slab,
  Axis,
  Facing,
  FacingBack,
  Door,
  Trapdoor,
  Wall,
  Torch,
  Layers,
  Pointing,  // six facings: out of the clicked face (end rods, pistons, amethyst); a hopper into it
  Attached,  // "face": on the floor, a wall or the ceiling (buttons, levers, grindstones)
  Rotation,  // sixteen "rotation"s toward the player on a floor, its wall variant on a side (signs)
  TwoTall,   // "half" lower and upper: two cells high (tall flowers, dripleaves)
  Bed,       // "part" foot and head: two cells along the player's look
  Rail       // on a whole block's top, along the player's look
};
inline constexpr EnumNames<PlacementRule, 17> kPlacementRules{
    {"", "stairs", "slab", "axis", "facing", "facing_back", "door", "trapdoor", "wall", "torch", "layers",
     "pointing", "attached", "rotation", "two_tall", "bed", "rail"}};

// blocks.json's "connects" (world/connected_states.h): fences, panes and walls join their neighbours;
// a gate is what fences and walls join across its bars.
enum class Connects : std::uint8_t { None, Fence, Pane, Wall, Gate };
inline constexpr EnumNames<Connects, 5> kConnects{{"", "fence", "pane", "wall", "gate"}};

// A state's property has a value: "none_when": "open=true".
struct PropertyValue {
  std::string property, value;
};

// Texture names per face in Direction order (west, east, down, up, north, south). Each face lists
// candidates, first found in the packs wins (e.g. "short_grass" then its pre-1.20.3 name "grass").
using FaceTextures = std::array<std::vector<std::string>, 6>;

// A property and the values it takes ("axis": "y", "x", "z"); the first is the default unless the
// block names another.
struct BlockProperty {
  std::string name;
  std::vector<std::string> values;

  // The value's index, values.size() when it is not one of them.
  std::size_t indexOf(std::string_view value) const {
    return static_cast<std::size_t>(std::find(values.begin(), values.end(), value) - values.begin());
  }
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
  std::uint8_t emission = 0;  // light level emitted by its default state, 0..15 (per state: the registry)
  // One of Minecraft's blocks (world/block_table.h): its states, light and collision are Minecraft's.
  bool minecraft = false;
  // A pack's blocks.json lists it; one of Minecraft's blocks it leaves out is drawn by the packs'
  // blockstates, or as a placeholder where none has them.
  bool inBlocksJson = false;
  // Stands in water in every state (seagrass, kelp); other blocks hold water where "waterlogged=true".
  bool alwaysInWater = false;
  // Light stops at the sides its shape covers whole (vanilla's useShapeForLightOcclusion): a bottom
  // slab keeps sky light from the cell below it but lets it in through its open top half.
  bool shapeOccludesLight = false;
  // Gameplay. `placement`: the rule a placed state follows; `wallVariant`: the default state of the
  // block placed instead against a wall (a torch's wall torch), kAir for none; `connects`: how it
  // joins its neighbours; `opens`: using it toggles its "open" property.
  PlacementRule placement = PlacementRule::None;
  BlockId wallVariant = kAir;
  Connects connects = Connects::None;
  bool opens = false;
  // In the inventory and the hotbar; false for the stand-in of a block nothing knows (a mod's, in a
  // Minecraft save), which worlds hold but players do not place.
  bool placeable = true;
  // Collision (world/block_shapes.h): boxes reach up to `collisionHeight` (1/16, 0 keeps the shape's;
  // fences and walls 24), and none in states with `passableWhen` ("open=true": an open gate).
  std::uint8_t collisionHeight = 0;
  std::optional<PropertyValue> passableWhen;
  // How long it takes to dig, Minecraft's measure (stone 1.5, dirt 0.5, obsidian 50): 0 breaks at
  // once, kUnbreakable never (bedrock).
  float hardness = 1.0f;
  Tint tint = Tint::None;
  FaceTextures textures;
  // Faces some states draw otherwise ("textures_when": a snowy grass block's sides); a face left
  // empty keeps `textures`' (BlockRegistry::faceTextures).
  struct TexturesWhen {
    PropertyValue when;
    FaceTextures textures;
  };
  std::vector<TexturesWhen> texturesWhen;

  // A full opaque cube: hides neighbouring faces and is solid to walk on.
  bool isOpaqueCube() const { return shape == BlockShape::Cube && layer == RenderLayer::Opaque; }

  // A state's offset among the block's states from its values' indices: the last property counts
  // fastest, as Minecraft numbers them.
  std::size_t stateOffset(const std::vector<std::size_t>& valueIndices) const {
    std::size_t offset = 0;
    for (std::size_t i = 0; i < properties.size(); ++i)
      offset = offset * properties[i].values.size() + valueIndices[i];
    return offset;
  }
  std::vector<std::size_t> valueIndices(std::size_t offset) const {
    std::vector<std::size_t> indices(properties.size());
    for (std::size_t i = properties.size(); i-- > 0;) {
      indices[i] = offset % properties[i].values.size();
      offset /= properties[i].values.size();
    }
    return indices;
  }
};

}  // namespace terrasol
