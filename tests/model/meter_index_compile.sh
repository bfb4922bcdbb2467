#!/usr/bin/env bash
# A model naming a parameter its meter does not know does not compile; one naming its meter's own does, with the
# index expected by hand from the meter's kParameters order (cubic12's meter: cubic_x the tenth, nonorth_zx the
# ninth; the linear models' meter has no cubic_x at all).
# Usage: meter_index_compile.sh CXX SOURCE_DIR EIGEN_INCLUDE_DIR
set -euo pipefail
cxx="$1" source="$2" eigen="$3"
compile() { "$cxx" -std=c++20 -fsyntax-only -I"$source" -isystem "$eigen" "$@" "$source/tests/model/meter_index_compile.cpp"; }
refused() {  # the compile must fail, and for the reason meter_index_of gives
  local out
  if out=$(compile "$@" 2>&1); then
    echo "a model naming a parameter its meter does not know compiled ($*)" >&2
    exit 1
  fi
  grep -q "a model parameter the meter does not know" <<<"$out" || { echo "$out" | head -20 >&2; exit 1; }
}
compile -DSCALCAL_METER=CubicMeter -DSCALCAL_NAME='"cubic_x"' -DSCALCAL_EXPECTED=9
compile -DSCALCAL_METER=CubicMeter -DSCALCAL_NAME='"nonorth_zx"' -DSCALCAL_EXPECTED=8
compile -DSCALCAL_METER=LinearMeter -DSCALCAL_NAME='"nonorth_zx"' -DSCALCAL_EXPECTED=8
refused -DSCALCAL_METER=CubicMeter -DSCALCAL_NAME='"quartic_x"' -DSCALCAL_EXPECTED=12
refused -DSCALCAL_METER=LinearMeter -DSCALCAL_NAME='"cubic_x"' -DSCALCAL_EXPECTED=9
echo "meter_index_of: a meter's names compile to their indices; one its meter does not know stops the build"
