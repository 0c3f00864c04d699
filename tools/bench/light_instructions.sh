#!/bin/bash
# Instructions executed by each light update of a benchmark, counted by callgrind: steadier than the
# clock on a shared machine. Prints the last six LightEngine::blockChanged calls (in the torch
# benchmarks they alternate between the timed edit and its untimed undo).
# usage: tools/bench/light_instructions.sh [BENCH_BINARY] [FILTER]
set -euo pipefail
bench=${1:-build/terrasol-bench}
filter=${2:-BM_LightTorchPlace}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# Enough iterations (under callgrind an update takes about a millisecond) to leave first-use
# allocations behind.
valgrind --tool=callgrind --callgrind-out-file="$dir/cg.out" --toggle-collect='*LightEngine::blockChanged*' \
  --dump-after='terrasol::LightEngine::blockChanged*' "$bench" --benchmark_filter="$filter" \
  --benchmark_min_time=0.3 >/dev/null 2>&1
for part in $(ls -v "$dir"/cg.out.* | tail -6); do
  callgrind_annotate "$part" 2>/dev/null | awk '/PROGRAM TOTALS/ {printf "%s ", $1}'
done
echo
