#!/usr/bin/env bash
# Where a cold build's time goes (issue 31): builds the tree from nothing in its own folder, without ccache, every
# compile and link through scripts/time_command.sh, first what scripts/run.sh builds and then what scripts/test.sh
# adds, and prints the CPU seconds by stage, by target and the slowest files (scripts/build_profile.py).
# Usage: [EOMGEN_JOBS=N] scripts/build_profile.sh [BUILD_DIR]     (about 18 minutes on 2 cores; BUILD_DIR is emptied)
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(realpath -m "${1:-build-profile}")
jobs="${EOMGEN_JOBS:-$(nproc)}"
# Emptied first: only a folder this script made before (or a new one), never a checkout or another build.
if [[ -e $build && ! -f $build/command_times.tsv ]]; then
  echo "build_profile.sh: $build exists and is not an earlier profile's folder; name another" >&2
  exit 2
fi
rm -rf "$build"
times_file="$build/command_times.tsv"
mkdir -p "$build"
: > "$times_file"
export EOMGEN_TIMES_FILE="$times_file"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DEOMGEN_BUILD_BENCH=ON -DEOMGEN_CCACHE=OFF \
  -DCMAKE_CXX_COMPILER_LAUNCHER="$PWD/scripts/time_command.sh" \
  -DCMAKE_CXX_LINKER_LAUNCHER="$PWD/scripts/time_command.sh" >/dev/null
start=$(date +%s)
cmake --build "$build" -j "$jobs" --target eomgen eomgen-sim door_closing >/dev/null
mid=$(date +%s)
echo "--- run.sh's part ends" >> "$times_file"
cmake --build "$build" -j "$jobs" >/dev/null
end=$(date +%s)
echo "wall: run.sh's targets $((mid - start)) s, the rest $((end - mid)) s, $jobs jobs"
/usr/bin/python3 scripts/build_profile.py "$times_file"
