#!/bin/sh
# Every stability scene (tests/scenes/extreme) drawn through a shader pack: no crash, no GL error, no
# NaN or Inf in the pack's float buffers on any frame. Pictures are the pack's, so none is compared.
#   extreme_shaderpack.sh RENDER SCENES_DIR PACK OUT
set -eu
render=$1 scenes=$2 pack=$3 out=$4
rm -rf "$out"
for scene in "$scenes"/*.json; do
  name=$(basename "$scene" .json)
  "$render" "$scene" --out "$out/$name" --shaderpack "$pack" --report "$out/$name/report.json" --no-images
  frames=$(grep -c '"nan_pixels"' "$out/$name/report.json")
  clean=$(grep -c '"nan_pixels": 0' "$out/$name/report.json")
  echo "$name: $clean of $frames frames free of NaN and Inf"
  [ "$frames" -gt 0 ] && [ "$frames" -eq "$clean" ]
done
