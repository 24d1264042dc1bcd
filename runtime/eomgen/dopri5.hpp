/** @file dopri5.hpp  Adaptive Dormand–Prince 5(4) with error control and 4th-order dense output. */
#pragma once

#include "eomgen/device.hpp"
#include "eomgen/embedded_rk.hpp"

#include <Eigen/Core>

#include <limits>

namespace eomgen {

namespace detail {

/// A Dormand–Prince coefficient num/den, built from exact integers so long double gets it to full precision.
template <class Scalar>
EOMGEN_HD Scalar dp_coefficient(long long num, long long den) {
    return Scalar(num) / Scalar(den);
}

/**
 * The Dormand–Prince 5(4) tableau (HNW I, Table 5.2 of §II.5), shared by Dopri5 below and the member integrator
 * of device ensembles (device_ensemble.hpp). Stages 2–7 of one trial step of size h from (t, x), k1 = f(t, x):
 * `eval(t, x, k)` is called six times; x_new is the 5th-order solution and k7 = f(t + h, x_new), the next step's
 * k1 (first same as last); xs is scratch.
 */
template <class Eval, class State>
EOMGEN_HD void dopri5_stages(Eval& eval, const typename State::Scalar& t, const State& x, const State& k1,
                             const typename State::Scalar& h, State& k2, State& k3, State& k4, State& k5, State& k6,
                             State& k7, State& xs, State& x_new) {
    using Scalar = typename State::Scalar;
    const auto q = [](long long num, long long den) { return dp_coefficient<Scalar>(num, den); };
    const Scalar c2 = q(1, 5), c3 = q(3, 10), c4 = q(4, 5), c5 = q(8, 9);
    xs = x + h * (q(1, 5) * k1);
    eval(t + c2 * h, xs, k2);
    xs = x + h * (q(3, 40) * k1 + q(9, 40) * k2);
    eval(t + c3 * h, xs, k3);
    xs = x + h * (q(44, 45) * k1 - q(56, 15) * k2 + q(32, 9) * k3);
    eval(t + c4 * h, xs, k4);
    xs = x + h * (q(19372, 6561) * k1 - q(25360, 2187) * k2 + q(64448, 6561) * k3 - q(212, 729) * k4);
    eval(t + c5 * h, xs, k5);
    xs = x + h * (q(9017, 3168) * k1 - q(355, 33) * k2 + q(46732, 5247) * k3 + q(49, 176) * k4 -
                  q(5103, 18656) * k5);
    eval(t + h, xs, k6);
    x_new = x + h * (q(35, 384) * k1 + q(500, 1113) * k3 + q(125, 192) * k4 - q(2187, 6784) * k5 +
                     q(11, 84) * k6);
    eval(t + h, x_new, k7);
}

/// The error estimate x5 − x4 = h Σ e_i k_i of the trial step dopri5_stages made.
template <class State>
EOMGEN_HD void dopri5_error(const typename State::Scalar& h, const State& k1, const State& k3, const State& k4,
                            const State& k5, const State& k6, const State& k7, State& e) {
    using Scalar = typename State::Scalar;
    const auto q = [](long long num, long long den) { return dp_coefficient<Scalar>(num, den); };
    e = h * (q(71, 57600) * k1 - q(71, 16695) * k3 + q(71, 1920) * k4 - q(17253, 339200) * k5 + q(22, 525) * k6 -
             q(1, 40) * k7);
}

/// The dense-output coefficients r2 … r5 of an accepted step x → x_new of size h (Hairer's CONTD5).
template <class State>
EOMGEN_HD void dopri5_dense_coefficients(const typename State::Scalar& h, const State& x, const State& x_new,
                                         const State& k1, const State& k3, const State& k4, const State& k5,
                                         const State& k6, const State& k7, State& r2, State& r3, State& r4,
                                         State& r5) {
    using Scalar = typename State::Scalar;
    const auto q = [](long long num, long long den) { return dp_coefficient<Scalar>(num, den); };
    r2 = x_new - x;
    r3 = h * k1 - r2;
    r4 = r2 - h * k7 - r3;
    r5 = h * (q(-12715105075LL, 11282082432LL) * k1 + q(87487479700LL, 32700410799LL) * k3 +
              q(-10690763975LL, 1880347072LL) * k4 + q(701980252875LL, 199316789632LL) * k5 +
              q(-1453857185LL, 822651844LL) * k6 + q(69997945LL, 29380423LL) * k7);
}

/// u(θ) = x_prev + θ (r2 + (1−θ) (r3 + θ (r4 + (1−θ) r5))), θ ∈ [0, 1] across the step.
template <class State>
EOMGEN_HD void dopri5_dense(const typename State::Scalar& th, const State& x_prev, const State& r2, const State& r3,
                            const State& r4, const State& r5, State& x) {
    const typename State::Scalar th1 = typename State::Scalar(1) - th;
    x = x_prev + th * (r2 + th1 * (r3 + th * (r4 + th1 * r5)));
}

}  // namespace detail

/**
 * Dormand–Prince 5(4) (Dormand & Prince 1980; coefficients and the "first same as last" property in
 * HNW "Solving ODEs I", §II.5, Table 5.2), one accepted step per call of step(), for x' = f(t, x) with
 * `System` any callable f(const Scalar& t, const State& x, State& xdot) and `State` an Eigen column vector
 * (fixed or dynamic size; Scalar double or long double).
 *
 * Error control (HNW §II.4): the step is accepted when
 *   err = sqrt( (1/n) Σ_i ( (x5_i - x4_i) / sc_i )² ) ≤ 1,   sc_i = atol + rtol·max(|x_i|, |x_new_i|).
 * Step size, start, errors thrown: detail::EmbeddedRk (embedded_rk.hpp), with q = 5:
 *   h_new = h · clamp( safety · err^(-(1/5 - 0.75 β)) · err_prev^β, min_factor, max_factor ).
 * Each attempted step costs six evaluations of f (the seventh is the next step's first).
 *
 * Dense output on the last accepted step [t_prev, t] (HNW §II.6, Hairer's CONTD5):
 *   u(θ) = r1 + θ (r2 + (1-θ) (r3 + θ (r4 + (1-θ) r5))),   θ = (t - t_prev)/h,
 *   r1 = x0, r2 = x1 - x0, r3 = h k1 - r2, r4 = r2 - h k7 - r3, r5 = h Σ d_i k_i,
 * continuous, 4th order, exact at both ends, and free (no extra evaluations of f).
 */
template <class State>
class Dopri5 : public detail::EmbeddedRk<Dopri5<State>, State> {
    using Base = detail::EmbeddedRk<Dopri5<State>, State>;
    friend Base;

  public:
    using Scalar = typename State::Scalar;
    using Options = Dopri5Options<Scalar>;

    /// Prepares integration from (t0, x0) towards t_end (either direction). Evaluates f once or twice.
    template <class System>
    Dopri5(System&& f, const Scalar& t0, const State& x0, const Scalar& t_end, const Options& options = {})
        : Base(f, t0, x0, t_end, options, "Dopri5", 5, Scalar(0.75)),
          k2_(x0),
          k3_(x0),
          k4_(x0),
          k5_(x0),
          k6_(x0),
          k7_(x0),
          r2_(State::Zero(x0.size())),
          r3_(r2_),
          r4_(r2_),
          r5_(r2_) {}

    /// Dense output at t in [t_prev, t] of the last accepted step (CONTD5); exact at both ends.
    void dense(const Scalar& t, State& x) const {
        if (this->dense_at_node(t, x)) return;
        detail::dopri5_dense((t - this->t_prev_) / this->h_last_, this->x_prev_, r2_, r3_, r4_, r5_, x);
    }

  private:
    /// One trial step of size h from (t_, x_) with k1_ = f(t_, x_): fills k2..k7 and x_new_ and returns
    /// the scaled error norm (NaN or inf when anything went non-finite).
    template <class System>
    Scalar attempt(System& f, const Scalar& h) {
        auto eval = [&](const Scalar& t, const State& x, State& xdot) { this->evaluate(f, t, x, xdot); };
        detail::dopri5_stages(eval, this->t_, this->x_, this->k1_, h, k2_, k3_, k4_, k5_, k6_, k7_, this->xs_,
                              this->x_new_);
        if (!this->x_new_.allFinite() || !k7_.allFinite()) return std::numeric_limits<Scalar>::quiet_NaN();
        detail::dopri5_error(h, this->k1_, k3_, k4_, k5_, k6_, k7_, this->xs_);
        return this->scaled_norm(this->xs_);
    }

    /// Dense-output coefficients of the accepted step, then (t, x, f) ← (t + h, x_new, k7).
    void accept(const Scalar& h, bool last) {
        detail::dopri5_dense_coefficients(h, this->x_, this->x_new_, this->k1_, k3_, k4_, k5_, k6_, k7_, r2_, r3_,
                                          r4_, r5_);
        this->commit(h, last, k7_);  // first same as last
    }

    State k2_, k3_, k4_, k5_, k6_, k7_, r2_, r3_, r4_, r5_;
};

}  // namespace eomgen
