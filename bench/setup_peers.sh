#!/usr/bin/env bash
# Installs the benchmark's peers from Debian, only what is missing: MuJoCo (libmujoco-dev, for mj_forward on the
# n-link chain) and SUNDIALS (libsundials-dev, CVODE and ARKODE). Called by bench/run.sh; never needed by the main
# build or the tests (bench/CMakeLists.txt finds both optionally and skips their programs with a message).
# Usage: bash bench/setup_peers.sh   (a failed install is reported and the run goes on without that peer)
set -uo pipefail

packages=(libmujoco-dev libsundials-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
((${#missing[@]})) || exit 0
echo "setup_peers: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
if ! { $sudo apt-get update -qq &&
       DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; }; then
  echo "setup_peers: could not install ${missing[*]}; the benchmark runs without them" >&2
fi
exit 0
