#!/usr/bin/env bash
# The main job: installs what is missing, builds, and regenerates the paper's figures and tables
# (scalcal reproduce) into results/. Extra arguments go to `scalcal reproduce`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/experiments/scalcal reproduce --out results "$@"
