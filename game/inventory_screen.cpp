#include "inventory_screen.h"

#include <imgui.h>

#include <algorithm>
#include <cstdint>

#include "inventory.h"

namespace terrasol {
namespace {

ImTextureID textureOf(const ItemIcon& s) {
  return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(s.texture));
}

// The slot's icon as a button; true when clicked.
bool iconButton(const ItemIcon& s, float size) {
  if (s.texture == 0) return ImGui::Button("##empty", {size, size});
  return ImGui::ImageButton(textureOf(s), {size, size}, {s.u0, s.v0}, {s.u1, s.v1}, 2, {0, 0, 0, 0},
                            {s.r, s.g, s.b, 1.0f});
}

constexpr const char* kPayload = "TERRASOL_ITEM";

}  // namespace

bool InventoryScreen::typing() const {
  return ImGui::GetIO().WantTextInput;
}

InventoryScreen::Result InventoryScreen::draw(const std::vector<ItemIcon>& items,
                                              const std::vector<ItemIcon>& hotbar, int selected) {
  Result out;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float cell = std::clamp(display.y / 16.0f, 28.0f, 48.0f);
  ImGui::SetNextWindowPos({display.x * 0.5f, display.y * 0.5f}, ImGuiCond_Always, {0.5f, 0.5f});
  ImGui::SetNextWindowSize(
      {std::min(display.x - 20.0f, cell * 14.0f), std::min(display.y - 20.0f, cell * 12.0f)},
      ImGuiCond_Always);
  if (ImGui::Begin("Blocks", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
    // Not focused on opening: the key that opened the inventory closes it again unless the player
    // clicks into the search first (then letters type).
    char buffer[128] = {};
    search_.copy(buffer, sizeof buffer - 1);
    if (ImGui::InputTextWithHint("##search", "Search blocks", buffer, sizeof buffer)) search_ = buffer;
    // Minecraft's tabs; a search looks through every tab, as Minecraft's search tab does.
    if (ImGui::BeginTabBar("##groups")) {
      if (ImGui::BeginTabItem("All")) {
        group_ = -1;
        ImGui::EndTabItem();
      }
      for (int g = 0; g < static_cast<int>(kInventoryGroups.names.size()); ++g) {
        const std::string label(kInventoryGroups.names[static_cast<std::size_t>(g)]);
        if (ImGui::BeginTabItem(label.c_str())) {
          group_ = g;
          ImGui::EndTabItem();
        }
      }
      ImGui::EndTabBar();
    }

    const ImGuiStyle& style = ImGui::GetStyle();
    const float button = cell + 2.0f * 2.0f + style.ItemSpacing.x;  // icon, frame padding, spacing
    const float footer = cell + 4.0f + style.ItemSpacing.y * 2.0f + style.WindowPadding.y + 8.0f;
    ImGui::BeginChild("##items", {0.0f, -footer});
    const int columns =
        std::max(1, static_cast<int>((ImGui::GetContentRegionAvail().x + style.ItemSpacing.x) / button));
    int shown = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (!matchesSearch(items[i].name, search_)) continue;
      if (search_.empty() && group_ >= 0 && items[i].group != group_) continue;
      if (shown++ % columns != 0) ImGui::SameLine();
      ImGui::PushID(static_cast<int>(i));
      if (iconButton(items[i], cell)) out.place = {{selected, i}};
      if (ImGui::BeginDragDropSource()) {
        ImGui::SetDragDropPayload(kPayload, &i, sizeof i);
        ImGui::Image(textureOf(items[i]), {cell, cell}, {items[i].u0, items[i].v0},
                     {items[i].u1, items[i].v1});
        ImGui::EndDragDropSource();
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", items[i].name.c_str());
      ImGui::PopID();
    }
    if (shown == 0) ImGui::TextDisabled("No block is called that.");
    ImGui::EndChild();
    ImGui::Separator();

    // The hotbar: a click selects a slot, an item dropped on one goes there.
    for (int s = 0; s < static_cast<int>(hotbar.size()); ++s) {
      if (s > 0) ImGui::SameLine();
      ImGui::PushID(1'000'000 + s);
      const bool current = s == selected;
      if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
      if (iconButton(hotbar[static_cast<std::size_t>(s)], cell)) out.select = s;
      if (current) ImGui::PopStyleColor();
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", hotbar[static_cast<std::size_t>(s)].name.c_str());
      if (ImGui::BeginDragDropTarget()) {
        if (const ImGuiPayload* p = ImGui::AcceptDragDropPayload(kPayload)) {
          out.place = {{s, *static_cast<const std::size_t*>(p->Data)}};
        }
        ImGui::EndDragDropTarget();
      }
      ImGui::PopID();
    }
  }
  ImGui::End();
  return out;
}

}  // namespace terrasol
