// terrasol-render: renders a scene file headless (EGL), one PNG per frame of its camera path.
//
//   terrasol-render SCENE.json --out DIR [--set KEY=VALUE]... [--compare GOLDEN_DIR [--update-goldens]]
//                   [--threshold X] [--max-failing PERCENT] [--report FILE.json] [--timings] [--no-images]
//                   [--game-shadows]
//
// Exit status: 0 done (and every frame matched); 1 a frame differs from its golden, a golden is
// missing, or rendering failed; 2 bad arguments or a bad scene (nothing is written then).

#include <cstdio>
#include <deque>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/error.h"
#include "core/tool_main.h"
#include "frame_report.h"
#include "pack_render/pack_renderer.h"
#include "platform/egl/egl_context.h"
#include "progress.h"
#include "render/gl/program.h"
#include "scene_render/aa_error.h"
#include "scene_render/lod_error.h"
#include "scene_render/reflection_truth.h"
#include "scene_render/scene_render.h"
#include "sweep.h"

namespace terrasol {
namespace {

constexpr int kBadInput = 2;

struct Options {
  std::filesystem::path scene, out, compare, report, shaderpack;
  std::vector<std::string> overrides;
  std::vector<Sweep> sweeps;
  bool updateGoldens = false, timings = false, noImages = false, gameShadows = false;
  int referenceSupersample = 0;  // 0: no anti-aliasing error measured
  std::optional<float> threshold, maxFailing;
};

const char* const kUsage =
    "usage: terrasol-render SCENE.json --out DIR [options]\n"
    "  --set KEY=VALUE        change a scene value, e.g. --set render.width=640 (repeatable)\n"
    "  --compare GOLDEN_DIR   compare every frame with GOLDEN_DIR/frame_NNNN.png; exit 1 on a difference\n"
    "  --update-goldens       with --compare: write the frames into GOLDEN_DIR instead, on purpose\n"
    "  --threshold X          per-pixel threshold 0..1 (default: the scene's compare.pixel_threshold)\n"
    "  --max-failing PERCENT  pixels allowed over it (default: the scene's compare.max_failing_percent)\n"
    "  --report FILE.json     per-frame report: ms per pass, NaN/Inf pixels, sections drawn and culled,\n"
    "                         shadow and reflection error against the ray-traced truth; the GL renderer\n"
    "  --timings              print ms per pass (after a warm-up frame)\n"
    "  --reference-supersample N\n"
    "                         also draw each frame N x N times larger with no anti-aliasing, average it\n"
    "                         down and report aa_error against it (mean, p99, edge_over_pct)\n"
    "  --shaderpack PATH      draw with an OptiFine/Iris shader pack (folder or .zip) instead of\n"
    "                         Terrasol's pipeline (the scene's render.shaderpack)\n"
    "  --game-shadows         keep and spread the shadow map as the game does (FrameInputs::reuseShadowMap)\n"
    "                         instead of drawing it whole every frame\n"
    "  --no-images            write no frames (benchmarks: the time to encode a PNG would leave the GPU\n"
    "                         idle between frames, and it would clock down)\n"
    "  --sweep KEY=V1,V2,...  render every combination of the swept values (repeatable); writes\n"
    "                         DIR/sweep.csv and DIR/sweep.png (shadow error against ms, Pareto front)\n";

class UsageError : public Error {
 public:
  using Error::Error;
};

float numberArgument(const std::string& flag, const std::string& text) {
  try {
    std::size_t used = 0;
    const float v = std::stof(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  throw UsageError(flag + ": expected a number, got \"" + text + "\"");
}

Options parseOptions(int argc, char** argv) {
  Options o;
  auto value = [&](int& i, const std::string& flag) -> std::string {
    if (i + 1 >= argc) throw UsageError(flag + " needs a value");
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out")
      o.out = value(i, arg);
    else if (arg == "--set")
      o.overrides.push_back(value(i, arg));
    else if (arg == "--compare")
      o.compare = value(i, arg);
    else if (arg == "--update-goldens")
      o.updateGoldens = true;
    else if (arg == "--threshold")
      o.threshold = numberArgument(arg, value(i, arg));
    else if (arg == "--max-failing")
      o.maxFailing = numberArgument(arg, value(i, arg));
    else if (arg == "--report")
      o.report = value(i, arg);
    else if (arg == "--timings")
      o.timings = true;
    else if (arg == "--reference-supersample") {
      const float n = numberArgument(arg, value(i, arg));
      if (n != std::floor(n) || n < 2 || n > 8) throw UsageError(arg + ": expected a whole number 2..8");
      o.referenceSupersample = static_cast<int>(n);
    } else if (arg == "--shaderpack")
      o.shaderpack = std::filesystem::absolute(value(i, arg));
    else if (arg == "--no-images")
      o.noImages = true;
    else if (arg == "--game-shadows")
      o.gameShadows = true;
    else if (arg == "--sweep")
      o.sweeps.push_back(parseSweep(value(i, arg)));
    else if (!arg.empty() && arg[0] != '-' && o.scene.empty())
      o.scene = arg;
    else
      throw UsageError("unknown argument \"" + arg + "\"");
  }
  if (o.scene.empty() || o.out.empty()) throw UsageError("a scene and --out DIR are required");
  if (o.updateGoldens && o.compare.empty()) throw UsageError("--update-goldens needs --compare GOLDEN_DIR");
  return o;
}

std::string frameName(const char* prefix, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "%s_%04d.png", prefix, frame);
  return name;
}

// One line per frame; true when it matches (or the golden was written on purpose).
bool compareFrame(const Options& o, const SceneFile& scene, int index, const Image& image,
                  Progress& progress) {
  const auto golden = o.compare / frameName("frame", index);
  if (o.updateGoldens) {
    saveImage(golden, image);
    progress.line(frameName("frame", index) + ": golden written to " + golden.string());
    return true;
  }
  if (!std::filesystem::exists(golden)) {
    progress.line(frameName("frame", index) + ": FAIL, missing golden " + golden.string());
    return false;
  }
  const ImageTolerance tolerance{o.threshold.value_or(scene.compare.pixelThreshold),
                                 o.maxFailing.value_or(scene.compare.maxFailingPercent)};
  const ImageComparison c = compareImages(image, loadImage(golden), tolerance);
  char detail[160];
  std::snprintf(detail, sizeof detail,
                "%.3f %% of pixels over %.1f/255 (allowed %.3f %%), max difference %.1f/255",
                c.failingPercent, tolerance.pixel * 255.0, tolerance.percent, c.maxError * 255.0);
  if (c.matches) {
    progress.line(frameName("frame", index) + ": ok, " + detail);
    return true;
  }
  std::string line = frameName("frame", index) + ": FAIL, ";
  if (!c.sameSize) {
    line += "size differs from the golden";
  } else {
    const auto diff = o.out / frameName("diff", index);
    saveImage(diff, c.diff);
    line += std::string(detail) + "; diff: " + diff.string();
  }
  progress.line(line);
  return false;
}

int renderScene(const Options& o, const SceneFile& scene, SceneRenderer& renderer, const std::string& gl) {
  std::filesystem::create_directories(o.out);
  if (!o.compare.empty()) std::filesystem::create_directories(o.compare);
  Progress progress(renderer.frames(), stdout);
  nlohmann::json frames = nlohmann::json::array();
  bool allMatch = true;
  FrameRequest request;
  request.timed = o.timings || !o.report.empty();
  request.checkNan = !o.report.empty();
  request.readBack = !o.report.empty();
  request.reuseShadowMap = o.gameShadows;
  if (request.timed) renderer.renderFrame(0);  // warm-up: first-use costs are not a pass's time
  // The truth for anti-aliasing: the same scene N x N times larger, drawn without it.
  std::optional<SceneRenderer> reference;
  if (o.referenceSupersample > 0) {
    SceneFile big = scene;
    big.width *= o.referenceSupersample;
    big.height *= o.referenceSupersample;
    big.antialiasing = Antialiasing::None;
    big.renderScale = 1.0f;
    big.targetFps = 0;
    reference.emplace(big);
  }
  // Far terrain's truth: full detail out to its far edge, drawn for the report.
  std::optional<SceneRenderer> lodTruth;
  const bool lodMeasured = !o.report.empty() && renderer.lodStats();
  if (lodMeasured && scene.lod.distance <= kMaxLodTruthChunks) lodTruth.emplace(lodTruthScene(scene));
  std::deque<Image> truths;  // the last kGhostFrames + 1, for ghosting
  for (int i = 0; i < renderer.frames(); ++i) {
    const auto start = std::chrono::steady_clock::now();
    const RenderedFrame frame = renderer.renderFrame(i, request);
    if (!o.noImages) saveImage(o.out / frameName("frame", i), frame.image);
    std::optional<AaError> aaError;
    std::optional<GhostError> ghost;
    if (reference) {
      truths.push_back(downsample(reference->renderFrame(i).image, o.referenceSupersample));
      aaError = measureAaError(frame.image, truths.back());
      std::string line = frameName("frame", i) + ": aa_error mean " +
                         std::to_string(aaError->mean).substr(0, 6) + " p99 " +
                         std::to_string(aaError->p99).substr(0, 6) + " edges over " +
                         std::to_string(aaError->edgeOverPct).substr(0, 5) + " %";
      if (truths.size() > kGhostFrames) {
        ghost = measureGhosting(frame.image, truths.back(), truths[1], truths.front());
        truths.pop_front();
        line += ", ghost over " + std::to_string(ghost->overPct).substr(0, 5) + " % of " +
                std::to_string(ghost->changedPixels) + " changed";
      }
      progress.line(line);
    }
    if (!o.report.empty()) {
      frames.push_back(frameReport(i, frame));
      if (aaError) frames.back()["aa_error"] = aaErrorJson(*aaError, o.referenceSupersample);
      if (ghost) frames.back()["aa_error"]["ghost"] = ghostJson(*ghost);
      if (frame.geometry.shadowMapShown)
        frames.back()["shadow_error"] = shadowReport(renderer, i, frame, request);
      if (lodMeasured && !lodTruth)
        frames.back()["lod_error"] = {
            {"skipped",
             "the truth is made out to " + std::to_string(kMaxLodTruthChunks) + " chunks at most"}};
      if (lodTruth) {
        const LodError e = lodReport(*lodTruth, i, frame, scene);
        frames.back()["lod_error"] = lodErrorJson(e);
        progress.line(frameName("frame", i) + ": lod_error mean " + std::to_string(e.mean).substr(0, 6) +
                      " (half resolution " + std::to_string(e.halfResolutionMean.value_or(0.0)).substr(0, 6) +
                      "), holes " + std::to_string(e.holes) + " of " + std::to_string(e.band) +
                      " in the band");
      }
      if (frame.reflections) {
        const ReflectionError error = measureReflectionError(
            renderer.world(), frame.pixels, *frame.reflections, frame.geometry, scene.reflections.maxDistance,
            renderer.renderer().gbufferContents().surfaceNormals);
        frames.back()["reflection_error"] = reflectionErrorJson(error);
      }
    }
    if (o.timings) {
      std::string line = frameName("frame", i) + ":";
      for (const PassTiming& t : frame.timings)
        line += " " + t.pass + " " + std::to_string(t.ms).substr(0, 6) + " ms";
      progress.line(line);
    }
    if (!o.compare.empty()) allMatch = compareFrame(o, scene, i, frame.image, progress) && allMatch;
    progress.frameDone(
        i + 1, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  progress.finish();
  if (!o.report.empty()) {
    nlohmann::json report{{"scene", scene.file.string()}, {"gl", gl}, {"size", {scene.width, scene.height}}};
    if (const PackRenderer* pack = renderer.shaderPack()) {
      report["shader_pack"] = pack->packName();
      report["pack_programs"] = pack->programNames();
    } else {
      report["shader_variants"] = renderer.renderer().shaderVariants();
      report["gbuffer_bytes_per_pixel"] = renderer.renderer().gbufferContents().bytesPerPixel();
    }
    report["frames"] = frames;
    if (const auto lod = renderer.lodStats())
      report["lod"] = {{"tiles", lod->tiles},         {"levels", lod->levels},
                       {"triangles", lod->triangles}, {"cpu_bytes", lod->cpuBytes},
                       {"gpu_bytes", lod->gpuBytes},  {"build_ms", lod->buildMs}};
    std::ofstream(o.report) << report.dump(2) << "\n";
  }
  const SceneRenderStats& stats = renderer.stats();
  std::printf("terrasol-render: %s: %d frame(s), %zu sections, %zu quads, loaded in %.0f ms; wrote %s\n",
              scene.file.string().c_str(), renderer.frames(), stats.sections, stats.quads, stats.loadMs,
              o.out.string().c_str());
  if (const auto lod = renderer.lodStats())
    std::printf(
        "terrasol-render: far terrain: %d tiles in %d levels, %zu triangles, %.1f MB CPU, %.1f MB GPU\n",
        lod->tiles, lod->levels, lod->triangles, static_cast<double>(lod->cpuBytes) / 1e6,
        static_cast<double>(lod->gpuBytes) / 1e6);
  if (!allMatch)
    std::printf("terrasol-render: some frames differ from their goldens in %s\n", o.compare.string().c_str());
  return allMatch ? 0 : 1;
}

int run(int argc, char** argv) {
  Options options;
  std::optional<SceneFile> scene;
  try {
    options = parseOptions(argc, argv);
    scene = loadScene(options.scene, options.overrides);
    if (!options.shaderpack.empty()) scene->shaderpack = options.shaderpack;
    if (!options.sweeps.empty()) {
      // Every value must make a valid scene before anything is rendered.
      for (const Sweep& s : options.sweeps)
        for (const auto& v : s.values) {
          auto settings = options.overrides;
          settings.push_back(s.key + "=" + v);
          loadScene(options.scene, settings);
        }
    }
  } catch (const Error& e) {
    std::fprintf(stderr, "terrasol-render: error: %s\n%s", e.what(),
                 dynamic_cast<const UsageError*>(&e) ? kUsage : "");
    return kBadInput;
  }
  auto context = createHeadlessContext(GlErrorPolicy::Throw);
  if (!options.sweeps.empty()) {
    runSweep(options.scene, options.overrides, options.sweeps, options.out);
    context->checkErrors("the sweep");
    return 0;
  }
  std::optional<SceneRenderer> renderer;
  try {
    renderer.emplace(*scene);  // unknown blocks, unreadable packs: the scene is bad
  } catch (const ShaderError&) {
    throw;
  } catch (const Error& e) {
    std::fprintf(stderr, "terrasol-render: error: %s\n", e.what());
    return kBadInput;
  }
  for (const auto& p : renderer->stats().problems) {
    std::fprintf(stderr, "terrasol-render: %s: %s\n",
                 p.severity == PackProblem::Severity::Error ? "error" : "warning", p.message.c_str());
  }
  if (!renderer->stats().shaderpackError.empty()) {
    std::fprintf(
        stderr,
        "terrasol-render: error: shader pack: %s\nterrasol-render: drawing with Terrasol's pipeline\n",
        renderer->stats().shaderpackError.c_str());
  }
  const int status = renderScene(options, *scene, *renderer, context->description());
  if (const PackRenderer* pack = renderer->shaderPack()) {
    for (const std::string& u : pack->unknownUniforms())
      std::fprintf(stderr, "terrasol-render: warning: shader pack %s: %s is not set\n",
                   pack->packName().c_str(), u.c_str());
  }

  context->checkErrors("rendering the scene");
  return status;
}

}  // namespace
}  // namespace terrasol

int main(int argc, char** argv) {
  return terrasol::guardedMain("terrasol-render", [&] { return terrasol::run(argc, argv); });
}
