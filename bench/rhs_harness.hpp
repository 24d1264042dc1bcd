/** @file rhs_harness.hpp  One harness for both right-hand sides: fill M and f, then the same solve (the one the
 * generated rhs uses). */
#pragma once

#include "eomgen/linear_solve.hpp"

#include <benchmark/benchmark.h>
#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace eomgen::bench {

/// SymPy's cse'd C (bench/sympy_pendulum.py): M (column-major n×n) and f from q, q̇ and the parameters
/// in the order of Model::param_names.
using SympyDynamics = void (*)(const double* q, const double* qd, const double* p, double* M, double* f);

/// 64 states spread over angles in (−1.5, 1.5) and rates in (−2, 2), cycled so that sin/cos see varied
/// arguments.
template <class Model>
std::vector<typename Model::State> sample_states() {
    std::mt19937 rng(20260601u + Model::nq);
    std::uniform_real_distribution<double> angle(-1.5, 1.5), rate(-2.0, 2.0);
    std::vector<typename Model::State> xs(64);
    for (auto& x : xs) {
        for (int i = 0; i < Model::nq; ++i) x(i) = angle(rng);
        for (int i = 0; i < Model::nq; ++i) x(Model::nq + i) = rate(rng);
    }
    return xs;
}

/// Whether a generated model carries its own unrolled solve (solve_for_accelerations, n <= 12).
template <class Model, class = void>
struct HasUnrolledSolve : std::false_type {};
template <class Model>
struct HasUnrolledSolve<Model, std::void_t<decltype(&Model::solve_for_accelerations)>> : std::true_type {};

/// The same steps as the generated Model::rhs (head/tail, dynamics, the same solve, write), with SymPy's M and f.
template <class Model, SympyDynamics Dyn>
void sympy_rhs(const typename Model::State& x, const double* p, typename Model::State& xdot) {
    constexpr int nq = Model::nq;
    const typename Model::Config q = x.template head<nq>();
    const typename Model::Config qd = x.template tail<nq>();
    typename Model::MassMatrix M;
    typename Model::Config f;
    Dyn(q.data(), qd.data(), p, M.data(), f.data());
    typename Model::Config qdd;
    if constexpr (HasUnrolledSolve<Model>::value)
        Model::solve_for_accelerations(0.0, x, M, f, qdd);
    else
        eomgen::solve_mass_matrix(M, f, qdd, 0.0, x);
    xdot.template head<nq>() = qd;
    xdot.template tail<nq>() = qdd;
}

template <class Model>
void bm_eomgen_rhs(benchmark::State& st) {
    const auto xs = sample_states<Model>();
    const typename Model::Params p;
    typename Model::State xdot;
    std::size_t i = 0;
    for (auto _ : st) {
        Model::rhs(0.0, xs[i++ & 63], p, xdot);
        benchmark::DoNotOptimize(xdot.data());
        benchmark::ClobberMemory();
    }
}

template <class Model, SympyDynamics Dyn>
void bm_sympy_rhs(benchmark::State& st) {
    const auto xs = sample_states<Model>();
    const typename Model::Params p;
    const auto pv = Model::param_values(p);
    typename Model::State xdot;
    std::size_t i = 0;
    for (auto _ : st) {
        sympy_rhs<Model, Dyn>(xs[i++ & 63], pv.data(), xdot);
        benchmark::DoNotOptimize(xdot.data());
        benchmark::ClobberMemory();
    }
}

/// M and f only (no solve), eomgen.
template <class Model>
void bm_eomgen_dynamics(benchmark::State& st) {
    const auto xs = sample_states<Model>();
    const typename Model::Params p;
    typename Model::MassMatrix M;
    typename Model::Config f;
    std::size_t i = 0;
    for (auto _ : st) {
        const auto& x = xs[i++ & 63];
        Model::dynamics(0.0, x.template head<Model::nq>(), x.template tail<Model::nq>(), p, M, f);
        benchmark::DoNotOptimize(M.data());
        benchmark::DoNotOptimize(f.data());
        benchmark::ClobberMemory();
    }
}

/// M and f only (no solve), SymPy.
template <class Model, SympyDynamics Dyn>
void bm_sympy_dynamics(benchmark::State& st) {
    const auto xs = sample_states<Model>();
    const typename Model::Params p;
    const auto pv = Model::param_values(p);
    typename Model::MassMatrix M;
    typename Model::Config f;
    std::size_t i = 0;
    for (auto _ : st) {
        const auto& x = xs[i++ & 63];
        Dyn(x.data(), x.data() + Model::nq, pv.data(), M.data(), f.data());
        benchmark::DoNotOptimize(M.data());
        benchmark::DoNotOptimize(f.data());
        benchmark::ClobberMemory();
    }
}

/// Registers eomgen's benchmarks for an n-link pendulum.
template <class Model>
bool register_eomgen(int n) {
    benchmark::RegisterBenchmark(("rhs/eomgen/" + std::to_string(n)).c_str(), bm_eomgen_rhs<Model>);
    benchmark::RegisterBenchmark(("dynamics/eomgen/" + std::to_string(n)).c_str(), bm_eomgen_dynamics<Model>);
    return true;
}

/// Registers SymPy's benchmarks after checking that both right-hand sides agree (else exits with 1: timing
/// code that computes something else would be meaningless).
template <class Model, SympyDynamics Dyn>
bool register_sympy(int n) {
    const typename Model::Params p;
    const auto pv = Model::param_values(p);
    double worst = 0;
    for (const auto& x : sample_states<Model>()) {
        typename Model::State a, b;
        Model::rhs(0.0, x, p, a);
        sympy_rhs<Model, Dyn>(x, pv.data(), b);
        worst = std::max(worst, (a - b).cwiseAbs().maxCoeff() / std::max(1.0, a.cwiseAbs().maxCoeff()));
    }
    std::fprintf(stderr,
                 "n = %d: eomgen and SymPy right-hand sides agree to %.1e (relative, max over 64 states)\n",
                 n, worst);
    if (!(worst < 1e-8)) {
        std::fprintf(stderr, "n = %d: eomgen and SymPy disagree\n", n);
        std::exit(1);
    }
    benchmark::RegisterBenchmark(("rhs/sympy/" + std::to_string(n)).c_str(), bm_sympy_rhs<Model, Dyn>);
    benchmark::RegisterBenchmark(("dynamics/sympy/" + std::to_string(n)).c_str(),
                                 bm_sympy_dynamics<Model, Dyn>);
    return true;
}

}  // namespace eomgen::bench
