#include "menu.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <span>

#include "core/render_preset.h"
#include "core/render_scale.h"

namespace terrasol {
namespace {

// A combo box over an enum, by its names (in the enum's order); true when the choice changed.
template <class E>
bool comboOf(const char* label, E& value, std::span<const std::string_view> names) {
  bool changed = false;
  const auto current = static_cast<std::size_t>(value);
  if (ImGui::BeginCombo(label, std::string(names[current]).c_str())) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      const bool selected = i == current;
      if (ImGui::Selectable(std::string(names[i]).c_str(), selected) && !selected) {
        value = static_cast<E>(i);
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

// Sliders apply when let go (a new shadow map per drag step would stall the menu).
bool released() {
  return ImGui::IsItemDeactivatedAfterEdit();
}

}  // namespace

MenuResult Menu::draw(GameSettings& settings, const std::vector<std::string>& loadedPacks,
                      const ShaderPackChoices& shaderPacks, const std::vector<std::string>& propFiles,
                      const std::string& selectedProp) {
  MenuResult out;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos({display.x * 0.5f, display.y * 0.5f}, ImGuiCond_Always, {0.5f, 0.5f});
  ImGui::SetNextWindowSize({std::min(display.x - 20.0f, 560.0f), std::min(display.y - 20.0f, 520.0f)},
                           ImGuiCond_Always);
  if (ImGui::Begin("Game menu", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
    out.resume = ImGui::Button("Back to game");
    ImGui::SameLine();
    out.save = ImGui::Button("Save");
    ImGui::SameLine();
    out.quit = ImGui::Button("Save and quit");
    if (ImGui::BeginTabBar("tabs")) {
      if (ImGui::BeginTabItem("Settings")) {
        settingsTab(settings, out);
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Resource packs")) {
        packsTab(settings, loadedPacks, out);
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Shader packs")) {
        shaderPacksTab(settings, shaderPacks, out);
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Sound")) {
        soundTab(settings, out);
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Controls")) {
        keysTab(settings);
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Props")) {
        propsTab(propFiles, selectedProp, out);
        ImGui::EndTabItem();
      }
      ImGui::EndTabBar();
    }
  }
  ImGui::End();
  out.settingsChanged |= out.viewChanged || out.rendererChanged || out.packsChanged || out.shaderPackChanged;
  return out;
}

void Menu::propsTab(const std::vector<std::string>& files, const std::string& selected, MenuResult& out) {
  ImGui::TextWrapped(
      "glTF models (.gltf, .glb) in the world's props folder. The place-prop key (P by default) "
      "stands the chosen one in the free cell beside the block you look at.");
  if (files.empty()) ImGui::TextDisabled("The folder is empty.");
  for (const std::string& file : files) {
    if (ImGui::RadioButton(file.c_str(), file == selected)) out.prop = file;
  }
}

void Menu::shaderPacksTab(GameSettings& s, const ShaderPackChoices& packs, MenuResult& out) {
  ImGui::TextWrapped(
      "OptiFine and Iris shader packs (a folder with shaders/ inside, or a .zip) from the shaderpacks "
      "folder beside worlds. One draws the world instead of Terrasol's own pipeline, from the next frame.");
  const auto choose = [&](const std::filesystem::path& path) {
    if (path == s.shaderpack) return;
    s.shaderpack = path;
    out.shaderPackChanged = true;
  };
  if (ImGui::RadioButton("None: Terrasol's pipeline", s.shaderpack.empty())) choose({});
  for (const std::filesystem::path& pack : packs.found) {
    if (ImGui::RadioButton(pack.filename().string().c_str(), pack == s.shaderpack)) choose(pack);
  }
  if (packs.found.empty()) ImGui::TextDisabled("No packs found in shaderpacks/.");
  if (!packs.error.empty()) {
    ImGui::Separator();
    ImGui::TextColored({1.0f, 0.45f, 0.35f, 1.0f}, "The pack failed; Terrasol's pipeline draws:");
    ImGui::TextWrapped("%s", packs.error.c_str());
  }
}

// The preset the settings match ("custom" when none); choosing one sets what it decides.
static void presetCombo(GameSettings& s, MenuResult& out) {
  const std::optional<RenderPreset> current = presetOf(s);
  const std::string shown = current ? std::string(kRenderPresets.nameOf(*current)) : "custom";
  if (!ImGui::BeginCombo("Preset", shown.c_str())) return;
  for (std::size_t i = 0; i < kRenderPresets.names.size(); ++i) {
    const auto preset = static_cast<RenderPreset>(i);
    if (ImGui::Selectable(std::string(kRenderPresets.names[i]).c_str(), current == preset) &&
        current != preset) {
      applyPreset(preset, s);
      out.rendererChanged = true;
      out.viewChanged = true;
    }
  }
  ImGui::EndCombo();
}

// Volumes change as the slider moves (cheap, and the ear judges them); the file is saved on release.
void Menu::soundTab(GameSettings& s, MenuResult& out) {
  if (!soundDevice_.empty()) ImGui::TextDisabled("%s", soundDevice_.c_str());
  for (auto [label, volume] : {std::pair{"Master", &s.sound.master}, std::pair{"Blocks", &s.sound.blocks},
                               std::pair{"Ambient", &s.sound.ambient}, std::pair{"Music", &s.sound.music}}) {
    out.soundChanged |= ImGui::SliderFloat(label, volume, 0.0f, 1.0f, "%.2f");
    out.settingsChanged |= released();
  }
}

void Menu::settingsTab(GameSettings& s, MenuResult& out) {
  presetCombo(s, out);
  ImGui::SliderInt("View distance (chunks)", &s.viewDistance, 2, 32);
  out.viewChanged |= released();
  ImGui::SliderInt("Far terrain (chunks, 0: off)", &s.lod.distance, 0, 1024);
  out.viewChanged |= released();
  ImGui::SliderFloat("FOV", &s.fov, 30.0f, 110.0f, "%.0f");
  out.settingsChanged |= released();
  ImGui::SliderFloat("Mouse sensitivity", &s.mouseSensitivity, 0.01f, 2.0f, "%.2f deg/px");
  out.settingsChanged |= released();
  ImGui::SliderFloat("Sun path rotation", &s.sunPathRotation, -90.0f, 90.0f, "%.0f deg");
  out.settingsChanged |= released();
  out.settingsChanged |= ImGui::Checkbox("Survival digging (blocks take time to break)", &s.survivalDigging);
  out.settingsChanged |= ImGui::Checkbox("VSync", &s.vsync);
  ImGui::SliderFloat("Render scale", &s.renderScale, kMinRenderScale, kMaxRenderScale, "%.2f");
  out.settingsChanged |= released();
  ImGui::SliderInt("Target fps (0: fixed scale)", &s.targetFps, 0, 144);
  out.settingsChanged |= released();
  if (s.firstRun) {
    ImGui::TextWrapped("Chosen on the first start for %s (%s).", s.firstRun->glRenderer.c_str(),
                       s.firstRun->choice.c_str());
  }
  ImGui::Separator();
  ImGui::TextUnformatted("Shadows");
  ShadowSettings& sh = s.shadow;
  out.rendererChanged |= ImGui::Checkbox("Shadows", &sh.enabled);
  out.rendererChanged |= comboOf("Mode", sh.mode, kShadowModes);
  if (sh.mode == ShadowMode::Cascaded) {
    ImGui::SliderInt("Cascades", &sh.cascades, 2, 4);
    out.rendererChanged |= released();
  } else {
    out.rendererChanged |= comboOf("Warp", sh.warp, kShadowWarps);
  }
  static constexpr std::array<int, 5> kResolutions = {512, 1024, 2048, 4096, 8192};
  const std::string res = std::to_string(sh.resolution);
  if (ImGui::BeginCombo("Resolution", res.c_str())) {
    for (int r : kResolutions) {
      if (ImGui::Selectable(std::to_string(r).c_str(), r == sh.resolution) && r != sh.resolution) {
        sh.resolution = r;
        out.rendererChanged = true;
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SliderFloat("Distance (blocks)", &sh.distance, 16.0f, 512.0f, "%.0f");
  out.rendererChanged |= released();
  ImGui::SliderInt("PCF samples (N: (2N+1)^2 grid; disk, tent: on)", &sh.pcfSamples, 0, 8);
  out.rendererChanged |= released();
  ImGui::SliderFloat("PCF radius", &sh.pcfRadius, 0.0f, 8.0f, "%.1f");
  out.rendererChanged |= released();
  out.rendererChanged |= comboOf("PCF pattern", sh.pcfPattern, kPcfPatterns);
  ImGui::SliderInt("Update over frames", &sh.updateFrames, 1, 16);
  out.rendererChanged |= released();
  ImGui::Separator();
  ImGui::TextUnformatted("Image");
  out.rendererChanged |= comboOf("Anti-aliasing", s.antialiasing, kAntialiasingModes);
  out.rendererChanged |= ImGui::Checkbox("Bloom", &s.bloom.enabled);
  ImGui::SliderFloat("Bloom strength", &s.bloom.strength, 0.0f, 0.2f, "%.2f");
  out.rendererChanged |= released();
  out.rendererChanged |= comboOf("Clouds", s.clouds.mode, kCloudModes);
  out.rendererChanged |= ImGui::Checkbox("Cloud shadows", &s.clouds.shadows);
  ImGui::SliderFloat("Height fog density", &s.fog.density, 0.0f, 0.05f, "%.3f");
  out.rendererChanged |= released();
  out.rendererChanged |= ImGui::Checkbox("Light shafts (need shadows and fog)", &s.shafts.enabled);
  ImGui::Separator();
  ImGui::TextUnformatted("Reflections (smooth blocks, water, glass)");
  ReflectionSettings& r = s.reflections;
  out.rendererChanged |= ImGui::Checkbox("Reflections", &r.enabled);
  ImGui::SliderFloat("Resolution scale", &r.resolutionScale, kMinRenderScale, kMaxRenderScale, "%.2f");
  out.rendererChanged |= released();
  ImGui::SliderInt("Steps", &r.maxSteps, 4, 96);
  out.rendererChanged |= released();
}

void Menu::packsTab(GameSettings& s, const std::vector<std::string>& loadedPacks, MenuResult& out) {
  ImGui::TextWrapped("Loaded now, bottom to top: ");
  for (const std::string& name : loadedPacks) {
    ImGui::SameLine();
    ImGui::TextUnformatted(name.c_str());
  }
  ImGui::TextUnformatted("Top of the list wins. The default pack is always at the bottom.");
  bool changed = false;
  // Shown top first, stored bottom first.
  for (int i = static_cast<int>(s.packs.size()) - 1; i >= 0; --i) {
    ImGui::PushID(i);
    PackChoice& p = s.packs[static_cast<std::size_t>(i)];
    changed |= ImGui::Checkbox("##on", &p.enabled);
    ImGui::SameLine();
    if (ImGui::ArrowButton("up", ImGuiDir_Up) && i + 1 < static_cast<int>(s.packs.size())) {
      std::swap(s.packs[static_cast<std::size_t>(i)], s.packs[static_cast<std::size_t>(i + 1)]);
      changed = true;
    }
    ImGui::SameLine();
    if (ImGui::ArrowButton("down", ImGuiDir_Down) && i > 0) {
      std::swap(s.packs[static_cast<std::size_t>(i)], s.packs[static_cast<std::size_t>(i - 1)]);
      changed = true;
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("remove")) {
      s.packs.erase(s.packs.begin() + i);
      changed = true;
      ImGui::PopID();
      break;
    }
    ImGui::SameLine();
    ImGui::TextUnformatted(
        s.packs[static_cast<std::size_t>(std::min<int>(i, static_cast<int>(s.packs.size()) - 1))]
            .path.string()
            .c_str());
    ImGui::PopID();
  }
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, "%s", newPack_.c_str());
  if (ImGui::InputText("Pack path (folder, .zip or .jar)", buffer, sizeof buffer)) newPack_ = buffer;
  if (ImGui::Button("Add on top") && !newPack_.empty()) {
    s.packs.push_back({newPack_, true});
    newPack_.clear();
    changed = true;
  }
  ImGui::SameLine();
  out.packsChanged |= ImGui::Button("Reload packs");
  out.packsChanged |= changed;
}

void Menu::keysTab(GameSettings& s) {
  for (std::size_t i = 0; i < kActionCount; ++i) {
    const auto a = static_cast<Action>(i);
    ImGui::PushID(static_cast<int>(i));
    const std::string label = rebinding_ == a ? "> press a key <" : keyName(s.keys.key(a));
    if (ImGui::Button(label.c_str(), {140.0f, 0.0f})) rebinding_ = a;
    ImGui::SameLine();
    ImGui::TextUnformatted(std::string(actionName(a)).c_str());
    ImGui::PopID();
  }
}

bool Menu::takeKey(int key, GameSettings& settings) {
  if (!rebinding_) return false;
  if (key != kEscapeKey) settings.keys.bind(*rebinding_, key);
  rebinding_.reset();
  return true;
}

}  // namespace terrasol
