#include "game_session.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <exception>
#include <string>

#include "core/error.h"
#include "core/log.h"
#include "hud.h"
#include "platform/glfw/glfw_window.h"

// The HUD and the menu, and what the menu changes: settings, packs, saves.

namespace terrasol::session {

void Game::setScreens(bool menu, bool inventory) {
  menuOpen_ = menu;
  inventoryOpen_ = inventory;
  const bool open = screenOpen();
  controls_.releaseAll();
  cursorKnown_ = false;
  GLFWwindow* w = window_.handle();
  glfwSetInputMode(w, GLFW_CURSOR, open ? GLFW_CURSOR_NORMAL : GLFW_CURSOR_DISABLED);
  if (!open && glfwRawMouseMotionSupported()) glfwSetInputMode(w, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
}

Hud::Slot Game::slotOf(BlockId state) {
  Hud::Slot slot;
  slot.name = blocks_[state].name;
  if (const auto icon = renderer_.iconOf(state)) {
    const BlockIcons& icons = renderer_.icons();
    const glm::vec4 uv = icons.uv(*icon);
    slot.texture = icons.texture();
    slot.u0 = uv.x, slot.v0 = uv.y, slot.u1 = uv.z, slot.v1 = uv.w;
  }
  return slot;
}

std::vector<Hud::Slot> Game::hotbarSlots() {
  std::vector<Hud::Slot> slots;
  for (const BlockId state : hotbar_) slots.push_back(slotOf(state));
  return slots;
}

void Game::drawHud() {
  hud_->beginFrame();
  if (showHud_ && !screenOpen()) {
    hud_->crosshair();
    hud_->hotbar(hotbarSlots(), selected_);
  }
  if (showOverlay_) hud_->overlay(overlayLeft(), overlayRight(), {frameGraph_.begin(), frameGraph_.end()});
  if (menuOpen_) applyMenu(hud_->menu(settings_, renderer_.assets().packNames, propFiles(), selectedProp_));
  if (inventoryOpen_) {
    std::vector<Hud::Slot> items;
    for (const BlockId state : renderer_.iconStates()) items.push_back(slotOf(state));
    const Hud::InventoryResult r = hud_->inventory(items, hotbarSlots(), selected_);
    if (r.select) selected_ = *r.select;
    if (r.place) hotbar_[static_cast<std::size_t>(r.place->first)] = renderer_.iconStates()[r.place->second];
  }
  hud_->endFrame();
}

void Game::applyMenu(const MenuResult& r) {
  if (r.viewChanged) world_.setViewDistance(settings_.viewDistance);
  if (r.rendererChanged) renderer_.applySettings(settings_);
  if (r.packsChanged) reloadPacks();
  if (r.settingsChanged) {
    window_.setVsync(settings_.vsync);
    saveSettings(settingsFile_, settings_);
  }
  if (r.prop) selectedProp_ = *r.prop;
  if (r.save) save();
  if (r.resume) setScreens(false, false);
  if (r.quit) quit_ = true;
}

void Game::reloadPacks() {
  try {
    std::unique_ptr<BlockAssets> assets = renderer_.loadPacks(settings_.packs);
    world_.remeshAll(assets->table);
    renderer_.commit(std::move(assets));
    for (const PackProblem& p : renderer_.assets().atlas.problems) logWarning(p.message);
  } catch (const Error& e) {
    logError(std::string("packs not reloaded: ") + e.what());  // the old ones stay
  }
}

void Game::save() {
  Level& level = world_.level();
  level.playerPosition = player_.position();
  level.playerYaw = player_.yaw;
  level.playerPitch = player_.pitch;
  level.playerFlying = player_.flying;
  level.props = props_->level();
  try {
    world_.save();
    logInfo("saved " + world_.dir().string());
  } catch (const std::exception& e) {
    logError(std::string("saving failed: ") + e.what());
  }
  sinceSave_ = 0.0;
}

}  // namespace terrasol::session
