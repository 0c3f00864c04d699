#include "sweep.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <optional>

#include "core/error.h"
#include "scene_render/aa_error.h"
#include "scene_render/lod_error.h"
#include "scene_render/reflection_truth.h"
#include "scene_render/scene_render.h"
#include "scene_render/shadow_truth.h"
#include "sweep_plot.h"

namespace terrasol {
namespace {

// What a sweep measures: the shadows' error against shadow + lighting ms, (when it sweeps a
// render.reflections key) the reflections' against the reflection pass's ms, or (when it sweeps
// render.antialiasing or render.scale) the frame's error against its 3 x 3 supersampled truth against
// the frame's ms but the shadow map's, or (when it sweeps a render.lod key) far terrain's error against
// full detail out to the scene's far edge against the far terrain pass's ms.
enum class Measure { Shadows, Reflections, Antialiasing, Lod };
constexpr int kTruthSupersample = 3;

struct Row {
  std::vector<std::string> values;  // one per sweep
  std::vector<double> columns;      // the measure's own (columnNames)
  double errorPct = 0.0, costMs = 0.0, totalMs = 0.0;
  std::size_t evaluated = 0;
  bool pareto = false;
};

// What rows are measured against: the supersampled frame, or far terrain's truth and its half-scale draw.
struct Truth {
  Image image;
  std::optional<RenderedFrame> lod;
  Image lodHalf;
  double fullDetail = 0.0, farEdge = 0.0;  // blocks
};

std::vector<const char*> columnNames(Measure m) {
  if (m == Measure::Lod)
    return {"band_pixels",          "lod_mean",  "lod_p99", "holes", "sky_differs",
            "half_resolution_mean", "error_pct", "lod_ms"};
  if (m == Measure::Antialiasing) return {"aa_mean", "aa_p99", "edge_over_pct", "error_pct"};
  if (m == Measure::Reflections) {
    return {"evaluated_pixels",
            "agree_pct",
            "wrong_hit_pct",
            "border_hit_pct",
            "missed_on_screen_pct",
            "missed_off_screen_pct",
            "false_hit_pct",
            "sky_leak_pixels",
            "error_pct",
            "reflection_ms",
            "lighting_ms"};
  }
  return {"evaluated_pixels", "false_shadow_pct", "false_lit_pct", "error_pct",
          "ambiguous_pct",    "shadow_ms",        "lighting_ms"};
}

double pct(std::size_t n, std::size_t of) {
  return of ? 100.0 * static_cast<double>(n) / static_cast<double>(of) : 0.0;
}

double msOf(const RenderedFrame& frame, const char* pass) {
  for (const PassTiming& t : frame.timings) {
    if (t.pass == pass) return t.ms;
  }
  return 0.0;
}

void measureShadows(SceneRenderer& renderer, const RenderedFrame& frame, Row& row) {
  ShadowCounts c;
  if (frame.geometry.shadowMapShown) {
    c = measureShadowError(renderer.world(), frame.pixels, frame.geometry, renderer.scene().shadow.distance)
            .total;
  }
  const double shadow = msOf(frame, "shadow"), lighting = msOf(frame, "lighting");
  row.evaluated = c.evaluated;
  row.errorPct = pct(c.falseLit + c.falseShadow, c.evaluated);
  row.costMs = shadow + lighting;
  row.columns = {static_cast<double>(c.evaluated),
                 pct(c.falseShadow, c.evaluated),
                 pct(c.falseLit, c.evaluated),
                 row.errorPct,
                 pct(c.ambiguous, c.evaluated + c.ambiguous),
                 shadow,
                 lighting};
}

void measureReflections(SceneRenderer& renderer, const RenderedFrame& frame, Row& row) {
  ReflectionError e;
  if (frame.reflections) {
    e = measureReflectionError(renderer.world(), frame.pixels, *frame.reflections, frame.geometry,
                               renderer.scene().reflections.maxDistance,
                               renderer.renderer().gbufferContents().surfaceNormals);
  }
  const ReflectionCounts& c = e.total;
  const double reflection = msOf(frame, "reflection");
  row.evaluated = c.evaluated;
  row.errorPct = 100.0 - pct(c.agree, c.evaluated);
  row.costMs = reflection;
  row.columns = {static_cast<double>(c.evaluated),
                 pct(c.agree, c.evaluated),
                 pct(c.wrongHit, c.evaluated),
                 pct(c.borderHit, c.evaluated),
                 pct(c.missedOnScreen, c.evaluated),
                 pct(c.missedOffScreen, c.evaluated),
                 pct(c.falseHit, c.evaluated),
                 static_cast<double>(e.skyLeakPixels),
                 row.errorPct,
                 reflection,
                 msOf(frame, "lighting")};
}

void measureAntialiasing(const RenderedFrame& frame, const Image& truth, Row& row) {
  const AaError e = measureAaError(frame.image, truth);
  row.evaluated = static_cast<std::size_t>(truth.width) * static_cast<std::size_t>(truth.height);
  row.errorPct = 100.0 * e.mean;
  row.columns = {e.mean, e.p99, e.edgeOverPct, row.errorPct};
}

void measureLod(const RenderedFrame& frame, const Truth& truth, Row& row) {
  const LodError e = measureLodError(frame, *truth.lod, truth.fullDetail, truth.farEdge, &truth.lodHalf);
  row.evaluated = e.band;
  row.errorPct = 100.0 * e.mean;
  row.costMs = msOf(frame, "lod");
  row.columns = {static_cast<double>(e.band),
                 e.mean,
                 e.p99,
                 static_cast<double>(e.holes),
                 static_cast<double>(e.skyDiffers),
                 e.halfResolutionMean.value_or(0.0),
                 row.errorPct,
                 row.costMs};
}

Measure measureOf(const std::vector<Sweep>& sweeps) {
  for (const Sweep& s : sweeps) {
    if (s.key.starts_with("render.lod.")) return Measure::Lod;
  }
  for (const Sweep& s : sweeps) {
    if (s.key.starts_with("render.reflections.")) return Measure::Reflections;
  }
  for (const Sweep& s : sweeps) {
    if (s.key == "render.antialiasing" || s.key == "render.scale") return Measure::Antialiasing;
  }
  return Measure::Shadows;
}

// The anti-aliasing truth: frame 0 of the scene (without the swept values) drawn kTruthSupersample
// times larger each way with no anti-aliasing, averaged down.
Image supersampledTruth(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  SceneFile big = loadScene(file, overrides);
  big.width *= kTruthSupersample;
  big.height *= kTruthSupersample;
  big.antialiasing = Antialiasing::None;
  big.renderScale = 1.0f;
  big.targetFps = 0;
  SceneRenderer renderer(big);
  return downsample(renderer.renderFrame(0).image, kTruthSupersample);
}

// Far terrain's truth: frame 0 of the scene (without the swept values) with full detail to its far edge.
Truth lodTruth(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  const SceneFile scene = loadScene(file, overrides);
  SceneRenderer renderer(lodTruthScene(scene));
  Truth t;
  t.fullDetail = scene.viewDistance * double(kChunkSize);
  t.farEdge = scene.lod.distance * double(kChunkSize);
  FrameRequest exact;
  exact.readBack = true;
  t.lod = renderer.renderFrame(0, exact);
  FrameRequest half;
  half.renderScale = 0.5f;
  t.lodHalf = renderer.renderFrame(0, half).image;
  return t;
}

// Every combination, the last sweep varying fastest.
std::vector<std::vector<std::string>> combinations(const std::vector<Sweep>& sweeps) {
  std::vector<std::vector<std::string>> out{{}};
  for (const Sweep& s : sweeps) {
    std::vector<std::vector<std::string>> next;
    for (const auto& prefix : out)
      for (const auto& v : s.values) {
        next.push_back(prefix);
        next.back().push_back(v);
      }
    out = std::move(next);
  }
  return out;
}

Row measure(const std::filesystem::path& file, std::vector<std::string> settings,
            const std::vector<Sweep>& sweeps, const std::vector<std::string>& values, Measure what,
            const Truth& truth) {
  for (std::size_t i = 0; i < sweeps.size(); ++i) settings.push_back(sweeps[i].key + "=" + values[i]);
  const SceneFile scene = loadScene(file, settings);
  SceneRenderer renderer(scene);
  renderer.renderFrame(0);  // warm-up: shader compilation, first uploads
  FrameRequest request;
  request.timed = true;
  request.readBack = true;
  const RenderedFrame frame = renderer.renderFrame(0, request);
  Row row;
  row.values = values;
  for (const PassTiming& t : frame.timings) row.totalMs += t.ms;
  if (what == Measure::Reflections) {
    measureReflections(renderer, frame, row);
  } else if (what == Measure::Antialiasing) {
    measureAntialiasing(frame, truth.image, row);
    // The scale changes every pass's cost but the shadow map's, which would only hide the rest.
    row.costMs = row.totalMs - msOf(frame, "shadow");
  } else if (what == Measure::Lod) {
    measureLod(frame, truth, row);
  } else {
    measureShadows(renderer, frame, row);
  }
  return row;
}

void markPareto(std::vector<Row>& rows) {
  for (Row& r : rows) {
    r.pareto = true;
    for (const Row& o : rows) {
      const bool noWorse = o.costMs <= r.costMs && o.errorPct <= r.errorPct;
      const bool better = o.costMs < r.costMs || o.errorPct < r.errorPct;
      if (noWorse && better) r.pareto = false;
    }
  }
}

void writeCsv(const std::filesystem::path& file, const std::vector<Sweep>& sweeps,
              const std::vector<Row>& rows, Measure what) {
  std::ofstream out(file);
  for (const Sweep& s : sweeps) out << s.key << ",";
  for (const char* name : columnNames(what)) out << name << ",";
  out << "total_ms,pareto\n";
  for (const Row& r : rows) {
    for (const auto& v : r.values) out << v << ",";
    for (const double c : r.columns) out << c << ",";
    out << r.totalMs << "," << (r.pareto ? 1 : 0) << "\n";
  }
}

// Points coloured by the anti-aliasing, the shadow mode or else the warp when swept (else by the first
// sweep's value).
void writePlot(const std::filesystem::path& file, const std::vector<Sweep>& sweeps,
               const std::vector<Row>& rows, Measure what) {
  std::size_t by = 0;
  for (const char* key : {"render.shadow.warp", "render.shadow.mode", "render.antialiasing"})
    for (std::size_t i = 0; i < sweeps.size(); ++i) {
      if (sweeps[i].key == key) by = i;
    }
  std::vector<PlotPoint> points;
  for (const Row& r : rows) {
    const auto& names = sweeps[by].values;
    const int group = static_cast<int>(std::find(names.begin(), names.end(), r.values[by]) - names.begin());
    points.push_back({r.costMs, r.errorPct, group, r.pareto});
  }
  const char* x = what == Measure::Reflections    ? "reflection ms"
                  : what == Measure::Antialiasing ? "frame ms without the shadow map"
                  : what == Measure::Lod          ? "far terrain ms"
                                                  : "shadow + lighting ms";
  const char* y = what == Measure::Reflections    ? "disagreeing with the truth %"
                  : what == Measure::Antialiasing ? "mean error against 3x3 supersampling %"
                  : what == Measure::Lod          ? "mean error against full detail %"
                                                  : "misclassified %";
  saveImage(file, scatterPlot(points, x, y, sweeps[by].values));
}

}  // namespace

Sweep parseSweep(const std::string& text) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == text.size()) {
    throw Error("--sweep " + text + ": expected KEY=VALUE,VALUE,...");
  }
  Sweep sweep;
  sweep.key = text.substr(0, equals);
  for (std::size_t start = equals + 1; start <= text.size();) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    if (comma == start) throw Error("--sweep " + text + ": an empty value");
    sweep.values.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  return sweep;
}

int runSweep(const std::filesystem::path& scene, const std::vector<std::string>& overrides,
             const std::vector<Sweep>& sweeps, const std::filesystem::path& out) {
  const Measure what = measureOf(sweeps);
  Truth truth;
  if (what == Measure::Antialiasing) truth.image = supersampledTruth(scene, overrides);
  if (what == Measure::Lod) {
    if (loadScene(scene, overrides).lod.distance > kMaxLodTruthChunks)
      throw Error("--sweep render.lod.*: far terrain's truth is made out to " +
                  std::to_string(kMaxLodTruthChunks) +
                  " chunks at most; the scene's render.lod.distance is more");
    truth = lodTruth(scene, overrides);
  }
  std::vector<Row> rows;
  for (const auto& values : combinations(sweeps)) {
    rows.push_back(measure(scene, overrides, sweeps, values, what, truth));
    const Row& r = rows.back();
    std::string name;
    for (std::size_t i = 0; i < sweeps.size(); ++i) name += (i ? " " : "") + sweeps[i].key + "=" + values[i];
    const char* error = what == Measure::Reflections                            ? "disagreeing"
                        : what == Measure::Antialiasing || what == Measure::Lod ? "mean error"
                                                                                : "misclassified";
    std::printf("%s: %s %.3f %% of %zu px, %.1f ms\n", name.c_str(), error, r.errorPct, r.evaluated,
                r.costMs);
    std::fflush(stdout);
  }
  markPareto(rows);
  std::filesystem::create_directories(out);
  writeCsv(out / "sweep.csv", sweeps, rows, what);
  writePlot(out / "sweep.png", sweeps, rows, what);
  std::printf("terrasol-render: %zu combinations; wrote %s and %s\n", rows.size(),
              (out / "sweep.csv").string().c_str(), (out / "sweep.png").string().c_str());
  return static_cast<int>(rows.size());
}

}  // namespace terrasol
