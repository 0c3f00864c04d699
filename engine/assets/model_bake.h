#pragma once
// A resolved block model, placed as a blockstate says (turned about x, then y, optionally with the
// textures locked to the world), as quads: what meshing consumes. Plain C++.

#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "assets/block_model.h"
#include "assets/block_states.h"

namespace terrasol {

struct BakedQuad {
  // Block units (0..1 across a full cube), counter-clockwise seen from the front: the corners showing
  // the texture's top left, bottom left, bottom right and top right before the face's rotation.
  std::array<glm::vec3, 4> corners;
  std::array<glm::vec2, 4> uvs;       // 0..1 across the texture
  std::string texture;                // "block/stone", or kMissingTexture
  std::optional<ModelFace> cullface;  // hidden when the neighbour on this side covers it (placed)
  ModelFace face = ModelFace::Up;     // the side it faces, placed (the nearest for a turned element)
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  int tintIndex = -1;
  bool shade = true;
  bool ambientOcclusion = true;  // the model's; never on an element turned by a non-right angle
  bool operator==(const BakedQuad&) const = default;
};

std::vector<BakedQuad> bakeModel(const BlockModel& model, const ModelPlacement& placement);

// The model's elements as boxes (1/16 units: min x, y, z, max x, y, z), placed: what a block built
// of it collides with and is targeted by. Elements turned by a non-right angle (plants, a torch on a
// wall) are left out, as Minecraft's collision leaves them.
std::vector<std::array<float, 6>> placedBoxes(const BlockModel& model, const ModelPlacement& placement);

// The face whose normal is nearest `normal`.
ModelFace nearestFace(glm::vec3 normal);

}  // namespace terrasol
