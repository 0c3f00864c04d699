#pragma once
// Settings for the machine the game first starts on (no settings file yet): a short probe (the GL
// renderer and the time of a few frames of the empty renderer at the window's size) picks them. Plain
// C++; the game measures, this decides.

#include <string>

#include "settings.h"

namespace terrasol {

struct MachineProbe {
  std::string glRenderer;  // GL_RENDERER
  double frameMs = 0.0;    // the median of a few frames with nothing loaded: the passes' fixed cost
};

// A software renderer (Mesa's llvmpipe or softpipe, SwiftShader): every pixel costs CPU time.
bool softwareRenderer(const std::string& glRenderer);

// The defaults adjusted for the machine, with what was chosen and why in `firstRun`. Software
// rendering: the medium preset (low when even an empty frame is slow), dynamic resolution for 30 fps;
// a GPU: the ultra preset, dynamic resolution for 60 fps (core/render_preset.h).
GameSettings firstRunSettings(const MachineProbe& probe, GameSettings settings = {});

}  // namespace terrasol
