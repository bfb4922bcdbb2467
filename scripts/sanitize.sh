#!/usr/bin/env bash
# The test suite's areas that read input and run the CLI (SCALCAL_SANITIZED_AREAS: the CLI, calibration,
# robustness, bench, gyro, export, thermal, and the docs' examples) again, built with clang,
# AddressSanitizer and UndefinedBehaviorSanitizer (-O1, line tables; the checks are in
# scripts/sanitizer_flags.sh) into build-asan/, with libFuzzer's coverage instrumentation so that
# scripts/fuzz.sh links its fuzzers against the same objects instead of building the libraries a second
# time. Any sanitizer report aborts its test, so zero failures means zero findings. Left out (they read no
# input and cost half the sanitized build's 55 CPU-minutes and a third of its run): the synthesis, region,
# certify, model, numeric (its readers are fuzzed), symbolic and plot suites, the proof checks, the house rules, and embedded.host (the C
# library's host check, which runs unsanitized in embedded/check.sh). Arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
source scripts/sanitizer_flags.sh
configure=()
if [ ! -f build-asan/CMakeCache.txt ]; then
  configure+=(-G Ninja)
  if command -v ccache >/dev/null; then configure+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
fi
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS="$sanitizer_cxx_flags" \
  -DCMAKE_EXE_LINKER_FLAGS="$sanitizer_link_flags" -DCMAKE_SHARED_LINKER_FLAGS="$sanitizer_link_flags" \
  -DSCALCAL_FUZZ=ON -DSCALCAL_BENCH=OFF -DSCALCAL_MPI=OFF -DSCALCAL_PACKAGE_TEST=OFF -DSCALCAL_PYTHON=OFF \
  -DSCALCAL_TEST_ONLY="${SCALCAL_SANITIZED_AREAS:-cli;calibration;robustness;bench;gyro;export;thermal}" \
  -DSCALCAL_BUILD_PROOFS=OFF \
  "${configure[@]}" >/dev/null
# The build runs the test executables too (GoogleTest's discovery), so the options come first.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
cmake --build build-asan -j"$(nproc)"
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -LE "rules|embedded" "$@"
