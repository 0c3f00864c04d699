#include "sweep.h"

#include <cstdio>
#include <fstream>

#include "core/error.h"
#include "scene_render/scene_render.h"
#include "scene_render/shadow_truth.h"
#include "sweep_plot.h"

namespace terrasol {
namespace {

struct Row {
  std::vector<std::string> values;  // one per sweep
  ShadowError error;
  double shadowMs = 0.0, lightingMs = 0.0, totalMs = 0.0;
  bool pareto = false;

  double errorPct() const {
    const ShadowCounts& c = error.total;
    return c.evaluated ? 100.0 * static_cast<double>(c.falseLit + c.falseShadow) / static_cast<double>(c.evaluated) : 0.0;
  }
  double costMs() const { return shadowMs + lightingMs; }
};

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

Row measure(const std::filesystem::path& file, std::vector<std::string> settings, const std::vector<Sweep>& sweeps,
            const std::vector<std::string>& values) {
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
  if (frame.geometry.shadowMapShown) {
    row.error = measureShadowError(renderer.world(), frame.pixels, frame.geometry, scene.shadow.distance);
  }
  for (const PassTiming& t : frame.timings) {
    if (t.pass == "shadow") row.shadowMs = t.ms;
    if (t.pass == "lighting") row.lightingMs = t.ms;
    row.totalMs += t.ms;
  }
  return row;
}

void markPareto(std::vector<Row>& rows) {
  for (Row& r : rows) {
    r.pareto = true;
    for (const Row& o : rows) {
      const bool noWorse = o.costMs() <= r.costMs() && o.errorPct() <= r.errorPct();
      const bool better = o.costMs() < r.costMs() || o.errorPct() < r.errorPct();
      if (noWorse && better) r.pareto = false;
    }
  }
}

void writeCsv(const std::filesystem::path& file, const std::vector<Sweep>& sweeps, const std::vector<Row>& rows) {
  std::ofstream out(file);
  for (const Sweep& s : sweeps) out << s.key << ",";
  out << "evaluated_pixels,false_shadow_pct,false_lit_pct,error_pct,ambiguous_pct,shadow_ms,lighting_ms,total_ms,pareto\n";
  for (const Row& r : rows) {
    for (const auto& v : r.values) out << v << ",";
    const ShadowCounts& c = r.error.total;
    const double n = static_cast<double>(std::max<std::size_t>(c.evaluated, 1));
    out << c.evaluated << "," << 100.0 * static_cast<double>(c.falseShadow) / n << ","
        << 100.0 * static_cast<double>(c.falseLit) / n << "," << r.errorPct() << ","
        << 100.0 * static_cast<double>(c.ambiguous) / static_cast<double>(std::max<std::size_t>(c.evaluated + c.ambiguous, 1))
        << "," << r.shadowMs << "," << r.lightingMs << "," << r.totalMs << "," << (r.pareto ? 1 : 0) << "\n";
  }
}

// Points coloured by the shadow mode or else the warp when swept (else by the first sweep's value).
void writePlot(const std::filesystem::path& file, const std::vector<Sweep>& sweeps, const std::vector<Row>& rows) {
  std::size_t by = 0;
  for (const char* key : {"render.shadow.warp", "render.shadow.mode"})
    for (std::size_t i = 0; i < sweeps.size(); ++i) {
      if (sweeps[i].key == key) by = i;
    }
  std::vector<PlotPoint> points;
  for (const Row& r : rows) {
    const auto& names = sweeps[by].values;
    const int group = static_cast<int>(std::find(names.begin(), names.end(), r.values[by]) - names.begin());
    points.push_back({r.costMs(), r.errorPct(), group, r.pareto});
  }
  saveImage(file, scatterPlot(points, "shadow + lighting ms", "misclassified %", sweeps[by].values));
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
  std::vector<Row> rows;
  for (const auto& values : combinations(sweeps)) {
    rows.push_back(measure(scene, overrides, sweeps, values));
    const Row& r = rows.back();
    std::string name;
    for (std::size_t i = 0; i < sweeps.size(); ++i) name += (i ? " " : "") + sweeps[i].key + "=" + values[i];
    std::printf("%s: misclassified %.3f %% of %zu px, shadow %.1f ms + lighting %.1f ms\n", name.c_str(),
                r.errorPct(), r.error.total.evaluated, r.shadowMs, r.lightingMs);
    std::fflush(stdout);
  }
  markPareto(rows);
  std::filesystem::create_directories(out);
  writeCsv(out / "sweep.csv", sweeps, rows);
  writePlot(out / "sweep.png", sweeps, rows);
  std::printf("terrasol-render: %zu combinations; wrote %s and %s\n", rows.size(), (out / "sweep.csv").string().c_str(),
              (out / "sweep.png").string().c_str());
  return static_cast<int>(rows.size());
}

}  // namespace terrasol
