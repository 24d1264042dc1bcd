#!/usr/bin/env bash
# The test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (g++, -O1 -g); any sanitizer
# report fails its test. Leaks inside CLN's caches (GiNaC's number library, not instrumented) and Open MPI's
# own allocations are suppressed: tests/fuzz/lsan.supp.
#   scripts/test_sanitized.sh           the whole suite, in build-sanitize/ (figures: docs/reliability.md)
#   scripts/test_sanitized.sh --quick   what reads text and does symbolic work: the generator's, the
#                                       checker's, the interpreter's and the escaping's tests, the CLI cases
#                                       of eomgen, and the bounded fuzz runs, in the same build directory. CI
#                                       runs this one.
# Both variants use one configuration, so the whole suite after --quick builds only what --quick did not.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ccache_env.sh
quick=0
[[ "${1:-}" == "--quick" ]] && quick=1
# Also for the build: it runs the sanitized eomgen (model headers) and the test programs (test discovery).
# intercept_tls_get_addr=0: up to GCC 13 the runtime's __tls_get_addr interceptor takes a dynamic TLS block that
# happens to start 16 bytes past a page boundary for a pre-2.25 glibc block and reads the two words before it as
# that block's bounds; LeakSanitizer's tracer then dies at exit ("Tracer caught signal 11"), by chance of where
# malloc put the block. Open MPI's dlopen'd components have dynamic TLS: a CI run lost
# cli:mpi_ensemble_equals_single_process so, with no leak reported (the same run passes 12 of 12 here).
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:intercept_tls_get_addr=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0"
build="${EOMGEN_SANITIZE_BUILD_DIR:-build-sanitize}"
EOMGEN_BUILD_DIR="$build" bash scripts/setup.sh --no-build -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
  -DEOMGEN_SANITIZE=address,undefined -DEOMGEN_BUILD_BENCH=OFF
if ((quick)); then
  targets=(eomgen test_model test_escape test_atomic_file test_checker test_mechanics_codegen test_constraints
           test_interpreter fuzz_text_fields fuzz_expression fuzz_model_file fuzz_latex fuzz_check fuzz_sim_values fuzz_structure)
  cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"
  ctest --test-dir "$build" --output-on-failure -j "$(nproc)" \
    -R '^(test_model|test_escape|test_atomic_file|test_checker|test_mechanics_codegen|test_constraints|test_interpreter):|^fuzz:.*_bounded$|^cli:(bad_|check_|modes_|mpi_|missing_file|unknown_command|version)'
else
  cmake --build "$build" -j "$(nproc)"
  ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
fi
