/** @file rk4.hpp  Classic fixed-step fourth-order Runge–Kutta, with cubic Hermite dense output. */
#pragma once

#include "eomgen/device.hpp"
#include "eomgen/errors.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>

namespace eomgen {

/**
 * One classic RK4 step of size h for x' = f(t, x) (Hairer–Nørsett–Wanner, "Solving ODEs I", §II.1, the
 * "classical Runge–Kutta method" of Kutta 1901):
 *
 *   k1 = f(t, x),  k2 = f(t + h/2, x + h/2 k1),  k3 = f(t + h/2, x + h/2 k2),  k4 = f(t + h, x + h k3),
 *   x_next = x + h/6 (k1 + 2 k2 + 2 k3 + k4).
 *
 * `System` is any callable f(const Scalar& t, const State& x, State& xdot); `State` an Eigen column vector
 * (fixed or dynamic size) whose scalar is double, long double or any Eigen scalar. `k1` = f(t, x) is an
 * input so callers that already have it (the dense-output driver below) do not evaluate it twice.
 * Exactly three evaluations of f. No error checking: see Rk4Stepper for the checked, counted version.
 */
template <class System, class State>
EOMGEN_HD void rk4_step(System&& f, const typename State::Scalar& t, const State& x, const State& k1,
              const typename State::Scalar& h, State& x_next) {
    using Scalar = typename State::Scalar;
    const Scalar half = h / Scalar(2);
    State k2 = k1, k3 = k1, k4 = k1;  // copies size the dynamic case
    State xs = x + half * k1;
    f(t + half, xs, k2);
    xs = x + half * k2;
    f(t + half, xs, k3);
    xs = x + h * k3;
    f(t + h, xs, k4);
    x_next = x + (h / Scalar(6)) * (k1 + Scalar(2) * (k2 + k3) + k4);
}

/// One RK4 step that evaluates k1 itself: four evaluations of f.
template <class System, class State>
void rk4_step(System&& f, const typename State::Scalar& t, const State& x, const typename State::Scalar& h,
              State& x_next) {
    State k1 = x;
    f(t, x, k1);
    rk4_step(f, t, x, k1, h, x_next);
}

/**
 * The cubic Hermite interpolant at θ ∈ [0, 1] across a step (x0, f0) → (x1, f1) of size h (the dense output of
 * Rk4Stepper and of the device member integrator, device_ensemble.hpp):
 *   u(θ) = (1−θ) x0 + θ x1 + θ(θ−1) [ (1−2θ)(x1 − x0) + (θ−1) h f0 + θ h f1 ].
 */
template <class State>
EOMGEN_HD void hermite_dense(const typename State::Scalar& th, const typename State::Scalar& h, const State& x0,
                             const State& f0, const State& x1, const State& f1, State& out) {
    using Scalar = typename State::Scalar;
    const Scalar one(1), two(2);
    out = (one - th) * x0 + th * x1 +
          (th * (th - one)) * ((one - two * th) * (x1 - x0) + ((th - one) * h) * f0 + (th * h) * f1);
}

/**
 * Fixed-step RK4 from t0 to t_end, with the interface the integration driver (integrate.hpp) expects of a
 * stepper: step(), t(), x(), t_prev(), x_prev(), dense(), done() and the counters.
 *
 * The grid is t_k = t0 + k·dt (computed by multiplication so rounding does not accumulate); the last step
 * is shortened to land exactly on t_end, and a remainder under 1e-6·dt is absorbed into the last step
 * rather than taken as a uselessly tiny extra step. dt must be positive; t_end < t0 integrates backwards.
 *
 * Dense output on the last step is the cubic Hermite interpolant through (x_prev, f_prev) and (x, f)
 * (HNW "Solving ODEs I" §II.6, eq. (6.7)):
 *   u(θ) = (1-θ) x0 + θ x1 + θ(θ-1) [ (1-2θ)(x1-x0) + (θ-1) h f0 + θ h f1 ],   θ = (t - t_prev)/h,
 * whose O(h⁴) local error matches RK4's global order. f at the new point is evaluated eagerly: it is the
 * next step's k1, so the only extra evaluation is the one after the final step.
 *
 * Throws NonFiniteState (with t and the last finite state) when x or f(t, x) becomes NaN or infinite.
 */
template <class State>
class Rk4Stepper {
  public:
    using Scalar = typename State::Scalar;

    template <class System>
    Rk4Stepper(System&& f, const Scalar& t0, const State& x0, const Scalar& t_end, const Scalar& dt)
        : t0_(t0), t_end_(t_end), t_(t0), t_prev_(t0), x_(x0), x_prev_(x0), f_(x0), f_prev_(x0) {
        using std::ceil;
        if (!(dt > Scalar(0)) || !std::isfinite(dt))
            throw std::invalid_argument("Rk4Stepper: dt must be positive and finite");
        if (!x0.allFinite())
            throw NonFiniteState(describe_state("initial state is not finite", t0, x0), value_of(t0));
        dt_ = t_end >= t0 ? dt : -dt;
        const Scalar ratio = (t_end - t0) / dt_;
        n_steps_ = ratio > Scalar(1e-6) ? static_cast<std::size_t>(ceil(ratio - Scalar(1e-6))) : 0;
        if (n_steps_ == 0 && t_end != t0) n_steps_ = 1;
        f(t_, x_, f_);
        ++n_rhs_;
        if (!f_.allFinite())
            throw NonFiniteState(describe_state("right-hand side is not finite", t_, x_), value_of(t_));
    }

    /// Advances one grid step (the last one ends exactly at t_end). Four evaluations of f.
    template <class System>
    void step(System&& f) {
        if (done()) throw std::logic_error("Rk4Stepper::step called after reaching t_end");
        const Scalar t_next = k_ + 1 == n_steps_ ? t_end_ : t0_ + Scalar(k_ + 1) * dt_;
        const Scalar h = t_next - t_;
        State x_next = x_;
        rk4_step(f, t_, x_, f_, h, x_next);
        n_rhs_ += 3;
        if (!x_next.allFinite()) {
            std::ostringstream what;
            what << "RK4 step of size " << value_of(h) << " produced a non-finite state, starting";
            throw NonFiniteState(describe_state(what.str(), t_, x_), value_of(t_));
        }
        State f_next = x_next;
        f(t_next, x_next, f_next);
        ++n_rhs_;
        if (!f_next.allFinite())
            throw NonFiniteState(describe_state("right-hand side is not finite", t_next, x_next),
                                 value_of(t_next));
        t_prev_ = t_;
        x_prev_.swap(x_);
        f_prev_.swap(f_);
        t_ = t_next;
        x_ = x_next;
        f_ = f_next;
        ++k_;
    }

    /// Cubic Hermite interpolant on [t_prev, t] (see the class comment); exact at both ends.
    void dense(const Scalar& t, State& x) const {
        if (t == t_) {
            x = x_;
            return;
        }
        if (t == t_prev_) {
            x = x_prev_;
            return;
        }
        const Scalar h = t_ - t_prev_;
        hermite_dense((t - t_prev_) / h, h, x_prev_, f_prev_, x_, f_, x);
    }

    bool done() const { return k_ == n_steps_; }
    const Scalar& t() const { return t_; }
    const State& x() const { return x_; }
    const Scalar& t_prev() const { return t_prev_; }
    const State& x_prev() const { return x_prev_; }
    std::size_t accepted_steps() const { return k_; }
    std::size_t rejected_steps() const { return 0; }
    std::size_t rhs_evaluations() const { return n_rhs_; }

  private:
    Scalar t0_, t_end_, dt_ = Scalar(0);
    Scalar t_, t_prev_;
    State x_, x_prev_, f_, f_prev_;
    std::size_t n_steps_ = 0, k_ = 0, n_rhs_ = 0;
};

}  // namespace eomgen
