#!/usr/bin/env bash
# The benchmarks of issues 6 and 15 in one run: eomgen against SymPy (generation, operation counts, right-hand side,
# compile time) and against Boost.Odeint (work-precision), generation's peak memory, `eomgen run`, and (section 8)
# against MuJoCo's mj_forward, an O(n) recursion, CVODE and ARKODE; writes docs/benchmarks.md (the measured parts)
# and docs/benchmarks.png. About 30 minutes on 2 cores, most of it SymPy; --peers-only about 5.
#
# Usage: bash bench/run.sh [--smoke] [--no-build] [--peers-only | --scale-only | --fit-only | --bicycle-only |
#                         --animation-only | --python-only |
#                         --interpreter-only] [--build-dir DIR]
#                          [--sympy-cap SECONDS]
#   --smoke        tiny sizes, seconds; results in DIR/bench_smoke/ (docs/ untouched); what CI runs
#   --peers-only   only section 8 (MuJoCo, SUNDIALS), rewriting only its part of docs/benchmarks.md
#   --scale-only   only section 9 (generation at n = 8 to 60 and a 3-D chain of 10 bodies, default header and
#                  --with all, beside SymPy capped at 300 s), rewriting only its part; about 10 minutes
#   --fit-only     only section 10 (eomgen fit: the coverage of its standard errors over 100 noisy data sets per
#                  model, its time against central differences), rewriting only its part; about a minute
#   --bicycle-only only section 11 (the Whipple bicycle: eomgen modes --steady against the benchmark's values and
#                  SymPy's Kane's method), rewriting only its part; about 2 minutes with SymPy
#   --animation-only only section 12 (eomgen run --animate: the page's size, the time to draw a frame in headless
#                  Chromium), rewriting only its part; about a minute
#   --python-only  only section 13 (the Python module: import, load, a first simulate, Model.rhs against the
#                  same loop in C++), rewriting only its part; about a minute
#   --interpreter-only only section 14 (eomgen run --interpret against the compiled run, per model: first run,
#                  cached, interpreted, the interpreter's cost per right-hand side), rewriting only its part; about
#                  two minutes
#   --no-build     skip scripts/setup.sh and use what DIR holds (configured with -DEOMGEN_BUILD_BENCH=ON); the
#                  full run still rebuilds time_rhs, which compiles in the SymPy code of the run
#   --build-dir    build directory (default build-bench/)
#   --sympy-cap    seconds SymPy may take per size before it is stopped and reported as capped (default 900)
# Without --no-build it first runs bench/setup_peers.sh (installs libmujoco-dev and libsundials-dev where missing;
# the run goes on without a peer that could not be installed) and scripts/setup.sh (installs missing Debian
# packages, configures, builds). With --no-build nothing is installed: the peers found at configure time are used.
# SymPy 1.14 is used if python3 can import it; without it the SymPy parts are skipped with a message.
set -euo pipefail
cd "$(dirname "$0")/.."

build=build-bench
smoke=()
no_build=0
extra=()
while (($#)); do
  case "$1" in
    --smoke) smoke=(--smoke) ;;
    --no-build) no_build=1 ;;
    --peers-only) extra+=(--peers-only) ;;
    --scale-only) extra+=(--scale-only) ;;
    --fit-only) extra+=(--fit-only) ;;
    --bicycle-only) extra+=(--bicycle-only) ;;
    --animation-only) extra+=(--animation-only) ;;
    --python-only) extra+=(--python-only) ;;
    --interpreter-only) extra+=(--interpreter-only) ;;
    --build-dir) build="$2"; shift ;;
    --sympy-cap) extra+=(--sympy-cap "$2"); shift ;;
    -h|--help) sed -n '2,35p' "$0"; exit 0 ;;
    *) echo "bench/run.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done

if ((no_build)); then
  extra+=(--no-build)
else
  bash bench/setup_peers.sh
  EOMGEN_BUILD_DIR="$build" bash scripts/setup.sh -DEOMGEN_BUILD_BENCH=ON -DEOMGEN_BUILD_TESTS=OFF
fi
if [ ! -f "$build/bench/bench_config.json" ]; then
  echo "bench/run.sh: $build is not configured with -DEOMGEN_BUILD_BENCH=ON" >&2
  exit 2
fi
exec python3 bench/bench.py --build-dir "$build" "${smoke[@]}" "${extra[@]}"
