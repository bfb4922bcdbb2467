#!/usr/bin/env bash
# A model naming a parameter the meter does not know does not compile; one naming the meter's own does, with the
# index expected by hand from ModelMeter::kParameters' order (cubic_x is the tenth, nonorth_zx the ninth).
# Usage: meter_index_compile.sh CXX SOURCE_DIR EIGEN_INCLUDE_DIR
set -euo pipefail
cxx="$1" source="$2" eigen="$3"
compile() { "$cxx" -std=c++20 -fsyntax-only -I"$source" -isystem "$eigen" "$@" "$source/tests/model/meter_index_compile.cpp"; }
compile -DSCALCAL_NAME='"cubic_x"' -DSCALCAL_EXPECTED=9
compile -DSCALCAL_NAME='"nonorth_zx"' -DSCALCAL_EXPECTED=8
if out=$(compile -DSCALCAL_NAME='"quartic_x"' -DSCALCAL_EXPECTED=12 2>&1); then
  echo "a model naming quartic_x, which the meter does not know, compiled" >&2
  exit 1
fi
grep -q "a model parameter the meter does not know" <<<"$out" || { echo "$out" | head -20 >&2; exit 1; }
echo "meter_index_of: the meter's names compile to their indices; an unknown one stops the build"
