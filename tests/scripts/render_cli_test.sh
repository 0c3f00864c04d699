#!/usr/bin/env bash
# terrasol-render's command line, end to end: two runs of a camera-path scene give identical PNGs;
# --compare passes against the goldens and fails (exit 1, diff image written) when one is perturbed or
# missing; bad scenes exit 2 naming the key, and write no frame.
#   render_cli_test.sh TERRASOL_RENDER SCENE GOLDEN_DIR WORK_DIR
set -euo pipefail
exe=$1 scene=$2 goldens=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

"$exe" "$scene" --out "$work/a" > /dev/null
"$exe" "$scene" --out "$work/b" > /dev/null
for f in "$work"/a/frame_*.png; do cmp -s "$f" "$work/b/${f##*/}" || fail "${f##*/} differs between two runs"; done

"$exe" "$scene" --out "$work/c" --compare "$goldens" > "$work/compare.log" || fail "compare against the goldens: $(cat "$work/compare.log")"

# Perturb one golden: frame 0's replaced by frame 1's.
cp -r "$goldens" "$work/perturbed"
cp "$work/perturbed/frame_0001.png" "$work/perturbed/frame_0000.png"
status=0; "$exe" "$scene" --out "$work/d" --compare "$work/perturbed" > "$work/perturbed.log" || status=$?
[ "$status" -eq 1 ] || fail "a perturbed golden gave exit $status, expected 1"
[ -f "$work/d/diff_0000.png" ] || fail "no diff_0000.png for the perturbed frame"
grep -q "frame_0000.png: FAIL" "$work/perturbed.log" || fail "no FAIL line for frame 0"
grep -q "frame_0001.png: ok" "$work/perturbed.log" || fail "frame 1 should still match"
rm "$work/perturbed/frame_0002.png"
status=0; "$exe" "$scene" --out "$work/e" --compare "$work/perturbed" > "$work/missing.log" || status=$?
[ "$status" -eq 1 ] || fail "a missing golden gave exit $status, expected 1"
grep -q "frame_0002.png: FAIL, missing golden" "$work/missing.log" || fail "no line for the missing golden"

# Bad scenes: exit 2, the key named, nothing written.
bad() {  # KEY JSON [ARGS...]
  local key=$1 json=$2; shift 2
  printf '%s\n' "$json" > "$work/bad.json"
  rm -rf "$work/bad"
  status=0; "$exe" "$work/bad.json" --out "$work/bad" "$@" 2> "$work/bad.log" > /dev/null || status=$?
  [ "$status" -eq 2 ] || fail "$json gave exit $status, expected 2"
  grep -qF "$key" "$work/bad.log" || fail "$json: the error does not name $key: $(cat "$work/bad.log")"
  [ ! -e "$work/bad/frame_0000.png" ] || fail "$json wrote a frame"
}
bad 'world.edits[0].block' '{"world": {"generator": "void", "edits": [{"set": [0, 64, 0], "block": "unobtainium"}]}, "render": {"view_distance": 0}}'
bad 'camera_path.keyframes[1]: needs "position"' '{"camera_path": {"frames": 2, "keyframes": [{"t": 0, "position": [0, 80, 0], "look_at": [0, 80, -1]}, {"t": 1, "look_at": [0, 0, 0]}]}}'
bad 'camera_path.keyframes[0].t' '{"camera_path": {"keyframes": [{"t": 1.5, "position": [0, 80, 0], "look_at": [0, 80, -1]}]}}'
bad 'camera.fov' '{"camera": {"fov": "wide"}}'
bad 'render.width' '{}' --set render.width=huge
bad 'world.edits[0].at_frame' '{"world": {"generator": "void", "edits": [{"set": [0, 64, 0], "block": "stone", "at_frame": 3}]}}'
# A sweep: one CSV row per combination, and the chart.
"$exe" "$scene" --out "$work/sweep" --set render.width=80 --set render.height=45 \
  --sweep render.shadow.resolution=256,512 --sweep render.shadow.warp=none,radial > "$work/sweep.log" || fail "sweep: $(cat "$work/sweep.log")"
[ "$(wc -l < "$work/sweep/sweep.csv")" -eq 5 ] || fail "sweep.csv should have a header and 4 rows"
grep -q "^512,radial," "$work/sweep/sweep.csv" || fail "sweep.csv misses the 512,radial row"
[ -s "$work/sweep/sweep.png" ] || fail "no sweep.png"
bad 'render.shadow.warp' '{}' --sweep render.shadow.warp=none,bent
echo "ok"
