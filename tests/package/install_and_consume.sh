#!/usr/bin/env bash
# Installs the build tree into a temporary prefix, then builds and runs a consumer against it twice:
# with find_package(scalcal) (CMake) and with pkg-config scalcal-numeric (plain g++); and runs the
# installed CLI, which must find the paper's tables in <prefix>/share/scalcal/data; the installed Python
# module and man page.
# Usage: install_and_consume.sh BUILD_DIR SOURCE_DIR [PYTHON]  (PYTHON: the interpreter of the module)
set -euo pipefail
build="$1"
here="$2/tests/package"
python="${3:-}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$here/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" >/dev/null
"$work/consumer/consumer"
export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig"
# shellcheck disable=SC2046
g++ -DNUMERIC_ONLY "$here/consumer/main.cpp" -o "$work/consumer_pc" $(pkg-config --cflags --libs scalcal-numeric)
"$work/consumer_pc"
# Into a file first: `| grep -q` would close the pipe early and, under pipefail, fail on the CLI's SIGPIPE.
env -u SCALCAL_DATA "$work/prefix/bin/scalcal" evaluate table1-A --json >"$work/evaluate.json"
grep -q '"D"' "$work/evaluate.json"
# The Python module, when the build made one: imported from the prefix alone (the build tree's
# python/ folder is not on the path), it gives the installed CLI's D.
module=$(find "$work/prefix" -name '_scalcal.cpython-*.so' | head -n 1)
if [ -n "$python" ] && [ -z "$module" ]; then
  echo "no Python module installed under $work/prefix" >&2
  exit 1
fi
if [ -n "$module" ] && [ -n "$python" ]; then
  PYTHONPATH="$(dirname "$(dirname "$module")")" "$python" - "$work/evaluate.json" "$work/prefix" <<'PY'
import json, sys
import scalcal
assert scalcal.__file__.startswith(sys.argv[2]), scalcal.__file__
want = json.load(open(sys.argv[1]))["D"]
got = scalcal.evaluate("table1-A")["D"]
assert got == want, (got, want)
PY
  echo "installed Python module: $module"
fi
# The man pages: `man scalcal-optimize` finds the installed page and shows the options of the installed CLI.
page="$work/prefix/share/man/man1/scalcal-optimize.1"
test -f "$page" || { echo "no man page $page" >&2; exit 1; }
if command -v man >/dev/null; then
  [ "$(MANPATH="$work/prefix/share/man" man -w scalcal-optimize)" = "$page" ]
  MANPATH="$work/prefix/share/man" man scalcal-optimize >"$work/man.txt" 2>/dev/null
  grep -q -- '--positions' "$work/man.txt"
  echo "installed man page: $page"
fi
echo "installed package: CMake and pkg-config consumers and the installed CLI work"
