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
for p in /usr/bin/chromium /usr/bin/chromedriver /usr/bin/em++; do [ -x "$p" ] || missing+=("$p"); done
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
# The Xsens log's gravity, from its publishers (../shared/data/README.md).
cd "$here/test" && exec /usr/bin/python3 browser_test.py "$here/build/page" "$cli" "$log" 9.81744 "$work"
