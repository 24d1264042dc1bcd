#!/usr/bin/env bash
# Prints the suite's tests that took 5 s or more in the last ctest run of a build folder (default build/), longest
# first, as cmake/test_costs.cmake lists them (name=seconds), from ctest's own record of their times.
# Usage: bash scripts/test_costs.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
data="${1:-build}/Testing/Temporary/CTestCostData.txt"
[[ -f "$data" ]] || { echo "no $data: run ctest in that folder first" >&2; exit 2; }
# Lines are "name runs seconds" up to a line "---" (the failed tests follow). Catch's test names hold spaces, so
# a line of three fields whose runs (the second) are at least 1 is a whole name; only those can be listed.
awk '/^---$/ { exit } NF == 3 && $2 >= 1 && $3 >= 5 { printf "%s=%d\n", $1, $3 + 0.5 }' "$data" | sort -t= -k2 -n -r
