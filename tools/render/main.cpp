// terrasol-render: renders a scene file headless (EGL) into DIR/frame_0000.png.
//
//   terrasol-render SCENE.json --out DIR [--timings]
//
// --timings ends every pass with glFinish and prints its milliseconds, from a second frame (the
// first pays for shader compilation and uploads).

#include <cstdio>
#include <string>

#include "core/tool_main.h"
#include "platform/egl/egl_context.h"
#include "scene_render.h"

namespace terrasol {
namespace {

struct Options {
  std::filesystem::path scene, out;
  bool timings = false;
};

int usage() {
  std::fputs("usage: terrasol-render SCENE.json --out DIR [--timings]\n", stderr);
  return 2;
}

void printTimings(const std::vector<PassTiming>& timings, const SceneFile& scene) {
  double total = 0.0;
  for (const auto& t : timings) {
    std::printf("  %-12s %8.2f ms\n", t.pass.c_str(), t.ms);
    total += t.ms;
  }
  std::printf("  %-12s %8.2f ms  (%dx%d, glFinish after each pass)\n", "total", total, scene.width, scene.height);
}

int render(const Options& options) {
  const SceneFile scene = loadScene(options.scene);
  auto context = createHeadlessContext(GlErrorPolicy::Throw);
  SceneRenderer renderer(scene);
  for (const auto& p : renderer.stats().problems) {
    std::fprintf(stderr, "terrasol-render: %s: %s\n", p.severity == PackProblem::Severity::Error ? "error" : "warning",
                 p.message.c_str());
  }
  std::vector<PassTiming> timings;
  const Image image = renderer.render(options.timings ? &timings : nullptr);
  context->checkErrors("rendering the scene");
  std::filesystem::create_directories(options.out);
  const auto file = options.out / "frame_0000.png";
  saveImage(file, image);
  const SceneRenderStats& stats = renderer.stats();
  std::printf("terrasol-render: %s: %zu sections, %zu quads; packs and atlas %.0f ms, world %.0f ms; wrote %s\n",
              scene.file.string().c_str(), stats.sections, stats.quads, stats.loadMs, stats.worldMs,
              file.string().c_str());
  if (options.timings) printTimings(timings, scene);
  return 0;
}

int run(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) {
      options.out = argv[++i];
    } else if (arg == "--timings") {
      options.timings = true;
    } else if (!arg.empty() && arg[0] != '-' && options.scene.empty()) {
      options.scene = arg;
    } else {
      return usage();
    }
  }
  if (options.scene.empty() || options.out.empty()) return usage();
  return render(options);
}

}  // namespace
}  // namespace terrasol

int main(int argc, char** argv) {
  return terrasol::guardedMain("terrasol-render", [&] { return terrasol::run(argc, argv); });
}
