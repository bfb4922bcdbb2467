#!/usr/bin/env bash
# Configures and builds scalcal (Release) into build/; used by main.sh and test.sh. Arguments are
# the targets to build (default: everything, tests included).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
