/** @file time_chain.cpp  Google Benchmark main of the chain benchmark: eomgen's rhs, MuJoCo's mj_forward and the O(n)
 * recursion on the n-link planar chain of point masses (bench/chain_harness.hpp). */
// Usage: time_chain [--mjcf-dir DIR] [Google Benchmark options]. Names: chain/<eomgen|recursion|mujoco>/<n>.
// Before anything is timed, each peer's q̈ is compared with eomgen's at the 64 states (one line each on stderr);
// a disagreement beyond the stated tolerance exits with 1. --mjcf-dir: also write each chain's MJCF there.
#include "chain_harness.hpp"

#include <benchmark/benchmark.h>

#include <cstring>

#define EOMGEN_CHAIN_SIZE(n) void register_chain_##n();
#include "chain_sizes.inc"
#undef EOMGEN_CHAIN_SIZE

int main(int argc, char** argv) {
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--mjcf-dir") == 0 && i + 1 < argc)
            eomgen::bench::mjcf_dir() = argv[++i];
        else
            argv[kept++] = argv[i];
    }
    argc = kept;
#if !EOMGEN_BENCH_HAVE_MUJOCO
    std::fprintf(stderr, "MuJoCo not found when time_chain was built: mj_forward is not measured\n");
#endif
#define EOMGEN_CHAIN_SIZE(n) register_chain_##n();
#include "chain_sizes.inc"
#undef EOMGEN_CHAIN_SIZE
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
