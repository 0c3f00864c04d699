#pragma once
// The HUD and menus, drawn with Dear ImGui over the finished frame: crosshair, hotbar, the F3 debug
// overlay, and the Esc menu with the settings (applied live by the game from what menu() reports).

#include <optional>
#include <string>
#include <vector>

#include "settings.h"

struct GLFWwindow;

namespace terrasol {

// What the player did in the menu this frame.
struct MenuResult {
  bool resume = false, save = false, quit = false;
  bool viewChanged = false;      // view distance
  bool rendererChanged = false;  // shadow settings: new shader variants and maps
  bool packsChanged = false;     // reload the packs
  bool settingsChanged = false;  // anything: save the settings file
};

class Hud {
 public:
  // Installs ImGui's GLFW callbacks after the game's own (it chains to them).
  explicit Hud(GLFWwindow* window);
  ~Hud();
  Hud(const Hud&) = delete;
  Hud& operator=(const Hud&) = delete;

  void beginFrame();
  void crosshair();
  void hotbar(const std::vector<std::string>& slots, int selected);
  void overlay(const std::vector<std::string>& left, const std::vector<std::string>& right);
  MenuResult menu(GameSettings& settings, const std::vector<std::string>& loadedPacks);
  void endFrame();  // draws into the bound framebuffer

  // While the menu waits for a key to bind, the game hands key presses here first; true when taken.
  bool takeKey(int key, GameSettings& settings);

 private:
  void settingsTab(GameSettings& settings, MenuResult& out);
  void packsTab(GameSettings& settings, const std::vector<std::string>& loadedPacks, MenuResult& out);
  void keysTab(GameSettings& settings);

  std::optional<Action> rebinding_;
  std::string newPack_;
};

}  // namespace terrasol
