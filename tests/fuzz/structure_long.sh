#!/usr/bin/env bash
# The structural fuzzer's long run in the release build (no sanitizers: tests/fuzz/run.sh structure runs it under
# libFuzzer with ASan and UBSan, 5 to 20 times slower). Runs batches of 500 models with successive seeds on every
# core until SECONDS (default 3600) have passed, then prints the totals of the batches' statistics. Any finding
# (a crash, an unlocated error, a NaN reported, an input slower than 10 s) is kept in build/structure-long/.
# Batch seeds run from FIRST_SEED (default 1000) upward: a run meant to add models to earlier runs' must start
# above the seeds they used (each run prints its range), or it draws the same models again.
# Usage: tests/fuzz/structure_long.sh [SECONDS] [JOBS] [FIRST_SEED]       Figures: docs/reliability.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-3600}"
jobs="${2:-$(nproc)}"
first="${3:-1000}"
[[ "$seconds" =~ ^[0-9]+$ && "$jobs" =~ ^[1-9][0-9]*$ && "$first" =~ ^[0-9]+$ ]] ||
  { echo "usage: tests/fuzz/structure_long.sh [SECONDS] [JOBS] [FIRST_SEED]" >&2; exit 1; }
driver=build/tests/fuzz/fuzz_structure
[[ -x "$driver" ]] || { echo "tests/fuzz/structure_long.sh: build $driver first (bash scripts/test.sh builds it)" >&2; exit 1; }
out=build/structure-long
rm -rf "$out" && mkdir -p "$out"
end=$(( $(date +%s) + seconds ))
worker() {
  local seed=$1
  while (( $(date +%s) < end )); do
    EOMGEN_FUZZ_STATS=1 EOMGEN_FUZZ_KEEP_GOING=1 "$driver" --random 500 --seed "$seed" --slow 10 \
      > "$out/batch_$seed.log" 2>&1 || echo "seed $seed: exit $?" >> "$out/failures.txt"
    seed=$(( seed + jobs ))
  done
}
for ((j = 0; j < jobs; ++j)); do worker $(( first + j )) & done
wait
seeds=$(ls "$out" | sed -n 's/^batch_\([0-9]*\)\.log$/\1/p' | sort -n)
echo "batch seeds $(head -1 <<< "$seeds") to $(tail -1 <<< "$seeds") (the next run that adds models starts above)"
# Each batch ends with "fuzz_structure: N inputs, F findings: ...".
awk '/^fuzz_structure: [0-9]+ inputs/ { n += $2; f += $4; b++ } END { printf "%d batches, %d models, %d findings\n", b, n, f }' "$out"/batch_*.log
grep -h "^fuzz_structure: the slowest input took" "$out"/batch_*.log | sort -t' ' -k6 -g | tail -1
[[ -f "$out/failures.txt" ]] && { echo "failed batches:"; cat "$out/failures.txt"; exit 1; }
exit 0
