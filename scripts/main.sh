#!/usr/bin/env bash
# The main job: installs what is missing, builds, and regenerates the paper's figures and tables
# (scalcal reproduce) into results/. Extra arguments go to `scalcal reproduce`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh scalcal  # only what the main job needs: the CLI, not the tests
# The Python module the README's Python section uses, where the build has it (pybind11 found, SCALCAL_PYTHON on).
if cmake --build build --target help | grep -q '^scalcal_python:'; then
  cmake --build build -j"$(nproc)" --target scalcal_python
fi
./build/experiments/scalcal reproduce --out results "$@"
echo "scalcal is built; to call it by name, as the README and docs/ do, run from $PWD:"
echo "export PATH=\$PWD/build/experiments:\$PATH"
