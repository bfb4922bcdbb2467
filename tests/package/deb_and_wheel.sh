#!/usr/bin/env bash
# The packages a user installs, checked as they would be used: `cpack` in a build folder makes the Debian
# package, which is extracted (dpkg-deb -x) into an empty folder and its CLI, man pages and Python module run
# from there, away from the source and build trees; then `pip wheel` from the same build (SCALCAL_BUILD_DIR),
# installed with pip into an empty folder and imported. Prints the sizes and times.
# Usage: tests/package/deb_and_wheel.sh BUILD_DIR   (a configured and built folder; ctest runs it as package.deb_and_wheel)
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:?usage: deb_and_wheel.sh BUILD_DIR}" && pwd)
python=/usr/bin/python3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "deb_and_wheel: $*" >&2; exit 1; }

start=$(date +%s)
(cd "$build" && cpack -G DEB -B "$work/cpack" >"$work/cpack.log" 2>&1) || { tail -20 "$work/cpack.log"; fail "cpack failed"; }
deb=$(ls "$work"/cpack/scalcal_*.deb)
deb_seconds=$(($(date +%s) - start))
depends=$(dpkg-deb -f "$deb" Depends)
for library in libginac coinor-libipopt libmpfi python3-numpy; do
  [[ "$depends" == *"$library"* ]] || fail "the package's Depends lack $library: $depends"
done
root="$work/root"
mkdir "$root"
dpkg-deb -x "$deb" "$root"
cd "$work"  # away from the source tree and the build

# The CLI reads the tables beside itself (../share/scalcal/data); SCALCAL_DATA would point elsewhere.
out=$(env -u SCALCAL_DATA "$root/usr/bin/scalcal" evaluate table1-A)
[[ "$out" == *"16490126.5"* ]] || fail "the extracted CLI's evaluate printed: $out"
limits=$(env -u SCALCAL_DATA "$root/usr/bin/scalcal" limits)
[[ "$limits" == *"61509375/4"* ]] || fail "the extracted CLI's limits printed: $limits"
for page in scalcal scalcal-optimize scalcal-calibrate scalcal-export; do
  grep -q '^\.TH' "$root/usr/share/man/man1/$page.1" || fail "no man page $page.1"
done

# The module from the package's dist-packages, with the package's tables.
env -u PYTHONPATH SCALCAL_DATA="$root/usr/share/scalcal/data" "$python" - "$root" <<'PY' || fail "the extracted module failed"
import sys
sys.path.insert(0, sys.argv[1] + "/usr/lib/python3/dist-packages")
import scalcal
assert scalcal.__file__.startswith(sys.argv[1]), scalcal.__file__
d = scalcal.evaluate("table1-A")["D"]
assert d > 0, d
print(f"deb_and_wheel: the .deb's module {scalcal.__version__}: evaluate('table1-A') D = {d}")
PY

# A wheel from the same build, installed into an empty folder.
start=$(date +%s)
(cd "$source_dir" && SCALCAL_BUILD_DIR="$build" PIP_NO_INDEX=1 "$python" -m pip wheel --no-build-isolation --no-deps \
  -w "$work/wheel" . >"$work/wheel.log" 2>&1) || { tail -20 "$work/wheel.log"; fail "pip wheel failed"; }
wheel=$(ls "$work"/wheel/scalcal-*.whl)
PIP_NO_INDEX=1 "$python" -m pip install --no-deps --target "$work/site" "$wheel" >"$work/install.log" 2>&1 ||
  { tail -20 "$work/install.log"; fail "pip install of the wheel failed"; }
wheel_seconds=$(($(date +%s) - start))
env -u PYTHONPATH -u SCALCAL_DATA "$python" - "$work/site" <<'PY' || fail "the wheel's module failed"
import sys
sys.path.insert(0, sys.argv[1])
import scalcal
assert scalcal.__file__.startswith(sys.argv[1]), scalcal.__file__
print(f"deb_and_wheel: the wheel's module: evaluate('table1-A') D = {scalcal.evaluate('table1-A')['D']}")
PY
echo "deb_and_wheel: $(basename "$deb") $(($(stat -c %s "$deb") / 1024)) KB in ${deb_seconds} s," \
  "$(basename "$wheel") $(($(stat -c %s "$wheel") / 1024)) KB in ${wheel_seconds} s"
