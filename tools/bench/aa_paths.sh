#!/bin/sh
# Anti-aliasing on moving views: each mode and render scale over the dense camera paths in
# tools/bench/scenes, every frame against its 3x3 supersampled truth, and the anti-aliasing passes'
# time. Prints per run the mean over frames 4 on (TAA's history carried by motion, past the still
# start) of aa_error mean and edge_over_pct, the largest ghost over_pct of a frame with at least 200
# changed pixels, and the median ms of the taa, fxaa and final passes.
# Usage: tools/bench/aa_paths.sh [BUILD_DIR] (default build); about eight minutes on llvmpipe.
set -eu
build=${1:-build}
here=$(dirname "$0")
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for scene in ${TERRASOL_AA_SCENES:-aa_walk_terrain aa_showcase_turn aa_lake_walk}; do
  for run in none:1 fxaa:1 taa:1 none:0.67 taa:0.67; do
    aa=${run%:*}
    scale=${run#*:}
    "$build/terrasol-render" "$here/scenes/$scene.json" --out "$out" --no-images --timings \
      --reference-supersample 3 --set render.antialiasing="$aa" --set render.scale="$scale" >"$out/log"
    python3 - "$out/log" "$scene" "$aa" "$scale" <<'PY'
import re, statistics, sys
log, scene, aa, scale = sys.argv[1:5]
kFewest = 200  # changed pixels below which a frame's ghost share says little
error, edges, ghost, ms = [], [], [0.0], {}
for line in open(log):
    frame = re.match(r"frame_(\d+)\.png: (.*)", line)
    if not frame:
        continue
    index, rest = int(frame.group(1)), frame.group(2)
    m = re.match(r"aa_error mean ([\d.]+) p99 [\d.]+ edges over ([\d.]+) %(?:, ghost over ([\d.]+) % of (\d+))?", rest)
    if m:
        if index >= 4:
            error.append(float(m.group(1)))
            edges.append(float(m.group(2)))
        if m.group(3) and int(m.group(4)) >= kFewest:
            ghost.append(float(m.group(3)))
        continue
    for p, t in re.findall(r"(\w+) ([\d.]+) ms", rest):
        ms.setdefault(p, []).append(float(t))
passes = "  ".join(f"{p} {statistics.median(ms[p]):.1f} ms" for p in ("taa", "fxaa", "final") if p in ms)
print(f"{scene:17} {aa:4} scale {scale:4}: mean {statistics.mean(error):.4f}  edges over "
      f"{statistics.mean(edges):4.1f} %  ghost over {max(ghost):4.1f} %  {passes}")
PY
  done
done
