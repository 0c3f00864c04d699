#!/usr/bin/env bash
# Checks that every C++ file of the project is as clang-format 14 (Debian 12's, which tools/deps.sh
# installs) writes it with the root .clang-format, naming each file and line that is not;
# `tools/check-format.sh --fix` rewrites them instead. The test suite runs the check
# (ctest -R clang_format); another clang-format version formats differently, so there it skips (77).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
version=$(clang-format --version 2>/dev/null | grep -o 'version [0-9]*' | cut -d' ' -f2 || true)
if [[ $version != 14 ]]; then
  echo "check-format: needs clang-format 14 (found: ${version:-none}); not checked" >&2
  exit 77
fi
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.h')
else
  mapfile -t files < <(find engine game tools tests -name '*.cpp' -o -name '*.h' | sort)
fi
if [[ ${1:-} == --fix ]]; then
  clang-format -i "${files[@]}"
  exit 0
fi
clang-format --dry-run --Werror "${files[@]}"
echo "check-format: ${#files[@]} files as clang-format writes them"
