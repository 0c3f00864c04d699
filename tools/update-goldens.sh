#!/usr/bin/env bash
# Rewrites the golden images from the current renderer, on purpose. Look at every changed image
# (git diff --stat tests/goldens) and say why in the commit message.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/tools/build.sh" "$root/build"
TERRASOL_UPDATE_GOLDENS=1 ctest --test-dir "$root/build" -L gl --output-on-failure "$@"
git -C "$root" status --short -- tests/goldens
