#!/bin/sh
# Every stability scene (tests/scenes/extreme) drawn with every optional pass on: TAA (its resolved
# history is checked too), bloom, clouds with their shadows (fancy and volumetric, scene by scene in
# turn), reflections, height fog and shafts. No crash, no GL error, no NaN or Inf in any float target
# on any frame. Pictures change with the passes, so none is compared.
#   extreme_every_pass.sh RENDER SCENES_DIR OUT
set -eu
render=$1 scenes=$2 out=$3
rm -rf "$out"
clouds=fancy
for scene in "$scenes"/*.json; do
  name=$(basename "$scene" .json)
  clouds=$([ "$clouds" = fancy ] && echo volumetric || echo fancy)
  "$render" "$scene" --out "$out/$name" --report "$out/$name/report.json" --no-images \
    --set 'render.antialiasing="taa"' --set 'render.bloom={"enabled": true, "strength": 0.1}' \
    --set "render.clouds={\"mode\": \"$clouds\", \"shadows\": true}" --set render.reflections.enabled=true \
    --set 'render.fog={"density": 0.02, "base": 64, "falloff": 24}' --set 'render.shafts={"enabled": true}'
  frames=$(grep -c '"nan_pixels"' "$out/$name/report.json")
  clean=$(grep -c '"nan_pixels": 0' "$out/$name/report.json")
  echo "$name ($clouds clouds): $clean of $frames frames free of NaN and Inf"
  [ "$frames" -gt 0 ] && [ "$frames" -eq "$clean" ]
done
