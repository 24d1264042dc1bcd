/** @file time_rhs.cpp  Google Benchmark main for the right-hand sides registered by the rhs_<n>.cpp files. */
// Names: rhs/<eomgen|sympy>/<n> (M and f, Cholesky solve, q̈ into x') and dynamics/<eomgen|sympy>/<n> (M and f
// only).
#include <benchmark/benchmark.h>

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
