#pragma once
// The game's screens over the picture: the HUD (crosshair, hotbar; F1 hides it), the F3 panels, the
// Esc menu and the inventory, with the block icons they show. Takes keys for the menu's rebinding
// before the game does (InputRouter's ScreenKeys).

#include <string>
#include <vector>

#include "hotbar.h"
#include "hud.h"
#include "input_router.h"
#include "inventory_screen.h"
#include "menu.h"
#include "settings.h"

struct GLFWwindow;

namespace terrasol {

class GameRenderer;

class GameUi final : public ScreenKeys {
 public:
  GameUi(GLFWwindow* window, SettingsFile& settings, std::string selectedProp);

  bool takeKey(int key) override;  // a new binding is saved at once
  bool typing() const override { return inventory_.typing(); }

  bool hudShown() const { return hudShown_; }
  void toggleHud() { hudShown_ = !hudShown_; }
  void showHud() { hudShown_ = true; }
  // The model the place-prop key places, as chosen in the menu's Props tab.
  const std::string& selectedProp() const { return selectedProp_; }

  // One frame's ImGui, between these two.
  void begin() { hud_.beginFrame(); }
  void end() { hud_.endFrame(); }
  void crosshairAndHotbar(GameRenderer& renderer, const Hotbar& hotbar);
  void overlay(const std::vector<std::string>& left, const std::vector<std::string>& right,
               const std::vector<float>& frameMs) {
    hud_.overlay(left, right, frameMs);
  }
  // Shows `text` at the top of the screen for the next `seconds` (`now`: glfwGetTime's clock).
  void showNotice(std::string text, double now, double seconds) {
    notice_ = std::move(text);
    noticeUntil_ = now + seconds;
  }
  void loading(const std::string& text) { hud_.centred(text); }
  void notice(double now) {
    if (!notice_.empty() && now < noticeUntil_) hud_.notice(notice_);
  }
  MenuResult menu(const std::vector<std::string>& loadedPacks, const ShaderPackChoices& shaderPacks,
                  const std::vector<std::string>& propFiles);
  void inventory(GameRenderer& renderer, Hotbar& hotbar);
  void setSoundDevice(std::string text) { menu_.setSoundDevice(std::move(text)); }

 private:
  SettingsFile& settings_;
  Hud hud_;
  Menu menu_;
  InventoryScreen inventory_;
  bool hudShown_ = true;
  std::string notice_;
  double noticeUntil_ = 0.0;
  std::string selectedProp_;
};

}  // namespace terrasol
