#include "inventory.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace terrasol {
namespace {

std::string folded(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = c == '_' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool startsWithAny(std::string_view name, std::initializer_list<std::string_view> prefixes) {
  for (std::string_view p : prefixes)
    if (name.starts_with(p)) return true;
  return false;
}

bool endsWithAny(std::string_view name, std::initializer_list<std::string_view> suffixes) {
  for (std::string_view s : suffixes)
    if (name.ends_with(s)) return true;
  return false;
}

bool containsAny(std::string_view name, std::initializer_list<std::string_view> parts) {
  for (std::string_view p : parts)
    if (name.find(p) != std::string_view::npos) return true;
  return false;
}

bool isAny(std::string_view name, std::initializer_list<std::string_view> names) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

InventoryGroup groupOf(const BlockType& type) {
  const std::string_view n = type.name;
  // Ores, and flowers whose names read like a dye or a torch.
  if (n.ends_with("_ore") || containsAny(n, {"orchid", "petals", "torchflower"}) || n == "bush")
    return InventoryGroup::Natural;
  // Dyed blocks, and the undyed members of their families.
  if (startsWithAny(n, {"white_", "orange_", "magenta_", "light_blue_", "yellow_", "lime_", "pink_", "gray_",
                        "light_gray_", "cyan_", "purple_", "blue_", "brown_", "green_", "red_", "black_"}) &&
      !containsAny(n, {"mushroom", "tulip", "nether_brick", "sandstone", "sand", "glazed_terracotta_"}))
    return InventoryGroup::Coloured;
  if (isAny(n, {"terracotta", "glass", "glass_pane", "tinted_glass", "candle", "shulker_box", "candle_cake"}))
    return InventoryGroup::Coloured;
  // Redstone's parts.
  if (containsAny(n, {"redstone", "piston", "rail", "_button", "pressure_plate", "repeater", "comparator",
                      "observer", "dispenser", "dropper", "hopper", "lever", "daylight_detector", "tripwire",
                      "sculk_sensor", "lightning_rod", "copper_bulb", "trapped_chest", "crafter"}) ||
      isAny(n, {"target", "note_block", "tnt", "slime_block", "honey_block"}))
    return InventoryGroup::Redstone;
  // Work stations, storage, light and decorations.
  if (containsAny(n, {"table",
                      "furnace",
                      "smoker",
                      "stonecutter",
                      "loom",
                      "grindstone",
                      "lectern",
                      "composter",
                      "barrel",
                      "chest",
                      "anvil",
                      "brewing_stand",
                      "cauldron",
                      "bell",
                      "beacon",
                      "conduit",
                      "lodestone",
                      "respawn_anchor",
                      "campfire",
                      "lantern",
                      "torch",
                      "ladder",
                      "scaffolding",
                      "_sign",
                      "_bed",
                      "bookshelf",
                      "flower_pot",
                      "potted_",
                      "decorated_pot",
                      "_shelf",
                      "end_portal_frame",
                      "jukebox",
                      "spawner",
                      "vault",
                      "_skull",
                      "_head",
                      "chain",
                      "end_rod",
                      "golem_statue",
                      "command_block",
                      "structure_",
                      "jigsaw",
                      "test_",
                      "banner",
                      "froglight",
                      "glowstone",
                      "sea_lantern",
                      "dragon_egg",
                      "heavy_core",
                      "cake"}))
    return InventoryGroup::Functional;
  // Cut, laid and shaped stone and wood are building blocks wherever their material grows.
  if (containsAny(n, {"bricks",  "_tiles",    "polished_", "smooth_", "cut_",   "chiseled_", "_slab",
                      "_stairs", "_wall",     "_planks",   "_fence",  "_door",  "_trapdoor", "pillar",
                      "_wood",   "stripped_", "hyphae",    "mosaic",  "cobble", "mossy_"}))
    return InventoryGroup::Building;
  // Soils, ores, wood as it grows, plants, water's and the Nether's and the End's growths.
  if (type.shape == BlockShape::Cross || type.tint == Tint::Grass || type.tint == Tint::Foliage ||
      endsWithAny(n, {"_ore",    "_leaves", "_log",       "_stem",        "_sapling",   "_roots",  "_fungus",
                      "_nylium", "_coral",  "_coral_fan", "_coral_block", "_propagule", "_bud",    "_vines",
                      "_plant",  "_crop",   "_bush",      "_mushroom",    "_wart",      "_petals", "ice",
                      "_egg",    "_grass",  "_fern",      "_flower"}) ||
      containsAny(n, {"dirt",
                      "sand",
                      "gravel",
                      "clay",
                      "podzol",
                      "mycelium",
                      "mud",
                      "moss",
                      "dripstone",
                      "amethyst",
                      "snow",
                      "seagrass",
                      "kelp",
                      "lichen",
                      "sculk",
                      "mushroom",
                      "bamboo_sapling",
                      "cactus",
                      "sugar_cane",
                      "lily_pad",
                      "wheat",
                      "carrots",
                      "potatoes",
                      "beetroots",
                      "melon",
                      "pumpkin",
                      "hay_block",
                      "bone_block",
                      "obsidian",
                      "netherrack",
                      "basalt",
                      "blackstone",
                      "end_stone",
                      "bedrock",
                      "magma",
                      "soul_s",
                      "glow_lichen",
                      "cobweb",
                      "azalea",
                      "dripleaf",
                      "spore_blossom",
                      "frogspawn",
                      "sea_pickle",
                      "chorus",
                      "raw_",
                      "ancient_debris",
                      "calcite",
                      "tuff",
                      "deepslate",
                      "hanging_roots",
                      "leaf_litter",
                      "wildflowers",
                      "cocoa",
                      "fire",
                      "bee_nest",
                      "honeycomb",
                      "pale_hanging_moss",
                      "eyeblossom",
                      "resin_clump",
                      "dried_ghast"}) ||
      isAny(n, {"grass_block", "farmland", "dirt_path", "vine", "sponge", "wet_sponge", "water", "lava",
                "creaking_heart", "sunflower", "lilac", "rose_bush", "peony"}))
    return InventoryGroup::Natural;
  return InventoryGroup::Building;
}

bool matchesSearch(std::string_view name, std::string_view query) {
  const std::string haystack = folded(name), words = folded(query);
  for (std::size_t at = 0; at < words.size();) {
    const std::size_t end = std::min(words.find(' ', at), words.size());
    if (end > at && haystack.find(words.substr(at, end - at)) == std::string::npos) return false;
    at = end + 1;
  }
  return true;
}

}  // namespace terrasol
