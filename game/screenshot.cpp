#include "screenshot.h"

#include <ctime>
#include <string>

#include "core/log.h"
#include "render/gl/render_target.h"

namespace terrasol {

std::filesystem::path screenshotName() {
  const std::time_t now = std::time(nullptr);
  char name[64];
  std::strftime(name, sizeof name, "%Y-%m-%d_%H.%M.%S", std::localtime(&now));
  std::filesystem::path file = std::filesystem::path("screenshots") / (std::string(name) + ".png");
  for (int i = 1; std::filesystem::exists(file); ++i) {
    file = std::filesystem::path("screenshots") / (std::string(name) + "_" + std::to_string(i) + ".png");
  }
  return file;
}

void saveScreenshot(const std::filesystem::path& file, glm::ivec2 size) {
  if (size.x <= 0 || size.y <= 0) {
    logWarning("no screenshot: the window has no pixels (minimised)");
    return;
  }
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  saveImage(file, readFramebuffer(0, size));
  logInfo("screenshot saved to " + file.string());
}

}  // namespace terrasol
