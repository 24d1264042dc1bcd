#!/usr/bin/env bash
# Sets up (installs, configures, builds) and runs the whole test suite through ctest, including one run of
# the benchmark pipeline at tiny sizes (bench_smoke; no time is asserted).
set -euo pipefail
cd "$(dirname "$0")/.."
# chromium: the animation's pages opened headless (tests/animation/; skipped where it is missing); nbconvert, nbclient,
# ipykernel and matplotlib: the example notebook executed (tests/python/; skipped where they are missing).
EOMGEN_EXTRA_PACKAGES="chromium jupyter-nbconvert python3-nbclient python3-ipykernel python3-matplotlib ${EOMGEN_EXTRA_PACKAGES:-}" bash scripts/setup.sh -DEOMGEN_BUILD_BENCH=ON
ctest --test-dir "${EOMGEN_BUILD_DIR:-build}" --output-on-failure -j "$(nproc)"
