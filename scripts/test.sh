#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite (GoogleTest, proof checks, docs examples),
# then the CLI with a fifth criterion registered (scripts/fifth_criterion.sh);
# then the same suite under AddressSanitizer + UndefinedBehaviorSanitizer (scripts/sanitize.sh) and
# libFuzzer on every reader for 30 s each (scripts/fuzz.sh). SCALCAL_SANITIZERS=0 skips those two.
# Arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
# The docs' printed numbers under another BLAS kernel than the machine's own (issue 49): OpenBLAS's generic
# SSE2 one (ctest -L determinism compares whole outputs under two kernels).
OPENBLAS_CORETYPE=Prescott ctest --test-dir build --output-on-failure -j"$(nproc)" -L docs
# "Registered means everywhere": the CLI built with a fifth criterion, run through every subcommand.
bash scripts/fifth_criterion.sh
bash embedded/check.sh  # the firmware library: host tests, Cortex-M4F cross-build, size, QEMU (embedded/README.md)
if [ "${SCALCAL_SANITIZERS:-1}" != 0 ]; then
  bash scripts/sanitize.sh "$@"
  bash scripts/fuzz.sh 30
fi
