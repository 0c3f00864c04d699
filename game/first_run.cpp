#include "first_run.h"

#include <cstdio>

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
  if (software) {
    s.viewDistance = slow ? 3 : 4;
    s.shadow.resolution = 1024;
    s.shadow.distance = 64.0f;
    s.reflections.enabled = false;
    s.targetFps = 30;
  } else {
    s.viewDistance = 12;
    s.shadow.resolution = 2048;
    s.shadow.distance = 128.0f;
    s.reflections.enabled = true;
    s.targetFps = 60;
  }
  s.renderScale = 1.0f;
  char why[160];
  std::snprintf(why, sizeof why, "%s, an empty frame %.1f ms: %s", software ? "software rendering" : "a GPU",
                probe.frameMs,
                software ? (slow ? "the slow settings" : "the light settings") : "the full settings");
  s.firstRun = FirstRunRecord{probe.glRenderer, probe.frameMs, why};
  return s;
}

}  // namespace terrasol
