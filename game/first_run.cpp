#include "first_run.h"

#include <cstdio>

#include "core/render_preset.h"

namespace terrasol {

bool softwareRenderer(const std::string& glRenderer) {
  for (const char* name : {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer"}) {
    if (glRenderer.find(name) != std::string::npos) return true;
  }
  return false;
}

GameSettings firstRunSettings(const MachineProbe& probe, GameSettings s) {
  const bool software = softwareRenderer(probe.glRenderer);
  // Even an empty world's passes taking a third of the frame budget leave little for the world.
  const bool slow = software && probe.frameMs > 11.0;
  const RenderPreset preset =
      software ? (slow ? RenderPreset::Low : RenderPreset::Medium) : RenderPreset::Ultra;
  applyPreset(preset, s);
  s.targetFps = software ? 30 : 60;
  s.renderScale = 1.0f;
  char why[160];
  std::snprintf(why, sizeof why, "%s, an empty frame %.1f ms: the %s preset",
                software ? "software rendering" : "a GPU", probe.frameMs,
                kRenderPresets.nameOf(preset).data());
  s.firstRun = FirstRunRecord{probe.glRenderer, probe.frameMs, why};
  return s;
}

}  // namespace terrasol
