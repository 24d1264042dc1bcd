/** @file test_models.hpp  Hand-written models shaped as in docs/generated_code.md, for the runtime tests. */
#pragma once

#include "eomgen/linear_solve.hpp"

#include <Eigen/Core>

#include <array>
#include <cmath>

namespace eomgen::test {

/**
 * A particle with position-dependent mass on a spring: L = ½ (1 + q²) q̇² − ½ k q², differentiated by hand.
 * M = 1 + q², ∂L/∂q̇ = (1 + q²) q̇, ∂L/∂q = q q̇² − k q, and the Euler–Lagrange equation
 * (1 + q²) q̈ = ∂L/∂q − (∂²L/∂q̇∂q) q̇ = q q̇² − k q − 2 q q̇² = −q q̇² − k q.
 */
template <class Scalar>
struct VariableMass {
    static constexpr const char* name = "variable_mass";
    static constexpr int nq = 1;
    static constexpr int nx = 2;
    static constexpr int n_params = 1;
    static constexpr int n_conserved = 1;
    static constexpr bool explicit_time = false;

    using Config = Eigen::Matrix<Scalar, nq, 1>;
    using State = Eigen::Matrix<Scalar, nx, 1>;
    using MassMatrix = Eigen::Matrix<Scalar, nq, nq>;
    using Conserved = Eigen::Matrix<Scalar, n_conserved, 1>;

    struct Params {
        Scalar k = Scalar(1);
    };

    static constexpr std::array<const char*, nx> state_names{"q", "q_dot"};

    /// x = [q, q̇].
    static State state(const Config& q, const Config& qd) { return State(q(0), qd(0)); }

    static void mass_matrix(const Scalar&, const Config& q, const Params&, MassMatrix& M) {
        M(0, 0) = Scalar(1) + q(0) * q(0);
    }
    static void forcing(const Scalar&, const Config& q, const Config& qd, const Params& p, Config& f) {
        f(0) = -q(0) * qd(0) * qd(0) - p.k * q(0);
    }
    static void rhs(const Scalar& t, const State& x, const Params& p, State& xdot) {
        const Config q = x.template head<nq>(), qd = x.template tail<nq>();
        MassMatrix M;
        Config f, qdd;
        mass_matrix(t, q, p, M);
        forcing(t, q, qd, p, f);
        solve_mass_matrix(M, f, qdd, t, x);
        // Fixed-size halves, not `xdot << qd, qdd`: GCC 12 -O3 flags Eigen's comma initializer from 1×1
        // blocks with a false -Warray-bounds.
        xdot.template head<nq>() = qd;
        xdot.template tail<nq>() = qdd;
    }
    static Scalar lagrangian(const Scalar&, const Config& q, const Config& qd, const Params& p) {
        return Scalar(0.5) * (Scalar(1) + q(0) * q(0)) * qd(0) * qd(0) - Scalar(0.5) * p.k * q(0) * q(0);
    }
    static Scalar energy(const Scalar&, const Config& q, const Config& qd, const Params& p) {
        return Scalar(0.5) * (Scalar(1) + q(0) * q(0)) * qd(0) * qd(0) + Scalar(0.5) * p.k * q(0) * q(0);
    }
    static void momenta(const Scalar&, const Config& q, const Config& qd, const Params&, Config& p_out) {
        p_out(0) = (Scalar(1) + q(0) * q(0)) * qd(0);
    }
    static void lagrangian_gradient(const Scalar&, const Config& q, const Config& qd, const Params& p,
                                    Config& dLdq) {
        dLdq(0) = q(0) * qd(0) * qd(0) - p.k * q(0);
    }
};

/**
 * The planar double pendulum (point masses m1, m2 on massless rods l1, l2; angles from the downward
 * vertical), with N = 2 or Eigen::Dynamic to exercise both storage kinds:
 *   L = ½ (m1+m2) l1² θ̇1² + ½ m2 l2² θ̇2² + m2 l1 l2 θ̇1 θ̇2 cos(θ1−θ2) + (m1+m2) g l1 cos θ1 + m2 g l2 cos θ2.
 */
template <class Scalar, int N = 2>
struct DoublePendulum {
    static constexpr const char* name = "double_pendulum";
    static constexpr int nq = 2;
    static constexpr int nx = 4;
    static constexpr bool explicit_time = false;

    using Config = Eigen::Matrix<Scalar, N, 1>;
    using State = Eigen::Matrix<Scalar, N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N, 1>;
    using MassMatrix = Eigen::Matrix<Scalar, N, N>;

    struct Params {
        Scalar m1 = Scalar(1), m2 = Scalar(0.5), l1 = Scalar(1), l2 = Scalar(0.7), g = Scalar(9.81);
    };

    /// x = [q, q̇].
    static State state(const Config& q, const Config& qd) {
        State x(4);
        x << q(0), q(1), qd(0), qd(1);
        return x;
    }

    static void mass_matrix(const Scalar&, const Config& q, const Params& p, MassMatrix& M) {
        using std::cos;
        M.resize(2, 2);
        const Scalar c = p.m2 * p.l1 * p.l2 * cos(q(0) - q(1));
        M << (p.m1 + p.m2) * p.l1 * p.l1, c, c, p.m2 * p.l2 * p.l2;
    }
    static void forcing(const Scalar&, const Config& q, const Config& qd, const Params& p, Config& f) {
        using std::sin;
        f.resize(2);
        const Scalar s = p.m2 * p.l1 * p.l2 * sin(q(0) - q(1));
        f << -s * qd(1) * qd(1) - (p.m1 + p.m2) * p.g * p.l1 * sin(q(0)),
            s * qd(0) * qd(0) - p.m2 * p.g * p.l2 * sin(q(1));
    }
    static void rhs(const Scalar& t, const State& x, const Params& p, State& xdot) {
        const Config q = x.head(2), qd = x.tail(2);
        MassMatrix M;
        Config f, qdd;
        mass_matrix(t, q, p, M);
        forcing(t, q, qd, p, f);
        qdd.resize(2);
        solve_mass_matrix(M, f, qdd, t, x);
        xdot.resize(4);
        xdot.head(2) = qd;
        xdot.tail(2) = qdd;
    }
    static Scalar kinetic_energy(const Scalar& t, const Config& q, const Config& qd, const Params& p) {
        MassMatrix M;
        mass_matrix(t, q, p, M);
        return Scalar(0.5) * qd.dot(M * qd);
    }
    static Scalar potential_energy(const Scalar&, const Config& q, const Config&, const Params& p) {
        using std::cos;
        return -(p.m1 + p.m2) * p.g * p.l1 * cos(q(0)) - p.m2 * p.g * p.l2 * cos(q(1));
    }
    static Scalar lagrangian(const Scalar& t, const Config& q, const Config& qd, const Params& p) {
        return kinetic_energy(t, q, qd, p) - potential_energy(t, q, qd, p);
    }
    static Scalar energy(const Scalar& t, const Config& q, const Config& qd, const Params& p) {
        return kinetic_energy(t, q, qd, p) + potential_energy(t, q, qd, p);
    }
    static void momenta(const Scalar& t, const Config& q, const Config& qd, const Params& p, Config& p_out) {
        MassMatrix M;
        mass_matrix(t, q, p, M);
        p_out = M * qd;
    }
    static void lagrangian_gradient(const Scalar&, const Config& q, const Config& qd, const Params& p,
                                    Config& dLdq) {
        using std::sin;
        dLdq.resize(2);
        const Scalar s = p.m2 * p.l1 * p.l2 * sin(q(0) - q(1)) * qd(0) * qd(1);
        dLdq << -s - (p.m1 + p.m2) * p.g * p.l1 * sin(q(0)), s - p.m2 * p.g * p.l2 * sin(q(1));
    }
};

}  // namespace eomgen::test
