/**
 * @file device_ensemble.hpp  One ensemble member integrated by code that runs on the host and, under nvcc, on a
 * CUDA device (EOMGEN_HD, device.hpp): fixed-step RK4 on the grid of Rk4Stepper, M q̈ = f solved by the
 * runtime's L D Lᵀ in registers, one terminal event (a state crossing a value) located on the cubic Hermite dense
 * output by the same Brent search as integrate(). No exceptions, no allocation: a failure is a status.
 *
 *     eomgen::device::Member<M> r = eomgen::device::integrate_member_rk4<M>(p, x0, t_end, dt, event);
 *
 * runtime/eomgen/cuda_ensemble.cuh launches it, one member per CUDA thread. The same function compiled by a
 * C++ compiler is what tests/runtime/exam_device_ensemble.cpp compares with integrate_rk4 (rk4.hpp).
 */
#pragma once

#include "eomgen/device.hpp"
#include "eomgen/events.hpp"
#include "eomgen/linear_solve.hpp"
#include "eomgen/rk4.hpp"

#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace eomgen::device {

/// How a member ended: at t_end, at its event, or failed (M not positive definite, a non-finite state).
enum class Status : int { Ok = 0, Event = 1, Singular = 2, NonFinite = 3 };

/// A terminal event: state component `index` crosses `value` (either direction); index < 0: none.
struct StateEvent {
    int index = -1;
    double value = 0;
};

/// What one member gave: where it stopped and the state there.
template <class M>
struct Member {
    double t = 0;
    typename M::State x;
    Status status = Status::Ok;
};

/**
 * Solves A x = b for symmetric positive definite A (fixed size) by the runtime's L D Lᵀ (factor_ldlt and
 * substitute_ldlt of linear_solve.hpp, without its exceptions). Returns false when a pivot is not positive or
 * not finite, or the result is not finite (a singular or indefinite M).
 */
template <class Matrix, class Vector>
EOMGEN_HD bool ldlt_solve(const Matrix& A, const Vector& b, Vector& x) {
    constexpr int n = Vector::RowsAtCompileTime;
    Eigen::Matrix<double, n, n, Eigen::RowMajor> L;
    Vector d, inv_d;
    factor_ldlt(A, n, L, d, inv_d);
    for (int i = 0; i < n; ++i)
        if (!(d(i) > 0) || !(d(i) < std::numeric_limits<double>::infinity())) return false;
    x = b;
    substitute_ldlt(L, inv_d, n, x);
    for (int i = 0; i < n; ++i)
        if (!(x(i) - x(i) == 0)) return false;  // NaN or infinite
    return true;
}

/// x' = [q', M⁻¹ f] of model M from its generated dynamics(); clears *ok when M cannot be solved.
template <class M>
struct Rhs {
    const typename M::Params* p;
    bool* ok;

    EOMGEN_HD void operator()(const double& t, const typename M::State& x, typename M::State& xdot) const {
        typename M::Config q, qd, f, qdd;
        for (int i = 0; i < M::nq; ++i) {
            q(i) = x(i);
            qd(i) = x(M::nq + i);
        }
        typename M::MassMatrix mass;
        M::dynamics(t, q, qd, *p, mass, f);
        if (!ldlt_solve(mass, f, qdd)) {
            *ok = false;
            qdd.setZero();
        }
        for (int i = 0; i < M::nq; ++i) {
            xdot(i) = qd(i);
            xdot(M::nq + i) = qdd(i);
        }
    }
};

template <class State>
EOMGEN_HD bool all_finite(const State& x) {
    for (int i = 0; i < x.size(); ++i)
        if (!(x(i) - x(i) == 0)) return false;
    return true;
}

/// Cubic Hermite interpolant at θ ∈ [0, 1] of the step (x0, f0) → (x1, f1) of size h (as Rk4Stepper::dense).
template <class State>
EOMGEN_HD void hermite(double th, double h, const State& x0, const State& f0, const State& x1, const State& f1,
                       State& out) {
    out = (1 - th) * x0 + th * x1 + (th * (th - 1)) * ((1 - 2 * th) * (x1 - x0) + ((th - 1) * h) * f0 + (th * h) * f1);
}

/**
 * Integrates model M with parameters p from (0, x0) to t_end with fixed RK4 steps dt on Rk4Stepper's grid
 * (t_k = k·dt, the last step shortened to land on t_end, a remainder under 1e-6·dt absorbed), stopping where
 * `event` fires. dt > 0 and t_end ≥ 0.
 */
template <class M>
EOMGEN_HD Member<M> integrate_member_rk4(const typename M::Params& p, const typename M::State& x0, double t_end,
                                         double dt, StateEvent event) {
    using State = typename M::State;
    Member<M> out;
    out.x = x0;
    bool ok = true;
    const Rhs<M> f{&p, &ok};
    const double ratio = t_end / dt;
    long n_steps = ratio > 1e-6 ? long(std::ceil(ratio - 1e-6)) : 0;
    if (n_steps == 0 && t_end != 0) n_steps = 1;
    State x = x0, fx = x0, x_next = x0, f_next = x0, x_tmp = x0;
    f(0.0, x, fx);
    if (!ok || !all_finite(x) || !all_finite(fx)) {
        out.status = ok ? Status::NonFinite : Status::Singular;
        return out;
    }
    const auto g = [&](const State& s) { return event.index >= 0 ? s(event.index) - event.value : 1.0; };
    double t = 0, g_prev = g(x);
    for (long k = 0; k < n_steps; ++k) {
        const double t_next = k + 1 == n_steps ? t_end : double(k + 1) * dt;
        const double h = t_next - t;
        rk4_step(f, t, x, fx, h, x_next);
        if (ok && all_finite(x_next)) f(t_next, x_next, f_next);
        if (!ok || !all_finite(x_next) || !all_finite(f_next)) {
            out.t = t;
            out.x = x;
            out.status = ok ? Status::NonFinite : Status::Singular;
            return out;
        }
        const double g_now = g(x_next);
        if (event.index >= 0 && crosses(g_prev, g_now, EventDirection::Both)) {
            const auto g_dense = [&](const double& s) {
                if (s == t_next) return g_now;
                if (s == t) return g_prev;
                hermite((s - t) / h, h, x, fx, x_next, f_next, x_tmp);
                return g(x_tmp);
            };
            const double tol = 2 * std::numeric_limits<double>::epsilon() * (std::abs(t) > std::abs(t_next) ? std::abs(t) : std::abs(t_next));
            out.t = find_root_brent(g_dense, t, g_prev, t_next, g_now, tol);
            if (out.t == t_next)
                out.x = x_next;
            else
                hermite((out.t - t) / h, h, x, fx, x_next, f_next, out.x);
            out.status = Status::Event;
            return out;
        }
        t = t_next;
        x = x_next;
        fx = f_next;
        g_prev = g_now;
    }
    out.t = t;
    out.x = x;
    return out;
}

}  // namespace eomgen::device
