#pragma once
// Which folder the game plays: a Terrasol world is its own folder; a Minecraft save is opened
// read-only, its edits kept in an overlay folder beside the game's worlds (never inside the save),
// named after the save and its path so reopening the save finds them.

#include <filesystem>

namespace terrasol {

struct WorldChoice {
  std::filesystem::path dir;        // the Terrasol world folder the game saves into
  std::filesystem::path minecraft;  // the Minecraft save it overlays, or empty
};

// A folder without level.json that holds Minecraft's level.dat or region files.
bool isMinecraftSave(const std::filesystem::path& path);

// `worlds`: where the game's worlds are (the overlay goes there).
WorldChoice chooseWorld(const std::filesystem::path& path, const std::filesystem::path& worlds);

}  // namespace terrasol
