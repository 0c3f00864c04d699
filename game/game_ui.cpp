#include "game_ui.h"

#include "game_renderer.h"
#include "inventory.h"

namespace terrasol {
namespace {

// The inventory icon of `state`'s block (an empty texture where it has none).
ItemIcon iconOf(GameRenderer& renderer, BlockId state, const std::string& name) {
  ItemIcon item;
  item.name = name;
  if (const auto icon = renderer.iconOf(state)) {
    const BlockIcons& icons = renderer.icons();
    const glm::vec4 uv = icons.uv(*icon);
    item.texture = icons.texture();
    item.u0 = uv.x, item.v0 = uv.y, item.u1 = uv.z, item.v1 = uv.w;
  }
  return item;
}

std::vector<ItemIcon> hotbarIcons(GameRenderer& renderer, const Hotbar& hotbar) {
  std::vector<ItemIcon> slots;
  for (const BlockId state : hotbar.slots())
    slots.push_back(iconOf(renderer, state, renderer.blocks()[state].name));
  return slots;
}

}  // namespace

GameUi::GameUi(GLFWwindow* window, SettingsFile& settings, std::string selectedProp)
    : settings_(settings), hud_(window), selectedProp_(std::move(selectedProp)) {}

bool GameUi::takeKey(int key) {
  if (!menu_.takeKey(key, settings_.values)) return false;
  settings_.save();
  return true;
}

void GameUi::crosshairAndHotbar(GameRenderer& renderer, const Hotbar& hotbar) {
  hud_.crosshair();
  hud_.hotbar(hotbarIcons(renderer, hotbar), hotbar.selected());
}

MenuResult GameUi::menu(const std::vector<std::string>& loadedPacks, const ShaderPackChoices& shaderPacks,
                        const std::vector<std::string>& propFiles) {
  const MenuResult r = menu_.draw(settings_.values, loadedPacks, shaderPacks, propFiles, selectedProp_);
  if (r.prop) selectedProp_ = *r.prop;
  return r;
}

void GameUi::inventory(GameRenderer& renderer, Hotbar& hotbar) {
  std::vector<ItemIcon> items;
  for (const BlockId state : renderer.iconStates()) {
    items.push_back(iconOf(renderer, state, renderer.blocks()[state].name));
    items.back().group = static_cast<int>(groupOf(renderer.blocks()[state]));
  }
  const InventoryScreen::Result r = inventory_.draw(items, hotbarIcons(renderer, hotbar), hotbar.selected());
  if (r.select) hotbar.select(*r.select);
  if (r.place) hotbar.put(r.place->first, renderer.iconStates()[r.place->second]);
}

}  // namespace terrasol
