#!/usr/bin/env bash
# The build without GiNaC (-DSCALCAL_WITH_GINAC=OFF, docs/library.md): configures build-noginac/ (no tests, no
# plots), builds the CLI and the Python module, checks with readelf that neither needs libginac or libcln, runs
# evaluate, optimize, limits and calibrate and compares them with the normal build's CLI (the same bytes where no
# closed form is involved, the same numbers where one is), and checks the one-line refusals of what it lacks.
# Usage: scripts/without_ginac.sh [NORMAL_CLI]   (default build/experiments/scalcal: build it first,
# bash scripts/build.sh scalcal). SCALCAL_JOBS sets the build's jobs (default: the cores). scripts/test.sh runs
# it: from an empty build-noginac/ the build takes most of its time (557 CPU-s, 5 min at -j2 on 2 cores; the
# checks alone 16 CPU-s, 14 s, docs/library.md).
set -euo pipefail
cd "$(dirname "$0")/.."
normal="$(realpath "${1:-build/experiments/scalcal}")"
[ -x "$normal" ] || { echo "without_ginac: no normal CLI at $normal (bash scripts/build.sh scalcal)" >&2; exit 1; }
configure=()
if [ ! -f build-noginac/CMakeCache.txt ]; then
  configure+=(-G Ninja -DCMAKE_CXX_COMPILER=clang++)
  if command -v ccache >/dev/null; then configure+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
fi
# Without the project's headers in the precompiled ones: the other builds' units see the registries and the program
# (cmake/precompiled_headers.cmake) whether they include them or not, so this build is where a unit that forgets
# to include them fails.
cmake -S . -B build-noginac -DCMAKE_BUILD_TYPE=Release -DSCALCAL_WITH_GINAC=OFF -DSCALCAL_BUILD_TESTS=OFF \
  -DSCALCAL_BUILD_PLOTS=OFF -DSCALCAL_PCH_PROJECT=OFF "${configure[@]}" >/dev/null
targets=(--target scalcal)
if ninja -C build-noginac -t targets all 2>/dev/null | grep -q '^scalcal_python:'; then targets+=(--target scalcal_python); fi
cmake --build build-noginac -j"${SCALCAL_JOBS:-$(nproc)}" "${targets[@]}"
off="$PWD/build-noginac/experiments/scalcal"
module=$(find build-noginac/python/scalcal -name '_scalcal*.so' 2>/dev/null | head -n 1)

fail() {
  echo "without_ginac: $*" >&2
  exit 1
}

# 1. No GiNaC, no CLN among the libraries the binaries need.
for binary in "$off" ${module:+"$module"}; do
  if readelf -d "$binary" | grep -E 'NEEDED.*lib(ginac|cln)'; then fail "$binary needs GiNaC or CLN"; fi
done
echo "without_ginac: readelf: neither $(basename "$off") nor ${module:+$(basename "$module")} needs libginac or libcln"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export SOURCE_DATE_EPOCH=0  # calibrate's "created": the same in both files

# 2. The same bytes on stdout and the same exit status from both CLIs (in JSON the run time aside).
same() {
  local n_status=0 o_status=0
  "$normal" "$@" >"$work/normal.out" 2>/dev/null || n_status=$?
  "$off" "$@" >"$work/off.out" 2>/dev/null || o_status=$?
  [ "$n_status" = "$o_status" ] || fail "scalcal $*: exit $n_status in the normal build, $o_status without GiNaC"
  if [ "${*: -1}" = --json ]; then
    /usr/bin/python3 - "$work" <<'EOF' || fail "scalcal $*: outputs differ"
import json, sys


def equal(n, o):
    """The same JSON, the run time and the builds' commits aside; an `exact` the build without GiNaC leaves null (a
    cap's) is not compared."""
    if isinstance(n, dict) and isinstance(o, dict):
        keys = (set(n) | set(o)) - {"seconds", "commit"}
        return all(k in n and k in o and (k == "exact" and o[k] is None or equal(n[k], o[k])) for k in keys)
    if isinstance(n, list) and isinstance(o, list):
        return len(n) == len(o) and all(equal(a, b) for a, b in zip(n, o))
    return n == o


normal, off = (json.load(open(f"{sys.argv[1]}/{side}.out")) for side in ("normal", "off"))
sys.exit(0 if equal(normal, off) else f"{json.dumps(normal)[:300]}\n  vs {json.dumps(off)[:300]}")
EOF
  else
    cmp -s "$work/normal.out" "$work/off.out" || { diff "$work/normal.out" "$work/off.out" | head -n 20; fail "scalcal $*: outputs differ"; }
  fi
  echo "without_ginac: same output: scalcal $*"
}
same evaluate icosahedral-20
same evaluate octahedral-1-1-1 --json
same evaluate data/table1_A.csv --model bias3 --json
same optimize --positions 12 --criterion D --seed 1 --json
same optimize --positions 10 --criterion E --region cap:90 --seed 1 --json  # a cap's limit: no closed form
same calibrate --measurements data/xsens_acc.txt --magnitude 9.81744 --json
same calibrate --instrument gyro --measurements data/xsens_gyro.txt --accelerometer data/xsens_acc.txt \
  --accelerometer-magnitude 9.81744 --json
# The real logs of the shared data beside the repository (../shared/data, issue 31), where present.
shared="$PWD/../shared/data"
if [ -d "$shared" ]; then
  same calibrate --measurements "$shared/mpu6050_acc.csv" --rate 100 --magnitude 9.80665 --json
  same calibrate --measurements "$shared/nilspod_ferraris_acc.csv" --rate 102.4 --magnitude 9.81 --json
  same calibrate --measurements "$shared/qmc5883l_mag.csv" --rate 50 --magnitude auto --json
fi

# 3. limits: the same numbers, statuses and stated forms; the exact moments and a cap's closed form are the
# normal build's alone.
"$normal" limits --out "$work/normal.csv" --json >"$work/normal.json"
"$off" limits --out "$work/off.csv" --json >"$work/off.json"
cmp "$work/normal.csv" "$work/off.csv" || fail "limits --out differs"
"$normal" limits --region cap:60 --out "$work/normal_cap.csv" --json >"$work/normal_cap.json"
"$off" limits --region cap:60 --out "$work/off_cap.csv" --json >"$work/off_cap.json"
"$normal" limits --model paper9+T2 --temperature 0..40 --json >"$work/normal_thermal.json"
"$off" limits --model paper9+T2 --temperature 0..40 --json >"$work/off_thermal.json"
/usr/bin/python3 - "$work" <<'EOF' || fail "limits: the builds differ"
import json, sys


def strip(o):
    """The JSON without the closed forms, which the build without GiNaC gives only where numeric/ states them."""
    if isinstance(o, dict):
        return {k: strip(v) for k, v in o.items() if k not in ("E[x^4]", "E[x^2 y^2]", "exact")}
    return [strip(v) for v in o] if isinstance(o, list) else o


def exacts(o, path=""):
    if isinstance(o, dict):
        out = {path: o["exact"]} if "exact" in o else {}
        for k, v in o.items():
            out.update(exacts(v, path + "/" + k))
        return out
    return {}


for name in ("", "_cap", "_thermal"):
    normal, off = (json.load(open(f"{sys.argv[1]}/{side}{name}.json")) for side in ("normal", "off"))
    if strip(normal) != strip(off):
        sys.exit(f"limits{name}: {json.dumps(strip(normal))[:300]}\n  vs {json.dumps(strip(off))[:300]}")
    derived = exacts(normal)
    for path, text in exacts(off).items():  # a form given without GiNaC is the one GiNaC derives
        if text is not None and text != derived.get(path):
            sys.exit(f"limits{name}: {path}: exact {text!r}, derived {derived.get(path)!r}")
print("without_ginac: limits (sphere, cap:60, paper9+T2): the same values, statuses and bounds; forms as derived")
EOF

# 4. What the build lacks: one line each, exit 2.
refused() {
  local status=0 err
  err=$("$off" "$@" 2>&1 >/dev/null) || status=$?
  [ "$status" = 2 ] || fail "scalcal $*: exit $status, not 2"
  [ "$(printf '%s\n' "$err" | wc -l)" = 1 ] || fail "scalcal $*: more than one line: $err"
  case "$err" in *GiNaC*) ;; *) fail "scalcal $*: the line does not name GiNaC: $err" ;; esac
  echo "without_ginac: refused: scalcal $* -> $err"
}
refused family octahedral
refused jig cube
refused help family
refused schema family
refused evaluate jig:cube
"$off" --help | grep -q 'not in this build (made with -DSCALCAL_WITH_GINAC=OFF, without GiNaC): family, jig' ||
  fail "--help does not name the lacking commands"

# 5. The Python module: build_info, the lacking commands, and the CLI's numbers.
if [ -n "$module" ]; then
  "$off" evaluate icosahedral-20 --json >"$work/evaluate.json"
  PYTHONPATH=build-noginac/python /usr/bin/python3 - "$work/evaluate.json" <<'EOF' || fail "the Python module"
import json, sys
import scalcal
info = scalcal.build_info()
assert info["ginac"] is False and sorted(info["lacking"]) == ["family", "jig"], info
try:
    scalcal.family("octahedral")
    raise SystemExit("scalcal.family ran")
except scalcal.UsageError as e:
    assert "-DSCALCAL_WITH_GINAC=OFF" in str(e), e
cli = json.load(open(sys.argv[1]))
py = json.loads(json.dumps(scalcal.evaluate("icosahedral-20"), default=lambda a: a.tolist()))
assert py == cli, (py, cli)
print("without_ginac: Python: build_info", info["ginac"], sorted(info["lacking"]), "; evaluate as the CLI's")
EOF
fi
echo "without_ginac: passed"
