/** @file dopri5.hpp  Adaptive Dormand–Prince 5(4) with error control and 4th-order dense output. */
#pragma once

#include "eomgen/embedded_rk.hpp"

#include <Eigen/Core>

#include <limits>

namespace eomgen {

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
        const Scalar th = (t - this->t_prev_) / this->h_last_;
        const Scalar th1 = Scalar(1) - th;
        x = this->x_prev_ + th * (r2_ + th1 * (r3_ + th * (r4_ + th1 * r5_)));
    }

  private:
    // Dormand–Prince coefficients (HNW I, Table 5.2 of §II.5); built from exact integer ratios so long double
    // gets them to full precision.
    static Scalar q(long long num, long long den) { return Scalar(num) / Scalar(den); }

    /// One trial step of size h from (t_, x_) with k1_ = f(t_, x_); fills k2..k7 and x_new_ and returns
    /// the scaled error norm (NaN or inf when anything went non-finite).
    template <class System>
    Scalar attempt(System& f, const Scalar& h) {
        const Scalar& t = this->t_;
        const State& x = this->x_;
        const State& k1 = this->k1_;
        State& xs = this->xs_;
        State& x_new = this->x_new_;
        const Scalar c2 = q(1, 5), c3 = q(3, 10), c4 = q(4, 5), c5 = q(8, 9);
        xs = x + h * (q(1, 5) * k1);
        this->evaluate(f, t + c2 * h, xs, k2_);
        xs = x + h * (q(3, 40) * k1 + q(9, 40) * k2_);
        this->evaluate(f, t + c3 * h, xs, k3_);
        xs = x + h * (q(44, 45) * k1 - q(56, 15) * k2_ + q(32, 9) * k3_);
        this->evaluate(f, t + c4 * h, xs, k4_);
        xs = x + h * (q(19372, 6561) * k1 - q(25360, 2187) * k2_ + q(64448, 6561) * k3_ - q(212, 729) * k4_);
        this->evaluate(f, t + c5 * h, xs, k5_);
        xs = x + h * (q(9017, 3168) * k1 - q(355, 33) * k2_ + q(46732, 5247) * k3_ + q(49, 176) * k4_ -
                      q(5103, 18656) * k5_);
        this->evaluate(f, t + h, xs, k6_);
        x_new = x + h * (q(35, 384) * k1 + q(500, 1113) * k3_ + q(125, 192) * k4_ - q(2187, 6784) * k5_ +
                         q(11, 84) * k6_);
        this->evaluate(f, t + h, x_new, k7_);
        if (!x_new.allFinite() || !k7_.allFinite()) return std::numeric_limits<Scalar>::quiet_NaN();
        // x5 - x4 = h Σ e_i k_i
        xs = h * (q(71, 57600) * k1 - q(71, 16695) * k3_ + q(71, 1920) * k4_ - q(17253, 339200) * k5_ +
                  q(22, 525) * k6_ - q(1, 40) * k7_);
        return this->scaled_norm(xs);
    }

    /// Dense-output coefficients of the accepted step, then (t, x, f) ← (t + h, x_new, k7).
    void accept(const Scalar& h, bool last) {
        r2_ = this->x_new_ - this->x_;
        r3_ = h * this->k1_ - r2_;
        r4_ = r2_ - h * k7_ - r3_;
        r5_ = h * (q(-12715105075LL, 11282082432LL) * this->k1_ + q(87487479700LL, 32700410799LL) * k3_ +
                   q(-10690763975LL, 1880347072LL) * k4_ + q(701980252875LL, 199316789632LL) * k5_ +
                   q(-1453857185LL, 822651844LL) * k6_ + q(69997945LL, 29380423LL) * k7_);
        this->commit(h, last, k7_);  // first same as last
    }

    State k2_, k3_, k4_, k5_, k6_, k7_, r2_, r3_, r4_, r5_;
};

}  // namespace eomgen
