#pragma once
// What the game shows until it is playable (issue 10 brings controls, physics and streaming): a flight
// over the generated world from late morning into the night, drawn by the deferred renderer.

#include <filesystem>
#include <glm/vec2.hpp>

#include "scene/scene_file.h"

namespace terrasol {

// Seconds per frame when the game runs a fixed number of frames (--frames).
inline constexpr double kFixedStep = 1.0 / 60.0;
// The flight's length in frames at 60 per second; it loops.
inline constexpr int kDemoPathFrames = 3600;

// The flight as a scene, rendered at `size`.
SceneFile demoScene(glm::ivec2 size);

// The frame of the flight shown `seconds` in.
int demoFrame(double seconds);

// Renders `frames` frames spread along the flight headless (EGL) into dir/frame_NNNN.png; returns
// the files' directory.
std::filesystem::path renderHeadlessDemo(const std::filesystem::path& dir, int frames, glm::ivec2 size);

}  // namespace terrasol
