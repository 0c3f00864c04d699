#!/usr/bin/env bash
# One command to test: installs what is missing, builds, runs every test (GL tests on llvmpipe
# headless, one at a time). `tools/test.sh --sanitize` does the same in build-asan/ with ASan+UBSan.
# Further arguments go to ctest (e.g. -L gl, -R Shader).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build
options=()
if [[ ${1:-} == --sanitize ]]; then
  shift
  build=$root/build-asan
  options=(-DTERRASOL_SANITIZE=ON)
fi
"$root/tools/deps.sh"
"$root/tools/build.sh" "$build" "${options[@]}"
# CPU tests run in parallel; the `gl` ones are RUN_SERIAL because llvmpipe already uses every core.
ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)" "$@"
