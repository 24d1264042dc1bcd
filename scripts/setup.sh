#!/usr/bin/env bash
# Installs what eomgen needs from Debian's packages (only what is missing), then configures and builds.
# Usage: scripts/setup.sh [--no-build | --packages-only] [extra cmake -D options...]
#        (build directory: $EOMGEN_BUILD_DIR, default build/; --no-build: install and configure only;
#        --packages-only: install only)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ccache_env.sh

packages=(g++ cmake make pkg-config libginac-dev libcln-dev libeigen3-dev catch2 libtomlplusplus-dev
          libcli11-dev libfmt-dev libbenchmark-dev libboost-dev gnuplot-nox
          libudunits2-dev              # the units of the model files' values (generator/model/units.hpp)
          libceres-dev                 # optional for eomgen: eomgen fit, least squares (generator/cli/fit_solve.hpp)
          ccache                       # optional: recompiles only what changed, across checkouts (CMakeLists.txt)
          dpkg-dev file   # cpack -G DEB (dpkg-shlibdeps, and file to find the binaries)
          libopenmpi-dev openmpi-bin   # optional for eomgen: ensembles across MPI ranks (mpirun), and its test
          libhdf5-dev                  # optional for eomgen: ensembles written as HDF5 (--out FILE.h5)
          python3-dev pybind11-dev python3-numpy  # optional: import eomgen (python/, docs/python.md)
          python3-pytest)              # the Python module's tests
# More for one caller, in the same apt-get run: scripts/test.sh adds chromium (the animation's browser test).
read -r -a extra_packages <<< "${EOMGEN_EXTRA_PACKAGES:-}"
packages+=("${extra_packages[@]}")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

[[ "${1:-}" == "--packages-only" ]] && exit 0
build="${EOMGEN_BUILD_DIR:-build}"
no_build=0
if [[ "${1:-}" == "--no-build" ]]; then  # configure only (the caller builds what it needs)
  no_build=1
  shift
fi
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
((no_build)) || cmake --build "$build" -j "$(nproc)"
