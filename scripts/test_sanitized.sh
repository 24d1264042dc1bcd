#!/usr/bin/env bash
# The whole test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (g++), in its own build
# directory (build-sanitize/, or $EOMGEN_SANITIZE_BUILD_DIR). Any sanitizer report fails its test. CI runs
# this after scripts/test.sh. Leaks inside CLN's caches (GiNaC's number library, not instrumented) are
# suppressed: tests/fuzz/lsan.supp.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EOMGEN_SANITIZE_BUILD_DIR:-build-sanitize}"
# Also for the build: it runs the sanitized eomgen (model headers) and the test programs (test discovery).
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0"
EOMGEN_BUILD_DIR="$build" bash scripts/setup.sh -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DEOMGEN_SANITIZE=address,undefined -DEOMGEN_BUILD_BENCH=OFF
ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
