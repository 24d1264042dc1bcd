#!/usr/bin/env bash
# Sets up (installs, configures, builds) and runs the whole test suite through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
ctest --test-dir "${EOMGEN_BUILD_DIR:-build}" --output-on-failure -j "$(nproc)"
