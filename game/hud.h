#pragma once
// The HUD and menus, drawn with Dear ImGui over the finished frame: crosshair, hotbar, the F3 debug
// overlay, the Esc menu with the settings (applied live by the game from what menu() reports) and
// the creative inventory (E).

#include <optional>
#include <string>
#include <utility>
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
  std::optional<std::string> prop;  // the prop model chosen in the Props tab
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
  // A hotbar slot or inventory item: the block's name and its icon (a cell of `texture`, from
  // (u0, v0) at its top left to (u1, v1), tinted).
  struct Slot {
    std::string name;
    unsigned texture = 0;
    float u0 = 0, v0 = 0, u1 = 0, v1 = 0;
    float r = 1, g = 1, b = 1;
  };
  void hotbar(const std::vector<Slot>& slots, int selected);
  // The F3 panels; under the left one, the last frames' times as a graph (ms, oldest first).
  void overlay(const std::vector<std::string>& left, const std::vector<std::string>& right,
               const std::vector<float>& frameMs = {});
  // `propFiles`: models the Props tab offers; `selectedProp`: the one the place-prop key places.
  MenuResult menu(GameSettings& settings, const std::vector<std::string>& loadedPacks,
                  const std::vector<std::string>& propFiles, const std::string& selectedProp);
  void endFrame();  // draws into the bound framebuffer

  // What the player did in the inventory this frame.
  struct InventoryResult {
    std::optional<std::pair<int, std::size_t>> place;  // put item `second` into hotbar slot `first`
    std::optional<int> select;                          // a hotbar slot clicked
  };
  // Every item as an icon, found by a search field; clicking one puts it into the selected hotbar
  // slot, dragging one onto a hotbar slot (shown below them) puts it there.
  InventoryResult inventory(const std::vector<Slot>& items, const std::vector<Slot>& hotbar, int selected);
  // A text field has the keyboard: letters are typing, not game keys.
  bool typing() const;

  // While the menu waits for a key to bind, the game hands key presses here first; true when taken.
  bool takeKey(int key, GameSettings& settings);

 private:
  void settingsTab(GameSettings& settings, MenuResult& out);
  void packsTab(GameSettings& settings, const std::vector<std::string>& loadedPacks, MenuResult& out);
  void keysTab(GameSettings& settings);
  void propsTab(const std::vector<std::string>& files, const std::string& selected, MenuResult& out);

  std::optional<Action> rebinding_;
  std::string newPack_;
  std::string search_;  // the inventory's, kept while it is closed
};

}  // namespace terrasol
