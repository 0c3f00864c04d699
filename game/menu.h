#pragma once
// The Esc menu: settings (applied live by the game from what draw() reports), resource packs, key
// bindings and the props to place. Draws with ImGui inside the HUD's frame.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "settings.h"

namespace terrasol {

// What the Shader packs tab shows: the packs found, and the chosen one's error when it failed.
struct ShaderPackChoices {
  std::vector<std::filesystem::path> found;
  std::string error;
};

// What the player did in the menu this frame.
struct MenuResult {
  bool resume = false, save = false, quit = false;
  bool viewChanged = false;         // view distance
  bool rendererChanged = false;     // shadow settings: new shader variants and maps
  bool packsChanged = false;        // reload the packs
  bool shaderPackChanged = false;   // draw with settings.shaderpack (or Terrasol's pipeline) from now on
  bool soundChanged = false;        // volumes: heard while the slider moves
  bool settingsChanged = false;     // anything: save the settings file
  std::optional<std::string> prop;  // the prop model chosen in the Props tab
};

class Menu {
 public:
  // `propFiles`: models the Props tab offers; `selectedProp`: the one the place-prop key places.
  MenuResult draw(GameSettings& settings, const std::vector<std::string>& loadedPacks,
                  const ShaderPackChoices& shaderPacks, const std::vector<std::string>& propFiles,
                  const std::string& selectedProp);
  // While the menu waits for a key to bind, the game hands key presses here first; true when taken.
  bool takeKey(int key, GameSettings& settings);
  // What the Sound tab says of the device ("OpenAL Soft, 247 voices", or that the game is silent).
  void setSoundDevice(std::string text) { soundDevice_ = std::move(text); }

 private:
  void settingsTab(GameSettings& settings, MenuResult& out);
  void packsTab(GameSettings& settings, const std::vector<std::string>& loadedPacks, MenuResult& out);
  void shaderPacksTab(GameSettings& settings, const ShaderPackChoices& packs, MenuResult& out);
  void keysTab(GameSettings& settings);
  void soundTab(GameSettings& settings, MenuResult& out);
  void propsTab(const std::vector<std::string>& files, const std::string& selected, MenuResult& out);

  std::optional<Action> rebinding_;
  std::string newPack_;
  std::string soundDevice_;
};

}  // namespace terrasol
