#!/usr/bin/env bash
# Long fuzzing with libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer (clang, Debian's
# libclang-rt-14-dev). Builds eomgen's libraries and the harnesses of tests/fuzz/ with clang into
# build-fuzz/, then runs each harness for SECONDS (default 600) from its corpus (the checked-in one, the
# project's models and derivation fixtures, and what earlier runs found) with its dictionary. An input
# slower than 1 s (10 s for check and model_file: see below) is a finding, as is a crash or a sanitizer report; findings are written
# to build-fuzz/findings/<harness>/. Prints one summary line per harness: executions, coverage, findings.
# Usage: tests/fuzz/run.sh [--runs N] [SECONDS] [HARNESS...]      Figures: docs/reliability.md.
#   --runs N   stop a harness after N executions (or SECONDS, whichever comes first)
set -euo pipefail
cd "$(dirname "$0")/../.."
runs=()
if [[ "${1:-}" == "--runs" ]]; then
  [[ "${2:-}" =~ ^[0-9]+$ ]] || { echo "tests/fuzz/run.sh: --runs needs a number of executions" >&2; exit 1; }
  runs=(-runs="$2")
  shift 2
fi
seconds="${1:-600}"
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "tests/fuzz/run.sh: SECONDS must be a whole number, not '$seconds'" >&2; exit 1; }
shift || true
harnesses=("$@")
((${#harnesses[@]})) || harnesses=(text_fields expression model_file latex check sim_values structure)
need=(clang libclang-rt-14-dev)
missing=()
for p in "${need[@]}"; do dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p"); done
if ((${#missing[@]})); then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
bash scripts/setup.sh --packages-only   # the Debian packages eomgen itself needs
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -g -O1"
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="$flags -fsanitize=fuzzer-no-link" -DEOMGEN_BUILD_TESTS=OFF -DEOMGEN_FUZZ=ON >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target "${harnesses[@]/#/libfuzz_}"

seeds_for() {  # the corpus directories a harness starts from
  case "$1" in
    model_file) echo models examples tests/cli/bad tests/security ;;
    latex | check) echo tests/checker/fixtures tests/checker/fixtures/repro ;;
    *) echo "tests/fuzz/corpus/$1" ;;
  esac
}
summary=()
for h in "${harnesses[@]}"; do
  corpus="build-fuzz/corpus/$h"
  findings="build-fuzz/findings/$h"
  mkdir -p "$corpus" "$findings"
  for d in $(seeds_for "$h"); do find "$d" -maxdepth 1 -type f ! -name '*.txt' ! -name '*.cpp' -exec cp -n {} "$corpus/" \; ; done
  dict=()
  case "$h" in
    expression) dict=(-dict=tests/fuzz/dict/expression.dict) ;;
    model_file | text_fields) dict=(-dict=tests/fuzz/dict/model_file.dict) ;;
    latex | check) dict=(-dict=tests/fuzz/dict/latex.dict) ;;
  esac
  # 1 s (2 s for check) as issue 12 asks, except model_file and check, whose own seeds are slower than that
  # under the sanitizers (docs/reliability.md): models/triangle_plate_5_15.toml takes 3.5 s under clang's ASan +
  # UBSan against 0.18 s in the release build, and the normal-modes fixture 4.2 s against 0.35 s. A limit of
  # 10 s is about 0.5 s of release-build time there, still far below anything that could be called a hang.
  # structure (models built from the bytes, each through eomgen modes as well) has the same 10 s.
  timeout=1
  [[ "$h" == check || "$h" == model_file || "$h" == structure ]] && timeout=10
  log="build-fuzz/findings/$h.log"
  started=$(date +%s)
  set +e
  LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp" \
    "build-fuzz/tests/fuzz/libfuzzer/libfuzz_$h" -max_total_time="$seconds" "${runs[@]}" -timeout="$timeout" -max_len=4096 \
    -rss_limit_mb=4096 -print_final_stats=1 "${dict[@]}" -artifact_prefix="$findings/" "$corpus" >"$log" 2>&1
  rc=$?
  set -e
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo "?")
  found=$(find "$findings" -type f | wc -l)
  took=$(($(date +%s) - started))
  rss=$(grep -o 'stat::peak_rss_mb: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  summary+=("$h: ${took} s, ${execs} executions, coverage ${cov} edges, corpus $(ls "$corpus" | wc -l), peak RSS ${rss} MB, exit $rc, findings ${found} (log $log)")
done
printf '%s\n' "${summary[@]}"
