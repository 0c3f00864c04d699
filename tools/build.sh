#!/usr/bin/env bash
# Configures and builds Terrasol. Usage: tools/build.sh [BUILD_DIR] [extra cmake -D options...]
# Shared by play.sh and test.sh so both build the same way.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$root/build}
shift || true
generator=()
if command -v ninja >/dev/null && [[ ! -f "$build/Makefile" ]]; then generator=(-G Ninja); fi
cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build" --parallel "$(nproc)"
