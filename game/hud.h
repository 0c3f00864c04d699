#pragma once
// The HUD, drawn with Dear ImGui over the finished frame: crosshair, hotbar and the F3 debug overlay.
// Owns ImGui's context for the window; the menu and the inventory (menu.h, inventory_screen.h) draw
// between beginFrame() and endFrame().

#include <string>
#include <vector>

#include "item_icon.h"

struct GLFWwindow;

namespace terrasol {

class Hud {
 public:
  // Installs ImGui's GLFW callbacks after the game's own (it chains to them).
  explicit Hud(GLFWwindow* window);
  ~Hud();
  Hud(const Hud&) = delete;
  Hud& operator=(const Hud&) = delete;

  void beginFrame();
  void crosshair();
  void hotbar(const std::vector<ItemIcon>& slots, int selected);
  // The F3 panels; under the left one, the last frames' times as a graph (ms, oldest first).
  void overlay(const std::vector<std::string>& left, const std::vector<std::string>& right,
               const std::vector<float>& frameMs = {});
  // One line at the top of the screen (what the world is, once when it opens).
  void notice(const std::string& text);
  // One line in the middle of the screen (the loading screen's).
  void centred(const std::string& text);
  void endFrame();  // draws into the bound framebuffer
};

}  // namespace terrasol
