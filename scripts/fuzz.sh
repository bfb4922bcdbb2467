#!/usr/bin/env bash
# libFuzzer on every reader (tests/fuzz/), built with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer, each run for SECONDS (default 60) from a seed corpus of the CSV files
# the repository already has. The fuzzers are built in build-asan/ when scripts/sanitize.sh has
# configured it (its objects carry the fuzzer's instrumentation), else in build-fuzz/. A crash, a
# sanitizer report, an input that takes over 10 s or a failed round trip stops the run and exits
# non-zero; the input is kept in BUILD/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
bash scripts/install-deps.sh
build=build-fuzz
if grep -qs '^SCALCAL_FUZZ:BOOL=ON' build-asan/CMakeCache.txt; then
  build=build-asan
else
  source scripts/sanitizer_flags.sh
  cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS="$sanitizer_cxx_flags" \
    -DCMAKE_EXE_LINKER_FLAGS="$sanitizer_link_flags" -DSCALCAL_FUZZ=ON -DSCALCAL_MPI=OFF -DSCALCAL_PYTHON=OFF >/dev/null
fi
targets=(fuzz_program_csv fuzz_measurements_csv fuzz_catalogue_name fuzz_region_spec fuzz_calibration_json
  fuzz_family_params fuzz_program_name fuzz_file_quoting)
cmake --build "$build" -j"$(nproc)" $(printf -- '--target %s ' "${targets[@]}")

# Seeds: the programs and bench files in the repository, and a few catalogue names.
corpus="$build"/corpus
rm -rf "$corpus" && mkdir -p "$build"/findings
for t in "${targets[@]}"; do mkdir -p "$corpus/$t"; done
# A previous run's findings are replayed as corpus inputs, then cleared: a run fails on what it finds
# itself, and an input that once crashed or hung fails it again until fixed.
for t in "${targets[@]}"; do
  for f in "$build"/findings/"$t"-*; do
    if [ -e "$f" ]; then mv "$f" "$corpus/$t/finding-$(basename "$f")"; fi
  done
done
find data experiments/docs -name '*.csv' | while read -r f; do
  if head -c 4096 "$f" | grep -q 'ix'; then
    for m in 0 1; do { printf "\\x3$m"; cat "$f"; } >"$corpus/fuzz_measurements_csv/$m-$(basename "$f")"; done
  else
    cp "$f" "$corpus/fuzz_program_csv/"
  fi
done
i=0
for name in classic18 rotation-6 rotation-6-p15 octahedral-1-0-1 random-18-s7 dodecahedral-12 icosahedral-20 \
  nine-2axes table1-A table3-S; do
  printf '%s' "$name" >"$corpus/fuzz_catalogue_name/$((i++))"
done
# The dialects the reader takes (issue 33): quoted fields, ';' with decimal commas, text position labels.
printf '"X","Y","Z"\n"1","0","0"\n"0,5",-1,"2"\n' >"$corpus/fuzz_program_csv/quoted.csv"
printf 'x;y;z\n1;0;0\n0,5;-1;2\n' >"$corpus/fuzz_program_csv/semicolon.csv"
printf '\x30Position,IX,IY,IZ\n"P1",1,0,0\nP1,1.1,0,0\nP2,0,1,0\n' >"$corpus/fuzz_measurements_csv/labels.csv"
for m in 2 6; do  # a raw log (text), magnitude auto and 1
  { printf "\\x3$m"; head -c 30000 data/xsens_acc.txt; } >"$corpus/fuzz_measurements_csv/raw$m-xsens"
done
i=0
for specs in sphere cap:30 'cap:30:1,1,1' band:60:120 'band:10:170:0,1,0' faces:20 $'cap:20\ncap:20:0,0,-1'; do
  printf '%s' "$specs" >"$corpus/fuzz_region_spec/$((i++))"
done
# A calibration as calibrate --out writes it (the keys correct reads), and one refused as unconverged.
printf '%s' '{"format_version": 1, "model": "paper9", "converged": true, "magnitude": 9.81,
 "offset": [0.05, -0.02, 0.03], "matrix": [[1.01, 0.002, 0], [0, 0.99, -0.001], [0.003, 0, 1.0]]}' \
  >"$corpus/fuzz_calibration_json/0"
printf '%s' '{"converged": false, "offset": [0, 0, 0], "matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}' \
  >"$corpus/fuzz_calibration_json/1"
# Family parameters: the first byte picks the family (by its index), then KEY=VALUE lines.
i=0
for p in $'\x00axes=2\nedges=1' $'\x01k=7\nphase=15' $'\x02orientation=aa:1,2,3,40' $'\x03orientation=q:1,0,0,1' \
  $'\x04axes=sqrt(2)' $'\x05orientation=rows:1,0,0,0,1,0,0,0,1'; do
  printf '%s' "$p" >"$corpus/fuzz_family_params/$((i++))"
done
i=0
for name in 'jig:cube@orientation=aa:1,2,3,40' 'jig:cuboctahedron' 'jig:dodecahedron@orientation=q:1,0,0,1' \
  'dodecahedral-12' 'icosahedral-20'; do
  printf '%s' "$name" >"$corpus/fuzz_program_name/$((i++))"
done
# Quoting (issue 50): gnuplot strings (first byte even) and region lines (odd; specs apart by 0x1E).
i=0
for q in $'\x02x\'.system(\'touch P\').\'.pdf' $'\x02a"b\\c`touch P`@m$v\nline\x1b\xff\xfe\xc3\xa9' \
  $'\x02\xe2\x89\xa5 \xce\xb8_{/*1.1 bias}' $'\x01cap:30\x1ecandidates:a;b.csv' \
  $'\x01candidates: sp ace\nx\x1ecap:20:0,0,-1' $'\x01candidates:"q"\\x\rz'; do
  printf '%s' "$q" >"$corpus/fuzz_file_quoting/$((i++))"
done
export SCALCAL_DATA="$PWD/data"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
# The targets that link GiNaC meet CLN's own allocations at exit, as the sanitizer run does.
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# One fuzzer per core at a time (each is single-threaded): the same seconds per reader in half the wall time on two
# cores; the reports follow in the readers' order once all have run.
fuzz_one() {
  "$build"/tests/fuzz/"$1" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$build"/findings/"$1"- "$corpus/$1" >"$build/$1.log" 2>&1 || true
}
running=0
for t in "${targets[@]}"; do
  fuzz_one "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$(nproc)" ]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait
total=0
for t in "${targets[@]}"; do
  log="$build"/$t.log
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  echo "scalcal fuzz: $t: ${runs:-0} inputs in $seconds s, corpus $(ls "$corpus/$t" | wc -l) files" >&2
  if [ -n "$(ls "$build"/findings/"$t"-* 2>/dev/null)" ] || [ -z "$runs" ]; then
    grep -E 'ERROR|SUMMARY|Test unit written|==[0-9]+==' "$log" | head -20 >&2 || true
    echo "scalcal fuzz: $t failed (log: $log)" >&2
    exit 1
  fi
  total=$((total + runs))
done
echo "scalcal fuzz: ${#targets[@]} readers, $total inputs, no finding" >&2
