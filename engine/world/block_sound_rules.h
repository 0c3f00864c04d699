#pragma once
// The families by name that give each block its sound group (world/block_sounds.h): Minecraft's
// assignments written as rules over block names, first match wins, particular blocks before their
// families and families before materials ("deepslate_iron_ore" is deepslate's before it is an ore).

#include <span>
#include <string_view>

namespace terrasol {

struct SoundRule {
  enum class Match { Exact, Prefix, Suffix, Contains };
  Match match;
  std::string_view text, group;

  bool matches(std::string_view name) const {
    switch (match) {
      case Match::Exact:
        return name == text;
      case Match::Prefix:
        return name.starts_with(text);
      case Match::Suffix:
        return name.ends_with(text);
      case Match::Contains:
        return name.find(text) != std::string_view::npos;
    }
    return false;
  }
};

// In the order they are tried; names without "minecraft:".
std::span<const SoundRule> blockSoundRules();

}  // namespace terrasol
