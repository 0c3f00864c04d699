#pragma once
// What the game shows until the world exists: the test scene seen from a slowly orbiting camera.

#include <filesystem>

#include "core/camera.h"

namespace terrasol {

struct DemoView {
  Camera camera;
  glm::vec3 towardLight;
};

// Seconds per frame when the game runs a fixed number of frames (--frames).
inline constexpr double kFixedStep = 1.0 / 60.0;

// The view `seconds` into the demo.
DemoView demoView(double seconds);

// Renders `frames` demo frames headless (EGL) into dir/frame_NNNN.png; returns the files' directory.
std::filesystem::path renderHeadlessDemo(const std::filesystem::path& dir, int frames, glm::ivec2 size);

}  // namespace terrasol
