#!/usr/bin/env bash
# "Registered means everywhere": builds the CLI with the I criterion (numeric/criteria/
# integrated_variance.hpp) registered as a fifth criterion into build-fifth/ (the CLI only, -O1, synthesis
# for the paper's model only: the script uses no other),
# then runs it through every subcommand that takes a criterion (tests/registry/fifth_criterion.sh).
# Called by scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
configure=()
if [ ! -f build-fifth/CMakeCache.txt ]; then
  configure+=(-G Ninja -DCMAKE_CXX_COMPILER=clang++)
  if command -v ccache >/dev/null; then configure+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
fi
cmake -S . -B build-fifth -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
  -DSCALCAL_FIFTH_CRITERION=ON -DSCALCAL_MODELS=paper9 -DSCALCAL_BUILD_TESTS=OFF -DSCALCAL_BUILD_PLOTS=OFF -DSCALCAL_PYTHON=OFF \
  -DSCALCAL_BENCH=OFF -DSCALCAL_MPI=OFF "${configure[@]}" >/dev/null
cmake --build build-fifth -j"$(nproc)" --target scalcal
bash tests/registry/fifth_criterion.sh build-fifth/experiments/scalcal
