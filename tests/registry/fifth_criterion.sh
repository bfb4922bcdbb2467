#!/usr/bin/env bash
# The I criterion, registered as a fifth criterion (scripts/fifth_criterion.sh), through every
# subcommand that takes a criterion or reports them all: each gives a value or a clear "no known
# limit", never an internal error. Expected values by hand (tests/optimize/new_criterion_test.cpp):
# I = 46/5 for classic18, and I = 9 for any spherical 4-design, below which no program goes.
# Usage: fifth_criterion.sh SCALCAL
set -uo pipefail
cli="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "fifth criterion: $*" >&2; failures=$((failures + 1)); }

# run NAME EXPECTED_STATUS ARGS...: the status, no internal error; stdout in $work/NAME.out, stderr in .err
run() {
  local name="$1" want="$2"
  shift 2
  "$cli" "$@" >"$work/$name.out" 2>"$work/$name.err"
  local got=$?
  [ "$got" = "$want" ] || fail "$name: exit $got, expected $want: $(head -c 300 "$work/$name.err")"
  if grep -q "internal error" "$work/$name.err"; then fail "$name: internal error: $(cat "$work/$name.err")"; fi
}
has() { grep -q -- "$2" "$work/$1.$3" || fail "$1: no '$2' in its std$3: $(head -c 300 "$work/$1.$3")"; }
near() {  # near NAME KEY VALUE TOLERANCE: a number in the JSON on stdout
  /usr/bin/python3 - "$work/$1.out" "$2" "$3" "$4" <<'PY' || fail "$1: $2 is not $3 within $4"
import json, sys
v = json.load(open(sys.argv[1]))
for k in sys.argv[2].split("."):
    v = v[int(k)] if isinstance(v, list) else v[k]
assert abs(float(v) - float(sys.argv[3])) <= float(sys.argv[4]), v
PY
}

run help 0 help optimize
has help "I = N tr(K W)" out
run evaluate 0 evaluate classic18 --json
near evaluate I 9.2 1e-12
run evaluate_text 0 evaluate classic18
has evaluate_text "I  N tr(K W)" out
run catalogue 0 catalogue
run optimize 0 optimize --positions 12 --criterion I --starts 4 --seed 1 --threads 1 --json
near optimize value 9 1e-9
run optimize_region 0 optimize --positions 12 --criterion I --region cap:100 --starts 2 --threads 1 --json
run random 0 random --positions 12 --count 2000 --criterion I --threads 1 --json
run sweep 0 sweep --positions 12 --criteria D,I --starts 2 --threads 1 --json --no-timing
near sweep 1.value 9 1e-9
has sweep '"ratio": null' out
run polish 0 polish icosahedral-20 --criterion I --digits 30 --json
has polish "no known limit" out
run certify 2 certify classic18 --criterion I
has certify "no known limit for criterion I" err
run augment 0 augment --program classic18 --add 2 --criterion I --json
run jig 0 jig cuboctahedron --criterion I --starts 4 --json
has jig '"limit": null' out
run limits 0 limits
has limits "I: no known limit" out
run limits_region 0 limits --region cap:60 --json
has limits_region '"I": null' out
run family 0 family octahedral --json
run simulate 0 simulate --program classic18 --trials 20 --noise 1e-3 --seed 1
run calibrate_suggest 0 calibrate --measurements "$(dirname "$0")/../../data/xsens_acc.txt" --magnitude 9.81744 --criterion I --suggest 2 --json
has calibrate_suggest '"I"' out
if [ "$failures" -gt 0 ]; then
  echo "fifth criterion: $failures failure(s)" >&2
  exit 1
fi
echo "fifth criterion: I ran through every subcommand (evaluate, catalogue, optimize, random, sweep, polish, certify, augment, jig, limits, family, simulate, calibrate)"
