#!/usr/bin/env bash
# One command to play: installs what is missing, builds (Release, in build/), runs the game.
# Arguments go to the game (see `build/terrasol --help`).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/tools/deps.sh"
"$root/tools/build.sh" "$root/build"
exec "$root/build/terrasol" "$@"
