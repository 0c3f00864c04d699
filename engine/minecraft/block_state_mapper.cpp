#include "minecraft/block_state_mapper.h"

#include "minecraft/data_versions.h"

namespace terrasol {
namespace {

// Names that meant another block before a version (by DataVersion); later names never come back
// with an older meaning, so only names reused for something new need the version.
struct Rename {
  std::string_view before, now;
  int until;  // chunks older than this DataVersion use `before` for `now`
};
constexpr Rename kRenames[] = {
    {"stone_slab", "smooth_stone_slab", kDataVersion1_14},  // 1.14 added a new stone_slab
    {"sign", "oak_sign", kDataVersion1_14},
    {"wall_sign", "oak_wall_sign", kDataVersion1_14},
};

std::string_view withoutNamespace(std::string_view name) {
  constexpr std::string_view kMinecraft = "minecraft:";
  return name.starts_with(kMinecraft) ? name.substr(kMinecraft.size()) : name;
}

}  // namespace

BlockStateMapper::BlockStateMapper(const BlockRegistry& blocks, BlockId placeholder)
    : blocks_(blocks), placeholder_(placeholder) {}

MappedState BlockStateMapper::map(std::string_view name, const StateProperties& properties, int dataVersion) {
  std::string key(name);
  // The renames' eras: names read alike within one.
  key += dataVersion < kDataVersion1_14 ? "@1.13" : dataVersion < kDataVersion1_17 ? "@1.14" : "";
  for (const auto& [k, v] : properties) key.append("|").append(k).append("=").append(v);
  if (const auto it = cache_.find(key); it != cache_.end()) return it->second;
  const MappedState mapped = resolve(name, properties, dataVersion);
  cache_.emplace(std::move(key), mapped);
  return mapped;
}

MappedState BlockStateMapper::resolve(std::string_view fullName, const StateProperties& properties,
                                      int dataVersion) const {
  if (fullName.find(':') != std::string_view::npos && !fullName.starts_with("minecraft:"))
    return {placeholder_, false, 0};  // another namespace: a mod's block
  std::string name(withoutNamespace(fullName));
  if (name == "air" || name == "cave_air" || name == "void_air") return {kAir, true, 0};
  for (const Rename& r : kRenames)
    if (name == r.before && dataVersion < r.until) name = r.now;
  // Before 1.17 a cauldron held water by its level; since, a filled one is water_cauldron.
  const bool oldCauldron = name == "cauldron" && dataVersion < kDataVersion1_17;
  if (oldCauldron) {
    for (const auto& [k, v] : properties)
      if (k == "level" && v != "0") name = "water_cauldron";
  }
  bool found = false;
  const BlockId base = blocks_.find(name, &found);
  if (!found) return {placeholder_, false, 0};
  MappedState out{base, true, 0};
  for (const auto& [k, v] : properties) {
    if (oldCauldron && k == "level" && name == "cauldron") continue;  // said by the name
    if (const auto next = blocks_.with(out.id, k, v))
      out.id = *next;
    else
      ++out.droppedProperties;
  }
  return out;
}

}  // namespace terrasol
