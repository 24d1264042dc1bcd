#!/usr/bin/env bash
# Long fuzzing with libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer (clang, Debian's
# libclang-rt-14-dev). Builds eomgen's libraries and the harnesses of tests/fuzz/ with clang into
# build-fuzz/, then runs each harness for SECONDS (default 600) from its checked-in corpus.
# Usage: tests/fuzz/run.sh [SECONDS]      Figures: docs/reliability.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-600}"
need=(clang libclang-rt-14-dev)
missing=()
for p in "${need[@]}"; do dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p"); done
if ((${#missing[@]})); then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
bash scripts/setup.sh >/dev/null   # the Debian packages eomgen itself needs
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -g -O1"
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="$flags -fsanitize=fuzzer-no-link" -DEOMGEN_BUILD_TESTS=OFF -DEOMGEN_FUZZ=ON >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target libfuzz_text_fields
mkdir -p build-fuzz/corpus/text_fields
cp -n tests/fuzz/corpus/text_fields/* build-fuzz/corpus/text_fields/ 2>/dev/null || true
LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp" \
  build-fuzz/tests/fuzz/libfuzzer/libfuzz_text_fields -max_total_time="$seconds" -max_len=400 -print_final_stats=1 \
  -artifact_prefix=build-fuzz/ build-fuzz/corpus/text_fields
