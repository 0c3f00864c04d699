#pragma once
// Minecraft's block model format (assets/<namespace>/models/block/*.json, Java 1.20 semantics):
// `parent` chains, `textures` with "#name" references, `elements` (boxes in 1/16 units, an optional
// rotation about one axis, faces with uv, texture, cullface, rotation and tintindex) and
// `ambientocclusion`. ModelLibrary reads them from a pack stack (the topmost pack's file wins) and
// resolves each model against its parents into a BlockModel whose textures are names ("block/stone")
// or kMissingTexture. Plain C++: no GL.

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/enum_names.h"

namespace terrasol {

class PackStack;

// Minecraft's face names, in its order.
enum class ModelFace : std::uint8_t { Down, Up, North, South, West, East };
inline constexpr EnumNames<ModelFace, 6> kModelFaceNames{{"down", "up", "north", "south", "west", "east"}};
// The unit vector out of a face (north is -z, east +x).
glm::vec3 faceNormal(ModelFace face);

// A texture reference that resolves to nothing: drawn with the missing-texture pattern.
inline const std::string kMissingTexture = "missingno";

struct ElementFace {
  glm::vec4 uv{0.0f};   // u0, v0, u1, v1 in 1/16 of the texture
  std::string texture;  // resolved: "block/stone", or kMissingTexture
  std::optional<ModelFace> cullface;
  int rotation = 0;    // 0, 90, 180 or 270: the texture turned clockwise
  int tintIndex = -1;  // -1: not tinted
};

struct ElementRotation {
  glm::vec3 origin{8.0f};  // 1/16 units
  int axis = 1;            // 0 x, 1 y, 2 z
  float angle = 0.0f;      // -45, -22.5, 0, 22.5 or 45 degrees
  bool rescale = false;    // stretch the two other axes by 1 / cos(angle), as a diagonal would
};

struct ModelElement {
  glm::vec3 from{0.0f}, to{16.0f};  // 1/16 units, -16..32
  std::optional<ElementRotation> rotation;
  bool shade = true;
  std::array<std::optional<ElementFace>, 6> faces;  // by ModelFace
};

struct BlockModel {
  std::string name;  // "block/oak_stairs"
  bool ambientOcclusion = true;
  std::vector<ModelElement> elements;
};

// "minecraft:block/stone" and "block/stone" name the same model or texture: "block/stone".
std::string resourceName(const std::string& location);

class ModelLibrary {
 public:
  // Reads from `packs`, which must outlive it.
  explicit ModelLibrary(const PackStack& packs) : packs_(packs) {}

  // The model `location` names, resolved against its parents. Throws Error naming the file and the key
  // for a malformed model, and the chain for a missing parent or a cycle.
  const BlockModel& model(const std::string& location);

  // Texture references that resolved to nothing, "model: #name", each warned about once.
  const std::set<std::string>& missingTextures() const { return missing_; }

 private:
  // One file as written: its faces' textures still references ("#side").
  struct Raw {
    std::string file;    // how messages name it
    std::string parent;  // "" for none
    std::map<std::string, std::string> textures;
    std::optional<std::vector<ModelElement>> elements;
    std::optional<bool> ambientOcclusion;
  };
  const Raw& raw(const std::string& name);
  std::string resolveTexture(const std::vector<const Raw*>& chain, const std::string& reference);

  const PackStack& packs_;
  std::map<std::string, Raw> raws_;
  std::map<std::string, BlockModel> models_;
  std::set<std::string> missing_;
};

}  // namespace terrasol
