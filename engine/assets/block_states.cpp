#include "assets/block_states.h"

#include <set>
#include <string_view>

#include "assets/block_model.h"
#include "assets/resource_pack.h"
#include "core/error.h"
#include "core/json_check.h"

namespace terrasol {

using namespace json_check;

namespace {

std::vector<std::string> split(const std::string& text, char by) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == by) {
      out.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

// A JSON scalar as Minecraft compares it: true, 3 and "3" are the strings "true" and "3".
std::string scalarText(const json& value, const std::string& key) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_number_integer()) return std::to_string(value.get<std::int64_t>());
  expected(key, "a string", value);
}

// "facing=east,half=bottom" (or "" for every state).
StateValues variantKey(const std::string& text, const std::string& key) {
  StateValues values;
  if (text.empty() || text == "normal") return values;  // "normal": pre-1.13 packs' name for no properties
  for (const std::string& pair : split(text, ',')) {
    const std::size_t eq = pair.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == pair.size()) {
      fail(key, join({"expected property=value pairs joined by ',', not \"", pair, "\""}));
    }
    values[pair.substr(0, eq)] = pair.substr(eq + 1);
  }
  return values;
}

ModelPlacement readPlacement(const json& value, const std::string& key) {
  if (!value.is_object()) expected(key, "an object with a \"model\"", value);
  ModelPlacement p;
  const json* model = field(value, "model");
  if (!model) fail(key, "needs a \"model\"");
  p.model = resourceName(nonEmptyString(*model, member(key, "model")));
  for (const auto& [name, out] : {std::pair{"x", &p.x}, std::pair{"y", &p.y}}) {
    if (const json* v = field(value, name)) {
      *out = static_cast<int>(wholeNumber(*v, member(key, name), 0, 270));
      if (*out % 90 != 0) expected(member(key, name), "0, 90, 180 or 270", *v);
    }
  }
  if (const json* u = field(value, "uvlock")) p.uvlock = boolean(*u, member(key, "uvlock"));
  if (const json* w = field(value, "weight"))
    p.weight = static_cast<int>(wholeNumber(*w, member(key, "weight"), 1, 1 << 20));
  return p;
}

// A model, or a non-empty list of them to pick from by weight.
std::vector<ModelPlacement> readChoices(const json& value, const std::string& key) {
  std::vector<ModelPlacement> out;
  if (value.is_array()) {
    if (value.empty()) expected(key, "a model or a non-empty list of them", value);
    for (std::size_t i = 0; i < value.size(); ++i) out.push_back(readPlacement(value[i], element(key, i)));
  } else {
    out.push_back(readPlacement(value, key));
  }
  return out;
}

StateCondition readCondition(const json& value, const std::string& key) {
  if (!value.is_object()) expected(key, "an object", value);
  StateCondition c;
  for (const char* op : {"OR", "AND"}) {
    if (const json* list = field(value, op)) {
      if (value.size() != 1) fail(key, join({"\"", op, "\" stands alone"}));
      const std::string k = member(key, op);
      if (!list->is_array()) expected(k, "an array of conditions", *list);
      c.kind = std::string_view(op) == "OR" ? StateCondition::Kind::Or : StateCondition::Kind::And;
      for (std::size_t i = 0; i < list->size(); ++i)
        c.children.push_back(readCondition((*list)[i], element(k, i)));
      return c;
    }
  }
  c.kind = StateCondition::Kind::Values;
  for (const auto& [name, v] : value.items()) c.values[name] = split(scalarText(v, member(key, name)), '|');
  return c;
}

// SplitMix64's finaliser: the seed's bits spread over the whole word.
const ModelPlacement& pick(const std::vector<ModelPlacement>& choices, std::int64_t seed) {
  std::vector<int> weights;
  for (const ModelPlacement& c : choices) weights.push_back(c.weight);
  return choices[weightedPick(weights, seed)];
}

}  // namespace

bool StateCondition::holds(const StateValues& state) const {
  switch (kind) {
    case Kind::Always:
      return true;
    case Kind::Or:
      for (const StateCondition& c : children) {
        if (c.holds(state)) return true;
      }
      return false;
    case Kind::And:
      for (const StateCondition& c : children) {
        if (!c.holds(state)) return false;
      }
      return true;
    case Kind::Values:
      for (const auto& [name, allowed] : values) {
        const auto it = state.find(name);
        if (it == state.end() || std::find(allowed.begin(), allowed.end(), it->second) == allowed.end())
          return false;
      }
      return true;
  }
  return false;
}

BlockStates BlockStates::parse(const json& root, const std::string& file) {
  BlockStates out;
  try {
    if (!root.is_object()) expected("", "a JSON object", root);
    const json* variants = field(root, "variants");
    const json* multipart = field(root, "multipart");
    if (!variants == !multipart) fail("", "expected \"variants\" or \"multipart\" (one of them)");
    if (variants) {
      if (!variants->is_object() || variants->empty()) expected("variants", "a non-empty object", *variants);
      for (const auto& [key, value] : variants->items()) {
        const std::string k = member("variants", key);
        out.variants_.push_back({variantKey(key, k), readChoices(value, k)});
      }
    } else {
      if (!multipart->is_array()) expected("multipart", "an array", *multipart);
      for (std::size_t i = 0; i < multipart->size(); ++i) {
        const std::string k = element("multipart", i);
        const json& part = (*multipart)[i];
        if (!part.is_object()) expected(k, "an object", part);
        const json* apply = field(part, "apply");
        if (!apply) fail(k, "a part needs \"apply\"");
        Part p;
        if (const json* when = field(part, "when")) p.when = readCondition(*when, member(k, "when"));
        p.choices = readChoices(*apply, member(k, "apply"));
        out.parts_.push_back(std::move(p));
      }
    }
  } catch (const Error& e) {
    throw Error(withFile(file, e.what()));
  }
  return out;
}

std::string BlockStates::pathOf(const std::string& block) {
  return "assets/minecraft/blockstates/" + block + ".json";
}

BlockStates BlockStates::load(const PackStack& packs, const std::string& block) {
  const std::string path = pathOf(block);
  const auto found = packs.find(path);
  if (!found) throw Error(join({"no pack has the blockstates of ", block, " (", path, ")"}));
  const std::string file = found->pack->files().displayName(path);
  const std::vector<std::uint8_t> bytes = found->pack->files().require(path);
  return parse(parseJson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), file),
               file);
}

std::vector<ModelPlacement> BlockStates::select(const StateValues& state, glm::ivec3 pos) const {
  const std::int64_t seed = positionSeed(pos);
  std::vector<ModelPlacement> out;
  if (const Variant* v = variantOf(state)) {
    out.push_back(pick(v->choices, seed));
    return out;
  }
  for (const Part& p : parts_) {
    if (p.when.holds(state)) out.push_back(pick(p.choices, seed));
  }
  return out;
}

const BlockStates::Variant* BlockStates::variantOf(const StateValues& state) const {
  for (const Variant& v : variants_) {
    bool matches = true;
    for (const auto& [name, value] : v.when) {
      const auto it = state.find(name);
      matches = matches && it != state.end() && it->second == value;
    }
    if (matches) return &v;
  }
  return nullptr;
}

std::vector<ModelPlacement> BlockStates::choices(const StateValues& state) const {
  const Variant* v = variantOf(state);
  return v && v->choices.size() > 1 ? v->choices : std::vector<ModelPlacement>{};
}

namespace {
void namedBy(const StateCondition& c, std::set<std::string>& out) {
  for (const auto& [name, allowed] : c.values) out.insert(name);
  for (const StateCondition& child : c.children) namedBy(child, out);
}

void addValue(std::map<std::string, std::vector<std::string>>& out, const std::string& name,
              const std::string& value) {
  std::vector<std::string>& values = out[name];
  if (std::find(values.begin(), values.end(), value) == values.end()) values.push_back(value);
}

void valuesIn(const StateCondition& c, std::map<std::string, std::vector<std::string>>& out) {
  for (const auto& [name, allowed] : c.values)
    for (const std::string& value : allowed) addValue(out, name, value);
  for (const StateCondition& child : c.children) valuesIn(child, out);
}
}  // namespace

std::map<std::string, std::vector<std::string>> BlockStates::propertyValues() const {
  std::map<std::string, std::vector<std::string>> out;
  for (const Variant& v : variants_)
    for (const auto& [name, value] : v.when) addValue(out, name, value);
  for (const Part& p : parts_) valuesIn(p.when, out);
  return out;
}

StateValues BlockStates::firstVariant() const {
  return variants_.empty() ? StateValues{} : variants_.front().when;
}

std::set<std::string> BlockStates::properties() const {
  std::set<std::string> out;
  for (const Variant& v : variants_)
    for (const auto& [name, value] : v.when) out.insert(name);
  for (const Part& p : parts_) namedBy(p.when, out);
  return out;
}

std::vector<std::string> BlockStates::models() const {
  std::vector<std::string> out;
  const auto add = [&](const std::vector<ModelPlacement>& choices) {
    for (const ModelPlacement& c : choices) {
      if (std::find(out.begin(), out.end(), c.model) == out.end()) out.push_back(c.model);
    }
  };
  for (const Variant& v : variants_) add(v.choices);
  for (const Part& p : parts_) add(p.choices);
  return out;
}

}  // namespace terrasol
