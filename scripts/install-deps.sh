#!/usr/bin/env bash
# Installs the Debian packages zeroset needs to build, test and benchmark.
# With --fuzz it adds clang and its libFuzzer and sanitizer runtimes
# (scripts/fuzz.sh). Idempotent: when everything is present it only checks
# and returns at once.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkgconf       # toolchain
  libpng-dev                          # PNG output
  libopenexr-dev openexr              # EXR output; exrheader reads it back in the tests
  libhwy-dev                          # SIMD with run-time dispatch (Highway)
  libgtest-dev libgmock-dev           # tests
  libmpfi-dev libmpfr-dev libgmp-dev  # high-precision oracles for the tests
  libbenchmark-dev                    # benchmarks
  python3-dev pybind11-dev            # the Python module, for Debian's python3
  python3-numpy python3-pytest        # …its arrays and its tests
  povray povray-examples              # POV-Ray's include files and sample scenes: the importer's corpus test and comparisons
  libopenmpi-dev openmpi-bin          # distributed rendering (mpirun -n N zeroset render; docs/distributed.md)
)
if [ "${1:-}" = "--fuzz" ]; then
  packages+=(clang libclang-rt-dev)      # libFuzzer, ASan, UBSan
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
