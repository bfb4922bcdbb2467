#!/usr/bin/env bash
# Installs the build tree into a temporary prefix, then builds and runs a consumer against it twice:
# with find_package(scalcal) (CMake) and with pkg-config scalcal-numeric (plain g++); and runs the
# installed CLI, which must find the paper's tables in <prefix>/share/scalcal/data.
# Usage: install_and_consume.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$1"
here="$2/tests/package"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$here/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" >/dev/null
"$work/consumer/consumer"
export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig"
# shellcheck disable=SC2046
g++ -DNUMERIC_ONLY "$here/consumer/main.cpp" -o "$work/consumer_pc" $(pkg-config --cflags --libs scalcal-numeric)
"$work/consumer_pc"
# Into a file first: `| grep -q` would close the pipe early and, under pipefail, fail on the CLI's SIGPIPE.
env -u SCALCAL_DATA "$work/prefix/bin/scalcal" evaluate table1-A --json >"$work/evaluate.json"
grep -q '"D"' "$work/evaluate.json"
echo "installed package: CMake and pkg-config consumers and the installed CLI work"
