#!/usr/bin/env bash
# Installs the Debian packages scalcal needs, only those missing (as root; no other network).
# libopenblas0-serial becomes the libblas.so.3 / liblapack.so.3 that Ipopt's MUMPS loads (Debian's
# alternatives): single-threaded, as the multistart already runs one worker per core. groff-base checks the
# man pages (ctest); clang-format checks the layout (ctest -L rules); pip, venv, setuptools and wheel are for `pip install .` (scripts/pip_check.sh). dpkg-dev (dpkg-shlibdeps) is for `cpack`'s Debian package (tests/package/deb_and_wheel.sh). emscripten, chromium,
# chromium-driver and python3-selenium build the page at the bench and test it in a real browser (web/check.sh).
# python3-jsonschema checks the requests' JSON Schemas (docs/schema/) independently of scalcal.
set -euo pipefail
packages=(cmake ninja-build g++ make pkg-config libeigen3-dev libboost-dev libginac-dev libcln-dev coinor-libipopt-dev
  gnuplot-nox libgtest-dev libbenchmark-dev libmpfr-dev libmpfi-dev libgmp-dev
  libopenblas0-serial
  libcli11-dev nlohmann-json3-dev libfmt-dev libopenmpi-dev openmpi-bin
  clang libclang-rt-dev clang-format
  python3-numpy python3-scipy python3-dev python3-pytest pybind11-dev python3-pybind11
  groff-base python3-setuptools python3-wheel python3-pip python3-venv dpkg-dev
  emscripten chromium chromium-driver python3-selenium python3-jsonschema)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
echo "scalcal: installing missing packages: ${missing[*]}" >&2
if [ "$(id -u)" -ne 0 ]; then
  echo "scalcal: run as root (or install these packages first): ${missing[*]}" >&2
  exit 2
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
