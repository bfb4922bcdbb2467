#!/usr/bin/env bash
# web/build.sh: builds the page into web/build/page/ (index.html, app.js, scalcal_core.js: the WebAssembly core
# inlined, so the folder works from file:// offline) with Debian's emscripten; the CMake tree is web/build/cmake.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out="$here/build"
for tool in emcmake em++ cmake ninja; do
  command -v "$tool" >/dev/null || { echo "web/build.sh: $tool is missing (apt-get install emscripten cmake ninja-build)" >&2; exit 2; }
done
# Debian's emscripten runs its JS tools with `node` and finds acorn etc. in /usr/share/nodejs, which a node not
# from Debian (nodesource's) does not search by itself.
export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"
# (Debian ships emscripten's system libraries prebuilt, in a frozen cache: nothing is built into it.)
mkdir -p "$out/cmake" "$out/page"
emcmake cmake -S "$here" -B "$out/cmake" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
nice ninja -C "$out/cmake" -j "${WEB_JOBS:-2}"
cp "$here/index.html" "$here/app.js" "$out/cmake/scalcal_core.js" "$out/page/"
echo "web/build.sh: the page is $out/page/index.html"
