#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite (GoogleTest, proof checks, docs examples),
# then the CLI with a fifth criterion registered (scripts/fifth_criterion.sh), the build without GiNaC
# (scripts/without_ginac.sh), the C library's whole check
# (embedded/check.sh) and the web page's in headless chromium (web/check.sh);
# then the suite's input-reading areas under AddressSanitizer + UndefinedBehaviorSanitizer (scripts/sanitize.sh)
# and libFuzzer on every reader for 30 s each (scripts/fuzz.sh). SCALCAL_SANITIZERS=0 skips those two.
# Every scalcal process and test runs on OpenBLAS's Prescott kernel (numeric/io/blas_kernel.hpp), and
# determinism.kernels compares whole outputs under Prescott and Haswell.
# Arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
# "Registered means everywhere": the CLI built with a fifth criterion, run through every subcommand.
bash scripts/fifth_criterion.sh
bash scripts/without_ginac.sh  # the build without GiNaC: no GiNaC/CLN linked, the same outputs (docs/library.md)
bash embedded/check.sh  # the firmware library: host tests, Cortex-M4F cross-build, size, QEMU (embedded/README.md)
bash web/check.sh  # the page at the bench: WebAssembly build, headless chromium against the CLI (docs/web.md)
if [ "${SCALCAL_SANITIZERS:-1}" != 0 ]; then
  bash scripts/sanitize.sh "$@"
  bash scripts/fuzz.sh 30
fi
