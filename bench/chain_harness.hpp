/** @file chain_harness.hpp  The n-link chain benchmark (bench/time_chain): eomgen's generated rhs against MuJoCo's
 * mj_forward on the same chain and against the O(n) recursion, each checked against eomgen before it is timed; and
 * against the same header's dense M (dynamics() and solve_mass_matrix), beside its tree recursion. */
#pragma once

#include "chain_recursion.hpp"
#include "rhs_harness.hpp"

#include "eomgen/errors.hpp"
#include "eomgen/linear_solve.hpp"

#include <benchmark/benchmark.h>
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#if EOMGEN_BENCH_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

namespace eomgen::bench {

/// Where each chain's MJCF is written (empty: nowhere; it is loaded from memory either way). Set by main.
inline std::string& mjcf_dir() {
    static std::string dir;
    return dir;
}

/// Largest relative difference allowed between eomgen's q̈ and a peer's before the peer is timed: the O(n)
/// recursion computes the same function (round-off only); MuJoCo's point masses carry a rotational inertia of
/// 1e-12 kg m² each (it needs one), against m l² = 1 kg m².
constexpr double kRecursionTolerance = 1e-10;
constexpr double kMujocoTolerance = 1e-6;

/// m, l and g of a family model's default parameters (param_values order: m1..mn, l1..ln, g).
template <class Model>
struct ChainParams {
    std::vector<double> m, l;
    double g = 0;
    ChainParams() {
        const auto v = Model::param_values(typename Model::Params{});
        constexpr int n = Model::nq;
        m.assign(v.begin(), v.begin() + n);
        l.assign(v.begin() + n, v.begin() + 2 * n);
        g = v[2 * n];
    }
};

inline double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, a.cwiseAbs().maxCoeff());
}

/**
 * eomgen's rhs through the dense M, to measure the tree's recursion within one run (the header's rhs is that
 * recursion from n = 6 on, codegen/tree_emitter.hpp): the header's dynamics() (M and f), then the runtime's
 * solve_mass_matrix (L D Lᵀ, Eigen's LLT above 20), as rhs ran for every n before.
 */
template <class Model>
void rhs_dense_solve(const typename Model::State& x, const typename Model::Params& p, typename Model::State& xdot) {
    constexpr int n = Model::nq;
    const typename Model::Config q = x.template head<n>(), qd = x.template tail<n>();
    typename Model::MassMatrix M;
    typename Model::Config f, qdd;
    Model::dynamics(0.0, q, qd, p, M, f);
    eomgen::solve_mass_matrix(M, f, qdd, 0.0, x);
    xdot.template head<n>() = qd;
    xdot.template tail<n>() = qdd;
}

template <class Model>
void bm_chain_dense(benchmark::State& st) {
    const auto xs = sample_states<Model>();
    const typename Model::Params p;
    typename Model::State xdot;
    std::size_t i = 0;
    for (auto _ : st) {
        rhs_dense_solve<Model>(xs[i++ & 63], p, xdot);
        benchmark::DoNotOptimize(xdot.data());
        benchmark::ClobberMemory();
    }
}

template <class Model>
void bm_chain_recursion(benchmark::State& st) {
    const auto xs = sample_states<Model>();
    const ChainParams<Model> cp;
    typename Model::State xdot;
    std::size_t i = 0;
    for (auto _ : st) {
        chain_rhs_recursive<Model::nq>(xs[i++ & 63].data(), cp.m.data(), cp.l.data(), cp.g, xdot.data());
        benchmark::DoNotOptimize(xdot.data());
        benchmark::ClobberMemory();
    }
}

#if EOMGEN_BENCH_HAVE_MUJOCO

/**
 * MJCF of the n-link chain: body i hangs from body i−1's point mass (the first from the origin) by a hinge about
 * −y, so that its joint angle is θ_i − θ_{i−1} and x = l sin θ, z = −l cos θ as in the eomgen model; its point
 * mass m_i is an <inertial> at (0, 0, −l_i) with a diagonal inertia of 1e-12 (MuJoCo needs one; negligible beside
 * m l²), drawn as a tiny sphere that neither collides nor adds mass. Gravity −g z; no damping, armature, limits,
 * springs or contacts (contacts disabled).
 */
inline std::string chain_mjcf(int n, const std::vector<double>& m, const std::vector<double>& l, double g) {
    char head[256];
    std::snprintf(head, sizeof head,
                  "<mujoco model=\"chain_%d\">\n  <compiler angle=\"radian\"/>\n"
                  "  <option gravity=\"0 0 %.17g\">\n    <flag contact=\"disable\"/>\n  </option>\n",
                  n, -g);
    std::string s = head;
    s += "  <worldbody>\n";
    std::string indent = "    ";
    for (int i = 0; i < n; ++i) {
        char buf[512];
        const double z_parent = i == 0 ? 0.0 : -l[std::size_t(i - 1)];
        std::snprintf(buf, sizeof buf,
                      "%s<body name=\"b%d\" pos=\"0 0 %.17g\">\n"
                      "%s  <joint name=\"j%d\" type=\"hinge\" axis=\"0 -1 0\" pos=\"0 0 0\"/>\n"
                      "%s  <inertial pos=\"0 0 %.17g\" mass=\"%.17g\" diaginertia=\"1e-12 1e-12 1e-12\"/>\n"
                      "%s  <geom type=\"sphere\" size=\"0.001\" pos=\"0 0 %.17g\" mass=\"0\" contype=\"0\" "
                      "conaffinity=\"0\"/>\n",
                      indent.c_str(), i + 1, z_parent, indent.c_str(), i + 1, indent.c_str(), -l[std::size_t(i)],
                      m[std::size_t(i)], indent.c_str(), -l[std::size_t(i)]);
        s += buf;
        indent += "  ";
    }
    for (int i = n; i-- > 0;) {
        indent.resize(indent.size() - 2);
        s += indent + "</body>\n";
    }
    s += "  </worldbody>\n</mujoco>\n";
    return s;
}

/// Compiles the MJCF text (through MuJoCo's virtual file system; also written to mjcf_dir() when set); exits with
/// 1 and MuJoCo's message when it does not load.
inline mjModel* load_chain(int n, const std::string& xml) {
    const std::string name = "chain_" + std::to_string(n) + ".xml";
    if (!mjcf_dir().empty()) {
        if (FILE* fh = std::fopen((mjcf_dir() + "/" + name).c_str(), "w")) {
            std::fputs(xml.c_str(), fh);
            std::fclose(fh);
        }
    }
    auto vfs = std::make_unique<mjVFS>();
    mj_defaultVFS(vfs.get());
    mj_makeEmptyFileVFS(vfs.get(), name.c_str(), int(xml.size()));
    const int k = mj_findFileVFS(vfs.get(), name.c_str());
    std::copy(xml.begin(), xml.end(), static_cast<char*>(vfs->filedata[k]));
    char error[1000] = "";
    mjModel* model = mj_loadXML(name.c_str(), vfs.get(), error, sizeof error);
    mj_deleteFileVFS(vfs.get(), name.c_str());
    if (!model) {
        std::fprintf(stderr, "n = %d: MuJoCo did not load the chain: %s\n", n, error);
        std::exit(1);
    }
    return model;
}

/// eomgen's state (absolute angles and rates) as MuJoCo's joint angles and rates (each relative to its parent).
inline void to_relative(const double* absolute, int n, double* relative) {
    for (int i = 0; i < n; ++i) relative[i] = absolute[i] - (i > 0 ? absolute[i - 1] : 0.0);
}

template <class Model>
void bm_chain_mujoco(benchmark::State& st, mjModel* model) {
    constexpr int n = Model::nq;
    const auto xs = sample_states<Model>();
    std::vector<double> qpos(64 * n), qvel(64 * n);
    for (int k = 0; k < 64; ++k) {
        to_relative(xs[std::size_t(k)].data(), n, &qpos[std::size_t(k * n)]);
        to_relative(xs[std::size_t(k)].data() + n, n, &qvel[std::size_t(k * n)]);
    }
    mjData* data = mj_makeData(model);
    std::size_t i = 0;
    for (auto _ : st) {
        const std::size_t k = (i++ & 63) * n;
        std::copy(&qpos[k], &qpos[k] + n, data->qpos);
        std::copy(&qvel[k], &qvel[k] + n, data->qvel);
        mj_forward(model, data);
        benchmark::DoNotOptimize(data->qacc);
        benchmark::ClobberMemory();
    }
    mj_deleteData(data);
}

/// MuJoCo's q̈ at eomgen's state x, converted back to absolute angles.
inline Eigen::VectorXd mujoco_qdd(const mjModel* model, mjData* data, const double* x, int n) {
    to_relative(x, n, data->qpos);
    to_relative(x + n, n, data->qvel);
    mj_forward(model, data);
    Eigen::VectorXd qdd(n);
    for (int i = 0; i < n; ++i) qdd(i) = data->qacc[i] + (i > 0 ? qdd(i - 1) : 0.0);
    return qdd;
}

#endif

/// Checks each peer against eomgen's rhs at the 64 states (a line on stderr each: the largest relative difference
/// of q̈), exits with 1 when one disagrees beyond its tolerance, then registers chain/<eomgen|recursion|mujoco>/n.
template <class Model>
void register_chain() {
    constexpr int n = Model::nq;
    const typename Model::Params p;
    const ChainParams<Model> cp;
    double worst_recursion = 0, worst_mujoco = 0, worst_dense = 0;
#if EOMGEN_BENCH_HAVE_MUJOCO
    mjModel* model = load_chain(n, chain_mjcf(n, cp.m, cp.l, cp.g));
    mjData* data = mj_makeData(model);
#endif
    for (const auto& x : sample_states<Model>()) {
        typename Model::State a, b;
        Model::rhs(0.0, x, p, a);
        chain_rhs_recursive<n>(x.data(), cp.m.data(), cp.l.data(), cp.g, b.data());
        const Eigen::VectorXd qdd = a.template tail<n>();
        worst_recursion = std::max(worst_recursion, relative_difference(qdd, b.template tail<n>()));
        rhs_dense_solve<Model>(x, p, b);
        worst_dense = std::max(worst_dense, relative_difference(qdd, b.template tail<n>()));
#if EOMGEN_BENCH_HAVE_MUJOCO
        worst_mujoco = std::max(worst_mujoco, relative_difference(qdd, mujoco_qdd(model, data, x.data(), n)));
#endif
    }
    std::fprintf(stderr, "n = %d: eomgen and the O(n) recursion agree to %.1e (relative, max over 64 states)\n", n,
                 worst_recursion);
    if (!(worst_recursion < kRecursionTolerance)) {
        std::fprintf(stderr, "n = %d: eomgen and the O(n) recursion disagree (tolerance %.0e)\n", n,
                     kRecursionTolerance);
        std::exit(1);
    }
    std::fprintf(stderr, "n = %d: eomgen's rhs and the dense solve agree to %.1e (relative, max over 64 states)\n",
                 n, worst_dense);
    if (!(worst_dense < kRecursionTolerance)) {
        std::fprintf(stderr, "n = %d: eomgen's rhs and the dense solve disagree\n", n);
        std::exit(1);
    }
    const std::string suffix = "/" + std::to_string(n);
    benchmark::RegisterBenchmark(("chain/eomgen" + suffix).c_str(), bm_eomgen_rhs<Model>);
    benchmark::RegisterBenchmark(("chain/dense" + suffix).c_str(), bm_chain_dense<Model>);
    benchmark::RegisterBenchmark(("chain/recursion" + suffix).c_str(), bm_chain_recursion<Model>);
#if EOMGEN_BENCH_HAVE_MUJOCO
    mj_deleteData(data);
    std::fprintf(stderr, "n = %d: eomgen and MuJoCo mj_forward agree to %.1e (relative, max over 64 states)\n", n,
                 worst_mujoco);
    if (!(worst_mujoco < kMujocoTolerance)) {
        std::fprintf(stderr, "n = %d: eomgen and MuJoCo disagree (tolerance %.0e): not timed\n", n,
                     kMujocoTolerance);
        std::exit(1);
    }
    benchmark::RegisterBenchmark(("chain/mujoco" + suffix).c_str(), bm_chain_mujoco<Model>, model);
#else
    static_cast<void>(worst_mujoco);
#endif
}

}  // namespace eomgen::bench
