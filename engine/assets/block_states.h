#pragma once
// Minecraft's blockstates format (assets/<namespace>/blockstates/<block>.json, Java 1.20 semantics):
// which models a block's state is drawn with. `variants` are keyed by property lists
// ("facing=east,half=bottom", "" for none), each a model or a weighted list of them; `multipart`
// lists parts applied where their `when` holds (values joined by '|', "OR" and "AND" lists). A
// weighted pick is seeded by the block's position, so a world looks the same every time. Plain C++.

#include <cstdint>
#include <glm/vec3.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "core/position_random.h"
#include "core/state_values.h"

namespace terrasol {

class PackStack;

// One model as a blockstate places it: turned about x, then y, in 90-degree steps.
struct ModelPlacement {
  std::string model;  // resource name: "block/oak_stairs"
  int x = 0, y = 0;   // 0, 90, 180 or 270
  bool uvlock = false;
  int weight = 1;
  bool operator==(const ModelPlacement&) const = default;
};

// A multipart part's `when`: every listed property takes one of its values, or (OR / AND) the
// children do. No condition at all holds always.
struct StateCondition {
  enum class Kind : std::uint8_t { Always, Values, Or, And } kind = Kind::Always;
  std::map<std::string, std::vector<std::string>> values;
  std::vector<StateCondition> children;
  bool holds(const StateValues& state) const;
};

class BlockStates {
 public:
  // Throws Error naming `file` and the key for a malformed document.
  static BlockStates parse(const nlohmann::json& root, const std::string& file);
  // assets/minecraft/blockstates/<block>.json from the topmost pack that has it.
  static BlockStates load(const PackStack& packs, const std::string& block);
  // Where a pack keeps a block's blockstates: "assets/minecraft/blockstates/<block>.json".
  static std::string pathOf(const std::string& block);

  // The models `state` is drawn with at block position `pos`: the first variant (in the file's key
  // order) whose every property matches, or every multipart part that holds; each a weighted pick.
  std::vector<ModelPlacement> select(const StateValues& state, glm::ivec3 pos) const;

  // The weighted models of the variant `state` is drawn with, where it picks among several by position
  // (select() makes the same pick): what a mesher draws per cell. Empty for a single model, for a
  // multipart blockstate and for a state no variant matches.
  std::vector<ModelPlacement> choices(const StateValues& state) const;

  // Every model any state may use.
  std::vector<std::string> models() const;
  // Every property a variant or a part's condition names: states that differ only in others (a
  // waterlogged twin) are drawn alike.
  std::set<std::string> properties() const;
  // Each property named, with every value the variants and conditions give it, in the order they first
  // appear: the states of a block only a pack knows (scene/pack_blocks.h).
  std::map<std::string, std::vector<std::string>> propertyValues() const;
  // The first variant's property values; none for a multipart blockstates.
  StateValues firstVariant() const;

 private:
  struct Variant {
    StateValues when;
    std::vector<ModelPlacement> choices;
  };
  struct Part {
    StateCondition when;
    std::vector<ModelPlacement> choices;
  };
  // The first variant (in the file's key order) whose every property matches; null for none.
  const Variant* variantOf(const StateValues& state) const;
  std::vector<Variant> variants_;
  std::vector<Part> parts_;
};

}  // namespace terrasol
