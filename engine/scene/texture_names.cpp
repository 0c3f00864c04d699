#include "scene/texture_names.h"

#include <algorithm>

namespace terrasol {
namespace {

constexpr std::pair<std::string_view, std::string_view> kRenamedTextures[] = {
    {"dirt_path_top", "grass_path_top"},  // 1.17
    {"dirt_path_side", "grass_path_side"},
    {"short_grass", "grass"},  // 1.20.3
    {"sugar_cane", "reeds"},   // 1.13
    {"nether_portal", "portal"},
    {"tripwire", "trip_wire"},
    {"lily_pad", "waterlily"},
    {"iron_chain", "chain"}};  // 1.21.9

}  // namespace

std::span<const std::pair<std::string_view, std::string_view>> renamedTextures() {
  return kRenamedTextures;
}

std::vector<std::string> withOlderNames(const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const std::string& name : names) {
    out.push_back(name);
    for (const auto& [now, old] : kRenamedTextures)
      if (name == now && std::find(names.begin(), names.end(), old) == names.end()) out.emplace_back(old);
  }
  return out;
}

std::vector<std::string> candidatesOf(const std::string& texture) {
  const std::string prefix = "block/";
  return withOlderNames(
      {texture.compare(0, prefix.size(), prefix) == 0 ? texture.substr(prefix.size()) : texture});
}

}  // namespace terrasol
