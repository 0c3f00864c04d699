#pragma once
// Saving the window's picture: F2, a script's "screenshot" and --screenshot all come here.

#include <filesystem>
#include <glm/vec2.hpp>

namespace terrasol {

// screenshots/<date>_<time>.png (relative to the current directory), never an existing file.
std::filesystem::path screenshotName();
// Saves the default framebuffer's `size` pixels into `file` (its folder made); a window with no
// pixels (minimised) saves nothing and says so.
void saveScreenshot(const std::filesystem::path& file, glm::ivec2 size);

}  // namespace terrasol
