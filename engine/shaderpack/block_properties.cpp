#include "shaderpack/block_properties.h"

#include <algorithm>
#include <charconv>
#include <sstream>

#include "core/error.h"

namespace terrasol {
namespace {

std::vector<std::string> split(std::string_view text, char by) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == by) {
      if (i > start) parts.emplace_back(text.substr(start, i - start));
      start = i + 1;
    }
  }
  return parts;
}

// "minecraft:oak_log:axis=x,y" and "oak_log:axis=x": the block's name and its property filters.
struct BlockMatcher {
  std::string name;
  std::vector<std::pair<std::string, std::vector<std::string>>> properties;
};

BlockMatcher matcherOf(const std::string& token, const std::string& where) {
  std::vector<std::string> parts = split(token, ':');
  if (parts.size() >= 2 && parts[0] == "minecraft" && parts[1].find('=') == std::string::npos)
    parts.erase(parts.begin());
  else if (parts.size() >= 2 && parts[1].find('=') == std::string::npos)
    parts.erase(parts.begin());  // another namespace ("mod:block"): the name alone is matched
  BlockMatcher m{parts.empty() ? std::string() : parts[0], {}};
  for (std::size_t i = 1; i < parts.size(); ++i) {
    const auto eq = parts[i].find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == parts[i].size())
      throw Error(where + ": '" + token + "': expected property=value after the block's name");
    m.properties.push_back({parts[i].substr(0, eq), split(std::string_view(parts[i]).substr(eq + 1), ',')});
  }
  return m;
}

bool matches(const BlockMatcher& m, const StateValues& values) {
  for (const auto& [property, allowed] : m.properties) {
    const auto found = values.find(property);
    if (found == values.end() || std::find(allowed.begin(), allowed.end(), found->second) == allowed.end())
      return false;
  }
  return true;
}

}  // namespace

int BlockIdMap::mappedStates() const {
  return static_cast<int>(std::count_if(ids.begin(), ids.end(), [](int id) { return id >= 0; }));
}

BlockIdMap parseBlockProperties(std::string_view text, const std::string& file, PackMacros macros,
                                const BlockRegistry& blocks) {
  BlockIdMap map{std::vector<int>(blocks.size(), -1), {}};
  for (const KeptLine& kept : propertyLines(text, file, macros)) {
    const std::string& line = kept.text;
    const std::string where = file + ":" + std::to_string(kept.number);
    const auto eq = line.find('=');
    if (line.empty() || eq == std::string::npos || !line.starts_with("block.")) continue;  // other keys
    const std::string key = line.substr(6, eq - 6);
    int id = 0;
    const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), id);
    if (ec != std::errc() || end != key.data() + key.size())
      throw Error(where + ": 'block." + key + "': the id is not a number");
    std::istringstream names(line.substr(eq + 1));
    for (std::string token; names >> token;) {
      const BlockMatcher m = matcherOf(token, where);
      bool found = false;
      const BlockId first = blocks.find(m.name, &found);
      if (!found) {
        if (std::find(map.unknown.begin(), map.unknown.end(), m.name) == map.unknown.end())
          map.unknown.push_back(m.name);
        continue;
      }
      const BlockType& type = blocks[first];
      for (BlockId s = type.firstState; s < type.firstState + type.stateCount; ++s) {
        int& slot = map.ids[s];
        if (slot < 0 && (m.properties.empty() || matches(m, blocks.stateValues(s)))) slot = id;
      }
    }
  }
  return map;
}

}  // namespace terrasol
