#include "hud.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>

namespace terrasol {
namespace {

constexpr ImGuiWindowFlags kOverlayFlags =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings |
    ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_AlwaysAutoResize;

}  // namespace

Hud::Hud(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // our settings file holds what matters; no imgui.ini beside the game
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
}

Hud::~Hud() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void Hud::beginFrame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

namespace {

// A line of text on a dark band, its top left at `at`.
void bannerAt(const std::string& text, ImVec2 at) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  const float pad = 6.0f;
  draw->AddRectFilled({at.x - pad, at.y - pad}, {at.x + size.x + pad, at.y + size.y + pad},
                      IM_COL32(0, 0, 0, 150), 4.0f);
  draw->AddText(at, IM_COL32(255, 255, 255, 240), text.c_str());
}

}  // namespace

void Hud::notice(const std::string& text) {
  bannerAt(text, {(ImGui::GetIO().DisplaySize.x - ImGui::CalcTextSize(text.c_str()).x) * 0.5f, 12.0f});
}

void Hud::centred(const std::string& text) {
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  bannerAt(text,
           {(ImGui::GetIO().DisplaySize.x - size.x) * 0.5f, (ImGui::GetIO().DisplaySize.y - size.y) * 0.5f});
}

void Hud::endFrame() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Hud::crosshair() {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImVec2 c(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f);
  const float r = 8.0f;
  for (const auto& [colour, width] :
       {std::pair{IM_COL32(0, 0, 0, 160), 4.0f}, std::pair{IM_COL32(255, 255, 255, 230), 2.0f}}) {
    draw->AddLine({c.x - r, c.y}, {c.x + r, c.y}, colour, width);
    draw->AddLine({c.x, c.y - r}, {c.x, c.y + r}, colour, width);
  }
}

void Hud::hotbar(const std::vector<ItemIcon>& slots, int selected) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float slot = std::clamp(display.x / 14.0f, 24.0f, 64.0f);
  const float x0 = display.x * 0.5f - slot * 4.5f, y0 = display.y - slot - 4.0f;
  for (int i = 0; i < static_cast<int>(slots.size()); ++i) {
    const ItemIcon& s = slots[static_cast<std::size_t>(i)];
    const ImVec2 a(x0 + slot * i, y0), b(a.x + slot, a.y + slot);
    draw->AddRectFilled(a, b, IM_COL32(0, 0, 0, 110));
    const float inset = slot * 0.18f;
    const ImU32 tint =
        IM_COL32(static_cast<int>(s.r * 255), static_cast<int>(s.g * 255), static_cast<int>(s.b * 255), 255);
    draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(s.texture)),
                   {a.x + inset, a.y + inset}, {b.x - inset, b.y - inset}, {s.u0, s.v0}, {s.u1, s.v1}, tint);
    draw->AddRect(a, b, i == selected ? IM_COL32(255, 255, 255, 255) : IM_COL32(130, 130, 130, 200), 0.0f, 0,
                  i == selected ? 3.0f : 1.0f);
  }
  if (selected >= 0 && selected < static_cast<int>(slots.size())) {
    const std::string& name = slots[static_cast<std::size_t>(selected)].name;
    const ImVec2 size = ImGui::CalcTextSize(name.c_str());
    draw->AddText({display.x * 0.5f - size.x * 0.5f, y0 - size.y - 6.0f}, IM_COL32(255, 255, 255, 255),
                  name.c_str());
  }
}

void Hud::overlay(const std::vector<std::string>& left, const std::vector<std::string>& right,
                  const std::vector<float>& frameMs) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos({4.0f, 4.0f});
  ImGui::SetNextWindowBgAlpha(0.45f);
  float leftBottom = 4.0f, leftRight = 4.0f;
  // Small windows get smaller text, so both panels and the hotbar fit.
  const float scale = std::clamp(display.y / 540.0f, 0.7f, 1.0f);
  if (ImGui::Begin("##debug_left", nullptr, kOverlayFlags)) {
    ImGui::SetWindowFontScale(scale);
    for (const std::string& line : left) ImGui::TextUnformatted(line.c_str());
    if (!frameMs.empty()) {
      // Scaled to the slowest frame shown (at least 50 ms), as Minecraft's and Luanti's graphs are.
      const float top = std::max(50.0f, *std::max_element(frameMs.begin(), frameMs.end()));
      char label[64];
      std::snprintf(label, sizeof label, "frame ms (top %.0f)", top);
      ImGui::PlotLines("##frames", frameMs.data(), static_cast<int>(frameMs.size()), 0, label, 0.0f, top,
                       {240.0f * scale, 48.0f * scale});
    }
    leftBottom = ImGui::GetWindowPos().y + ImGui::GetWindowSize().y;
    leftRight = ImGui::GetWindowPos().x + ImGui::GetWindowSize().x;
  }
  ImGui::End();
  // Beside the left panel when the window is wide enough, under it otherwise.
  const bool besideFits = display.x - leftRight > 360.0f * scale;
  ImGui::SetNextWindowPos({display.x - 4.0f, besideFits ? 4.0f : leftBottom + 4.0f}, 0, {1.0f, 0.0f});
  ImGui::SetNextWindowBgAlpha(0.45f);
  if (ImGui::Begin("##debug_right", nullptr, kOverlayFlags)) {
    ImGui::SetWindowFontScale(scale);
    for (const std::string& line : right) ImGui::TextUnformatted(line.c_str());
  }
  ImGui::End();
}

}  // namespace terrasol
