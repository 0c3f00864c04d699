#include "world/block_sounds.h"

#include "world/block_sound_rules.h"

namespace terrasol {
namespace {

// Minecraft's sound types, each with the plain group it is closest to.
constexpr SoundGroup kGroups[] = {
    {"stone", "stone"},
    {"wood", "wood"},
    {"gravel", "gravel"},
    {"grass", "grass"},
    {"sand", "sand"},
    {"snow", "snow"},
    {"glass", "glass"},
    {"metal", "metal"},
    {"wool", "wool"},
    {"slime_block", "slime_block"},
    {"mud", "mud"},
    {"amethyst_block", "amethyst_block"},
    {"netherrack", "netherrack"},
    {"empty", "empty"},
    // stone-like
    {"deepslate", "stone"},
    {"deepslate_bricks", "stone"},
    {"deepslate_tiles", "stone"},
    {"polished_deepslate", "stone"},
    {"tuff", "stone"},
    {"tuff_bricks", "stone"},
    {"polished_tuff", "stone"},
    {"calcite", "stone"},
    {"dripstone_block", "stone"},
    {"pointed_dripstone", "stone"},
    {"basalt", "stone"},
    {"bone_block", "stone"},
    {"coral_block", "stone"},
    {"lodestone", "stone"},
    {"gilded_blackstone", "stone"},
    {"decorated_pot", "stone"},
    {"mud_bricks", "stone"},
    {"packed_mud", "gravel"},
    {"resin_bricks", "stone"},
    {"nether_bricks", "netherrack"},
    {"nether_ore", "netherrack"},
    {"nether_gold_ore", "netherrack"},
    {"soul_sand", "sand"},
    {"soul_soil", "sand"},
    {"suspicious_sand", "sand"},
    {"suspicious_gravel", "gravel"},
    {"rooted_dirt", "gravel"},
    {"powder_snow", "snow"},
    // wood-like
    {"cherry_wood", "wood"},
    {"bamboo_wood", "wood"},
    {"nether_wood", "wood"},
    {"stem", "wood"},
    {"ladder", "wood"},
    {"scaffolding", "wood"},
    {"chiseled_bookshelf", "wood"},
    {"hanging_sign", "wood"},
    {"bamboo", "wood"},
    // plants and soft ground
    {"wet_grass", "grass"},
    {"crop", "grass"},
    {"hard_crop", "grass"},
    {"vine", "grass"},
    {"cave_vines", "grass"},
    {"weeping_vines", "grass"},
    {"glow_lichen", "grass"},
    {"sweet_berry_bush", "grass"},
    {"nether_wart", "grass"},
    {"nether_sprouts", "grass"},
    {"roots", "grass"},
    {"hanging_roots", "grass"},
    {"fungus", "grass"},
    {"nylium", "netherrack"},
    {"wart_block", "wool"},
    {"shroomlight", "wool"},
    {"azalea", "grass"},
    {"flowering_azalea", "grass"},
    {"azalea_leaves", "grass"},
    {"cherry_leaves", "grass"},
    {"cherry_sapling", "grass"},
    {"bamboo_sapling", "grass"},
    {"spore_blossom", "grass"},
    {"big_dripleaf", "grass"},
    {"small_dripleaf", "grass"},
    {"pink_petals", "grass"},
    {"leaf_litter", "grass"},
    {"lily_pad", "grass"},
    {"moss", "wool"},
    {"moss_carpet", "wool"},
    {"sculk", "mud"},
    {"sculk_vein", "mud"},
    {"sculk_sensor", "mud"},
    {"sculk_catalyst", "mud"},
    {"sculk_shrieker", "mud"},
    {"mangrove_roots", "wood"},
    {"muddy_mangrove_roots", "mud"},
    {"frogspawn", "slime_block"},
    {"froglight", "wool"},
    {"sponge", "wool"},
    {"wet_sponge", "mud"},
    {"cobweb", "wool"},
    {"candle", "wool"},
    {"resin", "slime_block"},
    {"honey_block", "slime_block"},
    // metal-like
    {"anvil", "metal"},
    {"chain", "metal"},
    {"lantern", "metal"},
    {"copper", "metal"},
    {"copper_bulb", "metal"},
    {"copper_grate", "metal"},
    {"iron", "metal"},
    {"netherite_block", "metal"},
    {"ancient_debris", "stone"},
    {"heavy_core", "metal"},
    {"vault", "metal"},
    {"trial_spawner", "metal"},
    {"spawner", "metal"},
    {"amethyst_cluster", "amethyst_block"},
};

const SoundGroup& group(std::string_view name) {
  for (const SoundGroup& g : kGroups) {
    if (g.name == name) return g;
  }
  return kGroups[0];  // never for the rules: a test checks each names a group
}

std::string_view bare(std::string_view name) {
  if (name.starts_with("minecraft:")) name.remove_prefix(10);
  return name;
}

}  // namespace

std::span<const SoundGroup> soundGroups() {
  return kGroups;
}

const SoundGroup& blockSoundGroup(std::string_view name) {
  name = bare(name);
  for (const SoundRule& r : blockSoundRules()) {
    if (r.matches(name)) return group(r.group);
  }
  return kGroups[0];
}

std::string_view openSoundKind(std::string_view name) {
  name = bare(name);
  const bool door = name.ends_with("_door"), trapdoor = name.ends_with("_trapdoor");
  if (name.ends_with("fence_gate")) return "fence_gate";
  if (!door && !trapdoor) return {};
  const bool metal = name.find("iron") != std::string_view::npos;
  const bool copper = name.find("copper") != std::string_view::npos;
  if (door) return metal ? "iron_door" : copper ? "copper_door" : "wooden_door";
  return metal ? "iron_trapdoor" : copper ? "copper_trapdoor" : "wooden_trapdoor";
}

}  // namespace terrasol
