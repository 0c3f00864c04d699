#include "scene/pack_blocks.h"

#include <algorithm>
#include <set>

#include "assets/block_model.h"
#include "assets/block_states.h"
#include "assets/model_bake.h"
#include "core/error.h"

namespace terrasol {
namespace {

constexpr std::string_view kBlockstatesDir = "assets/minecraft/blockstates";

// Whether the models a state picks fill its cell: one of them has a whole-cell box.
bool fillsCell(const BlockStates& states, const StateValues& values, ModelLibrary& library) {
  for (const ModelPlacement& p : states.select(values, {})) {
    for (const std::array<float, 6>& b : placedBoxes(library.model(p.model), p)) {
      if (b[0] <= 0.0f && b[1] <= 0.0f && b[2] <= 0.0f && b[3] >= 16.0f && b[4] >= 16.0f && b[5] >= 16.0f)
        return true;
    }
  }
  return false;
}

BlockType typeOf(const std::string& name, const BlockStates& states, ModelLibrary& library) {
  BlockType type;
  type.name = name;
  type.shape = BlockShape::Model;
  std::size_t count = 1;
  for (auto& [property, values] : states.propertyValues()) {
    count *= values.size();
    if (count > 4096) throw Error(name + ": more than 4096 states");
    type.properties.push_back({property, values});
  }
  type.stateCount = static_cast<std::uint16_t>(count);
  // The default: the first variant's values, the first of each value elsewhere.
  StateValues defaults = states.firstVariant();
  std::vector<std::size_t> indices;
  StateValues chosen;
  for (const BlockProperty& p : type.properties) {
    const auto it = defaults.find(p.name);
    const std::size_t i = it == defaults.end() ? 0 : p.indexOf(it->second);
    indices.push_back(i);
    chosen[p.name] = p.values[i];
  }
  type.defaultState = static_cast<BlockId>(type.stateOffset(indices));
  const bool solid = fillsCell(states, chosen, library);
  type.opacity = solid ? 15 : 0;
  type.layer = solid ? RenderLayer::Opaque : RenderLayer::Cutout;
  return type;
}

}  // namespace

std::vector<BlockType> packBlockTypes(const BlockRegistry& blocks, const PackStack& packs,
                                      std::vector<PackProblem>& problems) {
  std::set<std::string> names;
  for (const auto& pack : packs.packs()) {
    for (const std::string& file : pack->files().list(std::string(kBlockstatesDir))) {
      if (!file.ends_with(".json")) continue;
      const std::string name = file.substr(0, file.size() - 5);
      bool known = false;
      blocks.find(name, &known);
      if (!known) names.insert(name);
    }
  }
  std::vector<BlockType> types;
  ModelLibrary library(packs);
  for (const std::string& name : names) {
    try {
      types.push_back(typeOf(name, BlockStates::load(packs, name), library));
    } catch (const Error& e) {
      problems.push_back({PackProblem::Severity::Warning, e.what()});
    }
  }
  return types;
}

BlockRegistry withPackBlocks(BlockRegistry blocks, const PackStack& packs,
                             std::vector<PackProblem>& problems) {
  blocks.addPackBlocks(packBlockTypes(blocks, packs, problems));
  return blocks;
}

}  // namespace terrasol
