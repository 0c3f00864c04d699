#include "demo.h"

#include <cmath>
#include <cstdio>

#include "core/paths.h"
#include "platform/egl/egl_context.h"
#include "render/cube_scene.h"
#include "render/gl/render_target.h"

namespace terrasol {

DemoView demoView(double seconds) {
  const double angle = 0.25 * seconds;  // radians; a full turn in about 25 s
  DemoView view;
  view.camera.position = {static_cast<float>(12.0 * std::cos(angle)), 7.0f, static_cast<float>(12.0 * std::sin(angle))};
  view.camera.lookAt = {0.0f, 0.5f, 0.0f};
  view.camera.fovDegrees = 60.0f;
  view.towardLight = {0.45f, 0.8f, 0.35f};
  return view;
}

std::filesystem::path renderHeadlessDemo(const std::filesystem::path& dir, int frames, glm::ivec2 size) {
  auto context = createHeadlessContext(GlErrorPolicy::Throw);
  const ShaderPreprocessor shaders(shaderDir());
  const CubeScene scene(shaders, CubeScene::standardCubes());
  const RenderTarget target(size);
  std::filesystem::create_directories(dir);
  for (int i = 0; i < frames; ++i) {
    const DemoView view = demoView(i * 3.0);
    scene.draw(target.framebuffer(), target.size(), view.camera, view.towardLight);
    context->checkErrors("demo frame");
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    saveImage(dir / name, target.readPixels());
  }
  return std::filesystem::absolute(dir);
}

}  // namespace terrasol
