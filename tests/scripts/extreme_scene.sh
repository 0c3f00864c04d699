#!/bin/sh
# One stability scene (tests/scenes/extreme): rendered with --report and compared, frame by frame,
# with its goldens or with another scene's frames. Fails on a non-zero exit (a GL error, a bad scene, a
# frame that differs) and on any frame with NaN or Inf in a float target.
#   extreme_scene.sh RENDER SCENE OUT COMPARE_DIR [golden]
# With "golden" and TERRASOL_UPDATE_GOLDENS=1 the goldens are written instead, on purpose.
set -eu
render=$1 scene=$2 out=$3 compare=$4 kind=${5:-}
rm -rf "$out"
update=""
if [ "$kind" = golden ] && [ -n "${TERRASOL_UPDATE_GOLDENS:-}" ]; then update=--update-goldens; fi
"$render" "$scene" --out "$out" --report "$out/report.json" --compare "$compare" $update
frames=$(grep -c '"nan_pixels"' "$out/report.json")
clean=$(grep -c '"nan_pixels": 0' "$out/report.json")
echo "$clean of $frames frames free of NaN and Inf"
[ "$frames" -gt 0 ] && [ "$frames" -eq "$clean" ]
