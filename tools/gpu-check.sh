#!/usr/bin/env bash
# The GPU check: Terrasol on a real GPU through EGL's device platform (no display needed).
#   1. the GL test suite, golden images compared with a tolerance for another rasterizer (goldens are
#      made on llvmpipe), with the NaN, shadow-error and reflection-error checks the suite holds;
#   2. every camera-path golden, likewise, through terrasol-render;
#   3. frame times at 1920x1080, view distance 16, shadows 4096², on the benchmark paths
#      (benchmarks/flight.json, still.json): GPU ms per pass, NaN pixels, shadow error;
#   4. a short report with the GL renderer string (also written to build-gpu/gpu-check/report.txt).
#
#   tools/gpu-check.sh              install what is missing, build into build-gpu/, check
#   tools/gpu-check.sh --bundle     build build-gpu/ for a machine where nothing can be installed: image
#                                   files through stb (TERRASOL_IMAGE_IO=stb: OpenImageIO's ~250 libraries
#                                   cannot travel), the few shared libraries it needs in build-gpu/lib
#   tools/gpu-check.sh --prebuilt   check with build-gpu/ as it is (a bundle carried to the GPU machine)
# GPU_TOLERANCE="PIXEL,PERCENT" sets the golden tolerance (default 24,2: 24/255 on at most 2 % of pixels).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build-gpu
mode=${1:-build}

case $mode in
  build)
    "$root/tools/deps.sh"
    "$root/tools/build.sh" "$build" -DTERRASOL_TESTS=ON -DTERRASOL_IMAGE_IO=oiio
    ;;
  --bundle)
    "$root/tools/deps.sh"
    generator=()
    if command -v ninja >/dev/null && [[ ! -f "$build/Makefile" ]]; then generator=(-G Ninja); fi
    cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DTERRASOL_IMAGE_IO=stb >/dev/null
    cmake --build "$build" --parallel "$(nproc)" --target terrasol_gl_tests terrasol-render
    # Every shared library the programs load but the C and C++ runtimes and the GL vendor's own.
    rm -rf "$build/lib" && mkdir -p "$build/lib"
    ldd "$build/tests/terrasol_gl_tests" "$build/terrasol-render" | awk '/=> \//{print $3}' | sort -u |
      grep -v -E '/(libc|libm|libdl|librt|libpthread|libgcc_s|libstdc\+\+|libEGL|libGL|libGLX|libGLdispatch|libOpenGL)\.so' |
      xargs -r cp -L -t "$build/lib"
    echo "$root" > "$build/source-dir"
    du -sh "$build/lib" "$build/tests/terrasol_gl_tests" "$build/terrasol-render"
    exit 0
    ;;
  --prebuilt)
    [[ -x $build/terrasol-render ]] || { echo "gpu-check: no build in $build (tools/gpu-check.sh --bundle)" >&2; exit 2; }
    # The tests name goldens and scenes by the path they were built in.
    if [[ -f $build/source-dir ]]; then
      built_in=$(cat "$build/source-dir")
      if [[ $built_in != "$root" && ! -e $built_in ]]; then mkdir -p "$(dirname "$built_in")" && ln -s "$root" "$built_in"; fi
    fi
    export LD_LIBRARY_PATH=$build/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
    ;;
  *)
    sed -n '2,16p' "$0" >&2
    exit 2
    ;;
esac

# EGL without a display: Mesa's surfaceless platform (NVIDIA's EGL has it too), else the device
# platform; TERRASOL_EGL_PLATFORM=device (or surfaceless) insists on one.
export TERRASOL_EGL_PLATFORM=${TERRASOL_EGL_PLATFORM:-}
tolerance=${GPU_TOLERANCE:-24,2}
export TERRASOL_GOLDEN_TOLERANCE=$tolerance
out=$build/gpu-check
rm -rf "$out" && mkdir -p "$out"
render=$build/terrasol-render

# 1. The GL suite (the game's window tests need an X display: left out).
set +e
"$build/tests/terrasol_gl_tests" --gtest_filter='-GameWindowTest.*' --gtest_brief=1 > "$out/gl_tests.log" 2>&1
gl_status=$?
set -e

# 2. The camera-path goldens.
paths_ok=0 paths_all=0 paths_failed=""
threshold=$(awk -F, '{print $1 / 255}' <<< "$tolerance")
percent=${tolerance#*,}
for scene in "$root"/tests/scenes/paths/*.json; do
  name=$(basename "$scene" .json)
  paths_all=$((paths_all + 1))
  if "$render" "$scene" --out "$out/paths/$name" --compare "$root/tests/goldens/paths/$name" \
       --threshold "$threshold" --max-failing "$percent" >> "$out/paths.log" 2>&1; then
    paths_ok=$((paths_ok + 1))
  else
    paths_failed+=" $name"
  fi
done

# 3. Frame times at the target settings (GPU time per pass, after a warm-up frame) with the game's
#    shadow schedule (an unchanged map kept, a changed one rebuilt over 8 frames), and one frame of the
#    flight with the report: the GL renderer, NaN pixels, shadow error against the ray-traced truth.
target=(--set render.width=1920 --set render.height=1080 --set render.view_distance=16 --set render.shadow.resolution=4096)
for bench in flight still; do
  "$render" "$root/benchmarks/$bench.json" --out "$out/$bench" --timings --no-images --game-shadows \
    --set render.shadow.update_frames=8 "${target[@]}" > "$out/$bench.log" 2>&1 || true
done
"$render" "$root/benchmarks/flight.json" --out "$out/frame" --report "$out/frame.json" "${target[@]}" \
  --set camera_path.frames=1 > "$out/frame.log" 2>&1 || true

# 4. The report.
python3 - "$out" "$paths_ok" "$paths_all" "$paths_failed" "$tolerance" <<'EOF' | tee "$out/report.txt"
import json, re, statistics, sys
out, ok, total, failed, tolerance = sys.argv[1:6]
log = open(f"{out}/gl_tests.log").read()
passed = re.search(r"\[  PASSED  \] (\d+) test", log)
failures = sorted(set(re.findall(r"\[  FAILED  \] ([\w./]+)", log)))
frame = json.load(open(f"{out}/frame.json"))
print(f"GL: {frame['gl']}")
print(f"GL tests: {passed.group(1) if passed else 0} passed, {len(failures)} failed"
      + (f" ({', '.join(failures)})" if failures else "") + f"; goldens within {tolerance} (1/255, % of pixels)")
print(f"camera-path goldens: {ok} of {total} match" + (f"; differ:{failed}" if failed else ""))
f0 = frame["frames"][0]
shadow = f0.get("shadow_error", {})
print(f"one flight frame at 1920x1080: NaN/Inf pixels {f0['nan_pixels']}; shadow pixels false shadow "
      f"{shadow.get('false_shadow_pct', float('nan')):.3f} %, false lit {shadow.get('false_lit_pct', float('nan')):.3f} %")
for bench in ("flight", "still"):
    frames = []
    for line in open(f"{out}/{bench}.log"):
        m = re.match(r"frame_\d+\.png:(.*)", line)
        if m:
            frames.append({k: float(v) for k, v in re.findall(r" (\S+) ([\d.]+) ms", m.group(1))})
    totals = sorted(sum(f.values()) for f in frames)
    if not totals:
        print(f"{bench}: no frames (see {out}/{bench}.log)")
        continue
    worst = totals[min(len(totals) - 1, int(len(totals) * 0.99))]
    print(f"{bench}: {len(frames)} frames at 1920x1080, view 16, shadows 4096 (the game's schedule): GPU ms a frame median "
          f"{statistics.median(totals):.2f}, 99th percentile {worst:.2f}")
    names = list(dict.fromkeys(n for f in frames for n in f))
    print("  per pass, median ms: " + ", ".join(f"{n} {statistics.median(f.get(n, 0.0) for f in frames):.2f}" for n in names))
EOF
