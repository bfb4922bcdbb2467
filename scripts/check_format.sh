#!/usr/bin/env bash
# Checks that every C++ source of the tree (not the .in templates CMake fills) is as clang-format 14
# (.clang-format) leaves it; with --fix, formats them. Exit 1 naming the files that differ. Needs the clang-format package.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then bad+=("$f"); fi
done
if [ "${#bad[@]}" -gt 0 ]; then
  echo "check_format: ${#bad[@]} files differ from clang-format's output: ${bad[*]:0:10}" >&2
  exit 1
fi
