#!/usr/bin/env bash
# The main job: installs what is missing, builds, and regenerates the paper's figures and tables
# (scalcal reproduce) into results/. Extra arguments go to `scalcal reproduce`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh scalcal  # only what the main job needs: the CLI, not the tests
./build/experiments/scalcal reproduce --out results "$@"
