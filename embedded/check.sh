#!/usr/bin/env bash
# The whole check of the embedded C library (embedded/README.md): host tests in float and double
# (unit tests with simulated truth and fuzzed streams; equality with `scalcal calibrate` on every
# real log), the cross-compilation for a Cortex-M4F (-Os, -mfpu=fpv4-sp-d16 -mfloat-abi=hard) with
# warnings as errors, the size report, and QEMU's mps2-an386 running the whole streaming path on the
# Xsens log through semihosting, whose output must equal the host build's bit for bit. Installs
# what it needs with apt-get when missing (as root). The last line is
#   flash N bytes, ram M bytes
# for the float paper9 build with 64 poses (the worked example with the library: text + data, and
# data + bss + the stack's peak measured under QEMU).
# Usage: bash embedded/check.sh [--host] [--out DIR] [SCALCAL]   (--host: the host tests only; DIR:
# where to build, default build/embedded; SCALCAL: the CLI to compare with, default
# build/experiments/scalcal, built when missing.)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
out="$root/build/embedded"
host_only=0
scalcal=""
while [ $# -gt 0 ]; do
  case "$1" in
    --host) host_only=1 ;;
    --out) out="$2"; shift ;;
    *) scalcal="$1" ;;
  esac
  shift
done
mkdir -p "$out"
t0=$(date +%s)
step() { echo "== $* ($(($(date +%s) - t0)) s)"; }

# Packages: a host C compiler (gcc, or the clang the project builds with) and Python; the cross
# toolchain, newlib and QEMU for the target part.
need=()
cc=$(command -v gcc || command -v clang || true)
[ -n "$cc" ] || need+=(gcc libc6-dev)
command -v python3 >/dev/null || need+=(python3)
if [ "$host_only" = 0 ]; then
  command -v arm-none-eabi-gcc >/dev/null || need+=(gcc-arm-none-eabi)
  [ -f /usr/lib/arm-none-eabi/newlib/thumb/v7e-m+fp/hard/libc.a ] || need+=(libnewlib-arm-none-eabi)
  command -v qemu-system-arm >/dev/null || need+=(qemu-system-arm)
fi
if [ ${#need[@]} -gt 0 ]; then
  [ "$(id -u)" = 0 ] || { echo "embedded/check.sh: missing ${need[*]}; run as root to install them" >&2; exit 2; }
  step "installing ${need[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y --no-install-recommends "${need[@]}" >/dev/null ||
    { apt-get update -qq && apt-get install -y --no-install-recommends "${need[@]}" >/dev/null; }
  cc=$(command -v gcc || command -v clang)
fi

sources=("$here"/src/*.c)
host_flags=(-std=c99 -pedantic -Wall -Wextra -Werror -O2 -ffp-contract=off -I"$here/include" -I"$here/src")
xsens="$root/data/xsens_acc.txt"

step "host builds (float, double)"
for prec in float double; do
  def=()
  [ "$prec" = double ] && def=(-DSCALCAL_DOUBLE)
  objects=()
  for s in "${sources[@]}"; do
    "$cc" "${host_flags[@]}" "${def[@]}" -c "$s" -o "$out/host_$(basename "$s" .c)_$prec.o"
    objects+=("$out/host_$(basename "$s" .c)_$prec.o")
  done
  "$cc" "${host_flags[@]}" "${def[@]}" "${objects[@]}" "$here/tests/unit_test.c" -lm -o "$out/unit_$prec"
  "$cc" "${host_flags[@]}" "${def[@]}" "${objects[@]}" "$here/tests/planar_test.c" -lm -o "$out/planar_$prec"
  "$cc" "${host_flags[@]}" "${def[@]}" "${objects[@]}" "$here/tests/tumble_test.c" -lm -o "$out/tumble_$prec"
  "$cc" "${host_flags[@]}" "${def[@]}" "${objects[@]}" "$here/tests/log_reader.c" "$here/tests/host_run.c" -lm \
    -o "$out/host_run_$prec"
  "$cc" "${host_flags[@]}" "${def[@]}" -I"$here/tests/qemu" -DLOG_PATH="\"$xsens\"" "${objects[@]}" \
    "$here/tests/qemu/qemu_main.c" "$here/tests/qemu/host_io.c" -lm -o "$out/stream_host_$prec"
  "$cc" "${host_flags[@]}" "${def[@]}" -I"$here/tests" "${objects[@]}" "$here/tests/log_reader.c" \
    "$here/tests/export_header_test.c" -lm -o "$out/export_header_$prec"
done
# The reference of the CLI comparison: the same algorithm in long double (host only).
"$cc" "${host_flags[@]}" -DSCALCAL_LONG_DOUBLE "${sources[@]}" "$here/tests/log_reader.c" "$here/tests/host_run.c" \
  -lm -o "$out/host_run_long"

step "unit tests: simulated truth, fuzzed streams, records, guidance, planar layouts, tumbling; the export header"
for prec in float double; do
  "$out/unit_$prec"
  "$out/planar_$prec"
  "$out/tumble_$prec"
done
"$out/export_header_float" "$xsens"
"$out/export_header_double" "$xsens"

step "equality with scalcal calibrate on the real logs"
if [ -z "$scalcal" ]; then
  scalcal="$root/build/experiments/scalcal"
  [ -x "$scalcal" ] || (cd "$root" && nice -n 10 bash scripts/build.sh scalcal)
fi
python3 "$here/tests/compare_cli.py" "$scalcal" "$out/host_run_double" "$out/host_run_float" "$out/host_run_long" \
  "$root/data" "$root/../shared/data"
[ "$host_only" = 1 ] && { step "host tests passed"; exit 0; }

arm_flags=(-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -Os -std=c99 -pedantic -Wall -Wextra
  -ffp-contract=off -fno-math-errno -ffunction-sections -fdata-sections -I"$here/include" -I"$here/src"
  -I"$here/tests/qemu")
link=(-T "$here/tests/qemu/mps2_an386.ld" -nostartfiles -Wl,--gc-sections -lm)
step "cross-compilation for the Cortex-M4F (float, double)"
declare -A flash ram stack mag_flash mag_ram mag_stack
for prec in float double; do
  def=()
  [ "$prec" = double ] && def=(-DSCALCAL_DOUBLE)
  # The library alone with warnings as errors; then the size build (the worked example on the
  # smallest board), the worked example on the log, and the streaming test, linked from its objects.
  objects=()
  for s in "${sources[@]}"; do
    arm-none-eabi-gcc "${arm_flags[@]}" "${def[@]}" -Werror -c "$s" -o "$out/$(basename "$s" .c)_$prec.o"
    objects+=("$out/$(basename "$s" .c)_$prec.o")
  done
  arm-none-eabi-gcc "${arm_flags[@]}" "${def[@]}" -c "$here/tests/qemu/startup.c" -o "$out/startup_$prec.obj"
  arm-none-eabi-gcc "${arm_flags[@]}" "${def[@]}" -c "$here/tests/qemu/semihost.c" -o "$out/semihost_$prec.obj"
  target=("$out/startup_$prec.obj" "$out/semihost_$prec.obj")
  arm-none-eabi-gcc "${arm_flags[@]}" "${def[@]}" "${objects[@]}" "$here/examples/imu_calibration.c" \
    "$here/examples/board_stub.c" "${target[@]}" "${link[@]}" -o "$out/size_$prec.elf"
  arm-none-eabi-gcc "${arm_flags[@]}" "${def[@]}" -DLOG_PATH="\"$xsens\"" "${objects[@]}" \
    "$here/examples/imu_calibration.c" "$here/examples/board_qemu.c" "${target[@]}" "${link[@]}" -o "$out/example_$prec.elf"
  arm-none-eabi-gcc "${arm_flags[@]}" "${def[@]}" -DLOG_PATH="\"$xsens\"" "${objects[@]}" \
    "$here/tests/qemu/qemu_main.c" "${target[@]}" "${link[@]}" -o "$out/stream_$prec.elf"
  # The tumbling magnetometer's firmware (examples/mag_calibration.c): its size, and its run on the
  # QMC5883L log (t ix iy iz, 50 Hz).
  arm-none-eabi-gcc "${arm_flags[@]}" "${def[@]}" "${objects[@]}" "$here/examples/mag_calibration.c" \
    "$here/examples/board_stub.c" "${target[@]}" "${link[@]}" -o "$out/size_mag_$prec.elf"
  arm-none-eabi-gcc "${arm_flags[@]}" "${def[@]}" -DLOG_PATH="\"$out/qmc5883l_t.txt\"" "${objects[@]}" \
    "$here/examples/mag_calibration.c" "$here/examples/board_qemu.c" "${target[@]}" "${link[@]}" \
    -o "$out/mag_example_$prec.elf"
  echo "$prec: the library's objects (arm-none-eabi-size -t):"
  arm-none-eabi-size -t "${objects[@]}" | tail -1
  echo "$prec: the worked example with the library, smallest board:"
  arm-none-eabi-size "$out/size_$prec.elf"
  read -r text data bss _ < <(arm-none-eabi-size "$out/size_$prec.elf" | tail -1)
  flash[$prec]=$((text + data))
  ram[$prec]=$((data + bss))
  echo "$prec: the tumbling magnetometer example with the library, smallest board:"
  arm-none-eabi-size "$out/size_mag_$prec.elf"
  read -r text data bss _ < <(arm-none-eabi-size "$out/size_mag_$prec.elf" | tail -1)
  mag_flash[$prec]=$((text + data))
  mag_ram[$prec]=$((data + bss))
done
qmc="$root/../shared/data/qmc5883l_mag.csv"
[ -f "$qmc" ] && awk -F, 'NR > 1 { printf "%.2f %s %s %s\n", (NR - 2) / 50, $1, $2, $3 }' "$qmc" > "$out/qmc5883l_t.txt"

qemu() { timeout 300 qemu-system-arm -M mps2-an386 -nographic -semihosting-config enable=on,target=native -kernel "$1" 2>&1; }
step "QEMU mps2-an386: the streaming path on $(basename "$xsens"), against the host build"
for prec in float double; do
  qemu "$out/stream_$prec.elf" > "$out/stream_qemu_$prec.txt"
  "$out/stream_host_$prec" > "$out/stream_hostrun_$prec.txt"
  if ! diff <(grep -v '^stack_peak_bytes' "$out/stream_qemu_$prec.txt") "$out/stream_hostrun_$prec.txt"; then
    echo "embedded/check.sh: the Cortex-M4F ($prec) and the host give different results (above)" >&2
    exit 1
  fi
  echo "$prec: $(grep -c . "$out/stream_hostrun_$prec.txt") result lines bit for bit the same ($(grep '^poses' "$out/stream_hostrun_$prec.txt"), $(grep '^status' "$out/stream_hostrun_$prec.txt"))"
  qemu "$out/example_$prec.elf" > "$out/example_qemu_$prec.txt"
  grep -q '^calibrated' "$out/example_qemu_$prec.txt" || { cat "$out/example_qemu_$prec.txt"; exit 1; }
  stack[$prec]=$(sed -n 's/^stack_peak_bytes //p' "$out/example_qemu_$prec.txt")
  echo "$prec: worked example calibrated on QEMU; stack peak ${stack[$prec]} bytes;" \
    "flash ${flash[$prec]} bytes, ram $((ram[$prec] + stack[$prec])) bytes (static ${ram[$prec]} + stack ${stack[$prec]})"
  if [ -f "$out/qmc5883l_t.txt" ]; then
    qemu "$out/mag_example_$prec.elf" > "$out/mag_example_qemu_$prec.txt"
    grep -q '^calibrated' "$out/mag_example_qemu_$prec.txt" || { cat "$out/mag_example_qemu_$prec.txt"; exit 1; }
    mag_stack[$prec]=$(sed -n 's/^stack_peak_bytes //p' "$out/mag_example_qemu_$prec.txt")
    echo "$prec: tumbling magnetometer example calibrated the QMC5883L log on QEMU ($(grep -c . "$out/mag_example_qemu_$prec.txt") lines:" \
      "$(grep -v stack_peak "$out/mag_example_qemu_$prec.txt" | tr '\n' ';' | cut -c1-300));" \
      "flash ${mag_flash[$prec]} bytes, ram $((mag_ram[$prec] + mag_stack[$prec])) bytes" \
      "(static ${mag_ram[$prec]} + stack ${mag_stack[$prec]})"
  fi
done
step "embedded check passed"
echo "flash ${flash[float]} bytes, ram $((ram[float] + stack[float])) bytes"
