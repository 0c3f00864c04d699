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

void Game::setMenu(bool open) {
  menuOpen_ = open;
  controls_.releaseAll();
  cursorKnown_ = false;
  GLFWwindow* w = window_.handle();
  glfwSetInputMode(w, GLFW_CURSOR, open ? GLFW_CURSOR_NORMAL : GLFW_CURSOR_DISABLED);
  if (!open && glfwRawMouseMotionSupported()) glfwSetInputMode(w, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
}

void Game::drawHud() {
  hud_->beginFrame();
  if (showHud_ && !menuOpen_) {
    hud_->crosshair();
    std::vector<Hud::Slot> slots;
    const BlockAssets& assets = renderer_.assets();
    const GLuint icons = renderer_.iconTexture();
    for (BlockId id : hotbar_) {
      Hud::Slot slot;
      slot.name = blocks_[id].name;
      slot.texture = icons;
      const int face = blocks_[id].shape == BlockShape::Cube ? static_cast<int>(Direction::Up) : 0;
      const int texture = assets.atlas.textureOf(id, face);
      const Atlas& atlas = assets.atlas.atlas;
      if (texture >= 0 && static_cast<std::size_t>(texture) < atlas.textures.size()) {
        const glm::vec4 rect = atlas.tileRect(atlas.textures[static_cast<std::size_t>(texture)].firstTile);
        slot.u0 = rect.x, slot.v0 = rect.y, slot.u1 = rect.z, slot.v1 = rect.w;
      }
      const glm::vec3 colour = tintColour(assets.colormaps, blocks_[id].tint);
      slot.r = colour.r, slot.g = colour.g, slot.b = colour.b;
      slots.push_back(std::move(slot));
    }
    hud_->hotbar(slots, selected_);
  }
  if (showOverlay_) hud_->overlay(overlayLeft(), overlayRight());
  if (menuOpen_) applyMenu(hud_->menu(settings_, renderer_.assets().packNames, propFiles(), selectedProp_));
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
  if (r.resume) setMenu(false);
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
