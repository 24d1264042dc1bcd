/**
 * @file device_ensemble.hpp  One ensemble member integrated by code that runs on the host and, under nvcc, on a
 * CUDA device (EOMGEN_HD, device.hpp), M q̈ = f solved by the runtime's L D Lᵀ in registers, one terminal event
 * (a state crossing a value) located on the dense output by the same Brent search as integrate():
 *   - integrate_member_rk4: fixed-step RK4 on the grid of Rk4Stepper, cubic Hermite dense output;
 *   - integrate_member_dopri5: adaptive Dormand–Prince 5(4) with Dopri5's tableau, start (HINIT), PI step-size
 *     control and dense output (the functions dopri5.hpp and embedded_rk.hpp share with the host stepper).
 * No exceptions, no allocation: a failure is a status.
 *
 *     eomgen::device::Member<M> r = eomgen::device::integrate_member_rk4<M>(p, x0, t_end, dt, event);
 *     eomgen::device::Member<M> s = eomgen::device::integrate_member_dopri5<M>(p, x0, t_end, options, event);
 *
 * runtime/eomgen/cuda_ensemble.cuh launches them, one member per CUDA thread. The same functions compiled by a
 * C++ compiler are what tests/runtime/exam_device_ensemble.cpp compares with integrate_rk4 and integrate.
 */
#pragma once

#include "eomgen/device.hpp"
#include "eomgen/dopri5.hpp"
#include "eomgen/events.hpp"
#include "eomgen/linear_solve.hpp"
#include "eomgen/rk4.hpp"

#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace eomgen::device {

/// How a member ended: at t_end, at its event, or failed (M not positive definite, a non-finite state; for the
/// adaptive pair also more than max_steps attempted steps, or a step size below hmin), as the runtime's errors.
enum class Status : int { Ok = 0, Event = 1, Singular = 2, NonFinite = 3, TooManySteps = 4, StepSizeUnderflow = 5 };

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

using eomgen::detail::all_finite;

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
                hermite_dense((s - t) / h, h, x, fx, x_next, f_next, x_tmp);
                return g(x_tmp);
            };
            const double tol = 2 * std::numeric_limits<double>::epsilon() * (std::abs(t) > std::abs(t_next) ? std::abs(t) : std::abs(t_next));
            out.t = find_root_brent(g_dense, t, g_prev, t_next, g_now, tol);
            if (out.t == t_next)
                out.x = x_next;
            else
                hermite_dense((out.t - t) / h, h, x, fx, x_next, f_next, out.x);
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

/**
 * Integrates model M with parameters p from (0, x0) to t_end ≥ 0 by Dormand–Prince 5(4), step for step as
 * Dopri5 with the same options (rtol, atol, h0, hmin, hmax, max_steps, safety, min_factor, max_factor, beta)
 * driven by integrate(): the same first step, trial steps, step-size control and landing on t_end, and the event
 * located on the same dense output with the same Brent tolerance. Failures are statuses where the host throws:
 * Singular (M not positive definite at any stage), NonFinite (x0 or f(0, x0) not finite, or every trial step
 * down to hmin non-finite), TooManySteps, StepSizeUnderflow; the member's t and x are then the last accepted
 * point.
 */
template <class M>
EOMGEN_HD Member<M> integrate_member_dopri5(const typename M::Params& p, const typename M::State& x0, double t_end,
                                            const Dopri5Options<double>& o, StateEvent event) {
    using State = typename M::State;
    using std::abs;
    Member<M> out;
    out.x = x0;
    bool ok = true;
    const Rhs<M> f{&p, &ok};
    if (!all_finite(x0)) {
        out.status = Status::NonFinite;
        return out;
    }
    if (t_end == 0) return out;
    const double dir = t_end > 0 ? 1.0 : -1.0;
    const double hmax = o.hmax > 0 ? o.hmax : abs(t_end);
    State x = x0, k1 = x0, k2 = x0, k3 = x0, k4 = x0, k5 = x0, k6 = x0, k7 = x0, xs = x0, x_new = x0;
    const auto fail = [&](Status status, double t) {
        out.t = t;
        out.x = x;
        out.status = status;
        return out;
    };
    f(0.0, x, k1);
    if (!ok) return fail(Status::Singular, 0);
    if (!all_finite(k1)) return fail(Status::NonFinite, 0);
    double h = o.h0 != 0 ? dir * (abs(o.h0) < hmax ? abs(o.h0) : hmax)
                         : eomgen::detail::initial_step_size(f, 0.0, x, k1, dir, hmax, o.atol, o.rtol, 5, xs, x_new);
    if (!ok) return fail(Status::Singular, 0);
    eomgen::detail::StepSizeControl<double> control(o.safety, o.min_factor, o.max_factor, o.beta, 5, 0.75);
    const auto g = [&](const State& s) { return event.index >= 0 ? s(event.index) - event.value : 1.0; };
    double t = 0, g_prev = g(x);
    std::size_t attempts = 0;
    bool last_nonfinite = false;
    for (;;) {
        if (attempts >= o.max_steps) return fail(Status::TooManySteps, t);
        const double ulp16 = 16 * abs(std::nextafter(t, dir * std::numeric_limits<double>::infinity()) - t);
        const double hmin = o.hmin > ulp16 ? o.hmin : ulp16;
        bool last = false;
        if ((t + 1.01 * h - t_end) * dir >= 0) {
            h = t_end - t;  // a forced final step may be shorter than hmin
            last = true;
        } else if (abs(h) < hmin) {
            return fail(last_nonfinite ? Status::NonFinite : Status::StepSizeUnderflow, t);
        }
        ++attempts;
        eomgen::detail::dopri5_stages(f, t, x, k1, h, k2, k3, k4, k5, k6, k7, xs, x_new);
        if (!ok) return fail(Status::Singular, t);
        double err = std::numeric_limits<double>::quiet_NaN();
        if (all_finite(x_new) && all_finite(k7)) {
            eomgen::detail::dopri5_error(h, k1, k3, k4, k5, k6, k7, xs);
            err = std::sqrt(eomgen::detail::scaled_sum_of_squares(xs, x, x_new, o.atol, o.rtol) / double(x.size()));
        }
        if (!(err <= std::numeric_limits<double>::max())) {  // NaN or inf somewhere in the trial
            last_nonfinite = true;
            h = control.after_non_finite(h);
            continue;
        }
        last_nonfinite = false;
        const double h_next = control.next(err, h, hmax, dir);
        if (err > 1) {
            h = h_next;
            continue;
        }
        const double t_new = last ? t_end : t + h, h_step = t_new - t;
        const double g_now = g(x_new);
        if (event.index >= 0 && crosses(g_prev, g_now, EventDirection::Both)) {
            State r2 = x0, r3 = x0, r4 = x0, r5 = x0, x_dense = x0;
            eomgen::detail::dopri5_dense_coefficients(h, x, x_new, k1, k3, k4, k5, k6, k7, r2, r3, r4, r5);
            const auto dense = [&](double s, State& into) {
                if (s == t_new)
                    into = x_new;
                else if (s == t)
                    into = x;
                else
                    eomgen::detail::dopri5_dense((s - t) / h_step, x, r2, r3, r4, r5, into);
            };
            const auto g_dense = [&](const double& s) {
                dense(s, x_dense);
                return g(x_dense);
            };
            const double tol =
                2 * std::numeric_limits<double>::epsilon() * (abs(t) > abs(t_new) ? abs(t) : abs(t_new));
            out.t = find_root_brent(g_dense, t, g_prev, t_new, g_now, tol);
            dense(out.t, out.x);
            out.status = Status::Event;
            return out;
        }
        t = t_new;
        x = x_new;
        k1 = k7;  // first same as last
        g_prev = g_now;
        h = h_next;
        if (last) break;
    }
    out.t = t;
    out.x = x;
    return out;
}

}  // namespace eomgen::device
