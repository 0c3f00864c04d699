#include "demo.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "platform/egl/egl_context.h"
#include "scene_render/scene_render.h"

namespace terrasol {
namespace {

// Around the spawn area of seed 1 and back, while the sun crosses the sky and sets; far terrain to 24
// chunks shows the land round it.
constexpr const char* kDemoScene = R"({
  "world": { "generator": "terrain", "seed": 1 },
  "sun_path_rotation": -25,
  "render": { "view_distance": 4, "shadow": { "resolution": 2048, "distance": 96 }, "lod": { "distance": 24 } },
  "camera_path": { "frames": 3600, "keyframes": [
    { "t": 0.00, "position": [-40, 110, -40], "look_at": [0, 80, 0], "fov": 70, "time": 3000 },
    { "t": 0.25, "position": [30, 108, -45], "look_at": [0, 78, 10], "fov": 70, "time": 6000 },
    { "t": 0.50, "position": [45, 108, 30], "look_at": [-10, 80, 0], "fov": 75, "time": 9500 },
    { "t": 0.75, "position": [-20, 128, 45], "look_at": [10, 82, -10], "fov": 75, "time": 12300 },
    { "t": 1.00, "position": [-40, 110, -40], "look_at": [0, 80, 0], "fov": 70, "time": 15000 } ] }
})";

}  // namespace

SceneFile demoScene(glm::ivec2 size) {
  SceneFile scene = parseScene(kDemoScene, "the built-in demo");
  scene.width = std::max(size.x, 1);
  scene.height = std::max(size.y, 1);
  return scene;
}

int demoFrame(double seconds) {
  const auto frame = static_cast<long long>(std::floor(std::max(seconds, 0.0) / kFixedStep));
  return static_cast<int>(frame % kDemoPathFrames);
}

std::filesystem::path renderHeadlessDemo(const std::filesystem::path& dir, int frames, glm::ivec2 size) {
  auto context = createHeadlessContext(GlErrorPolicy::Throw);
  SceneRenderer renderer(demoScene(size));
  std::filesystem::create_directories(dir);
  for (int i = 0; i < frames; ++i) {
    const Image image = renderer.renderFrame(i * kDemoPathFrames / std::max(frames, 1)).image;
    context->checkErrors("demo frame");
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    saveImage(dir / name, image);
  }
  return std::filesystem::absolute(dir);
}

}  // namespace terrasol
