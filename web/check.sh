#!/usr/bin/env bash
# web/check.sh: builds the page (web/build.sh) and runs the browser test (web/test/browser_test.py) in Debian's
# headless chromium against the CLI; the last line is `page N bytes compressed, design S s, calibrate S s`.
# Fails (exit 1) on any difference with the CLI, and (exit 2) when a part is missing, never passing without it.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
cli="${SCALCAL_CLI:-$root/build/experiments/scalcal}"
log="${SCALCAL_WEB_LOG:-$root/../shared/data/xsens_acc.txt}"
missing=()
[ -x "$cli" ] || missing+=("the CLI at $cli (bash scripts/build.sh, or SCALCAL_CLI=...)")
[ -f "$log" ] || missing+=("the log $log (../shared/data, or SCALCAL_WEB_LOG=...)")
for p in /usr/bin/chromium /usr/bin/chromedriver /usr/bin/em++ /usr/bin/g++ /usr/bin/gcc; do [ -x "$p" ] || missing+=("$p"); done
/usr/bin/python3 -c "import selenium" 2>/dev/null || missing+=("python3-selenium")
if [ ${#missing[@]} -gt 0 ]; then
  printf 'web/check.sh: missing: %s\n' "${missing[@]}" >&2
  echo "web/check.sh: apt-get install emscripten chromium chromium-driver python3-selenium" >&2
  exit 2
fi
log="$(realpath "$log")"  # chromedriver takes only a canonical path for the file input
bash "$here/build.sh"
work="$here/build/test"
rm -rf "$work" && mkdir -p "$work"
# The charconv shim (web/wasm/charconv_compat.hpp) against libstdc++'s own floating to_chars/from_chars: 60,000
# numbers written and edge cases read must print identically.
export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"
g++ -std=c++20 -O1 -o "$work/charconv_host" "$here/test/charconv_check.cpp"
em++ -std=c++20 -O1 -sSINGLE_FILE=1 -include "$here/wasm/charconv_compat.hpp" -o "$work/charconv_wasm.js" \
  "$here/test/charconv_check.cpp"
"$work/charconv_host" >"$work/charconv_host.txt"
node "$work/charconv_wasm.js" >"$work/charconv_wasm.txt"
if ! cmp -s "$work/charconv_host.txt" "$work/charconv_wasm.txt"; then
  diff "$work/charconv_host.txt" "$work/charconv_wasm.txt" | head -20 >&2
  echo "web/check.sh: the charconv shim differs from libstdc++'s to_chars/from_chars" >&2
  exit 1
fi
echo "web/check.sh: charconv shim: $(wc -l <"$work/charconv_host.txt") lines equal to libstdc++'s"
# The Guide's reference: embedded/'s own host driver (tests/host_run.c) built in double as embedded/check.sh's
# host_run_double (the page's build of the library is double too, web/CMakeLists.txt).
emb="$root/embedded"
gcc -std=c99 -O2 -ffp-contract=off -DSCALCAL_DOUBLE -I"$emb/include" -I"$emb/src" "$emb"/src/*.c \
  "$emb/tests/log_reader.c" "$emb/tests/host_run.c" -lm -o "$work/host_run_double"
# The Xsens log's gravity, from its publishers (../shared/data/README.md).
cd "$here/test" && exec /usr/bin/python3 browser_test.py "$here/build/page" "$cli" "$log" 9.81744 "$work" "$work/host_run_double"
