#!/usr/bin/env bash
# `pip install --no-build-isolation .` as a user runs it: a fresh virtualenv over Debian's python3 (NumPy
# through --system-site-packages), offline (no package index), then `import scalcal; scalcal.correct` and
# one call that reads the paper's tables from the installed package. Prints the install's time.
# Usage: scripts/pip_check.sh [--fresh] [PYTHON]   (default /usr/bin/python3). The CMake build is setup.py's
# build-pip/, kept between installs; --fresh removes it first (and CCACHE_DISABLE=1 makes the build cold).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--fresh" ]; then
  rm -rf build-pip
  shift
fi
python="${1:-/usr/bin/python3}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$python" -m venv --system-site-packages "$work/venv"
start=$(date +%s)
PIP_NO_INDEX=1 "$work/venv/bin/pip" install --no-build-isolation . >"$work/pip.log" 2>&1 ||
  { tail -n 30 "$work/pip.log"; echo "pip_check: pip install failed" >&2; exit 1; }
seconds=$(($(date +%s) - start))
cd "$work"  # away from the source tree, whose python/scalcal has no extension
env -u SCALCAL_DATA -u PYTHONPATH "$work/venv/bin/python" - "$work/venv" <<'PY'
import sys
import scalcal
assert scalcal.__file__.startswith(sys.argv[1]), f"imported {scalcal.__file__}, not the virtualenv's"
assert callable(scalcal.correct)
d = scalcal.evaluate("table1-A")["D"]  # a catalogue program read from the package's data/
assert d > 0, d
print(f"pip_check: scalcal {scalcal.__version__} from {scalcal.__file__}; evaluate('table1-A') D = {d}")
PY
wheel_mb=$(du -sm "$work/venv/lib/"python3*/site-packages/scalcal | cut -f1)
echo "pip_check: pip install took ${seconds} s; the installed package is ${wheel_mb} MB"
