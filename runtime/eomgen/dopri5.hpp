/** @file dopri5.hpp  Adaptive Dormand–Prince 5(4) with error control and 4th-order dense output. */
#pragma once

#include "eomgen/errors.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace eomgen {

/**
 * Settings of Dopri5. Defaults are those of Hairer's DOPRI5 code (HNW "Solving ODEs I", §II.4 and the
 * appendix listing), except the tolerances.
 */
template <class Scalar>
struct Dopri5Options {
    Scalar rtol = Scalar(1e-6);       ///< relative tolerance, per component
    Scalar atol = Scalar(1e-9);       ///< absolute tolerance, per component; must be positive
    Scalar h0 = Scalar(0);            ///< first step size; 0: Hairer's automatic choice (HNW §II.4)
    Scalar hmin = Scalar(0);          ///< smallest |h| before StepSizeUnderflow; never below 16 ulp of t
    Scalar hmax = Scalar(0);          ///< largest |h|; 0: |t_end - t0|
    std::size_t max_steps = 100000;   ///< attempted steps (accepted + rejected) before TooManySteps
    Scalar safety = Scalar(0.9);      ///< safety factor of the step-size controller
    Scalar min_factor = Scalar(0.2);  ///< h_new / h is kept within [min_factor, max_factor]
    Scalar max_factor = Scalar(10);
    Scalar beta = Scalar(0.04);  ///< PI (Gustafsson) stabilisation exponent; 0 = plain I controller
};

/**
 * Dormand–Prince 5(4) (Dormand & Prince 1980; coefficients and the "first same as last" property in
 * HNW "Solving ODEs I", §II.5, Table 5.2), one accepted step per call of step(), for x' = f(t, x) with
 * `System` any callable f(const Scalar& t, const State& x, State& xdot) and `State` an Eigen column vector
 * (fixed or dynamic size; Scalar double or long double).
 *
 * Error control (HNW §II.4): the step is accepted when
 *   err = sqrt( (1/n) Σ_i ( (x5_i - x4_i) / sc_i )² ) ≤ 1,   sc_i = atol + rtol·max(|x_i|, |x_new_i|).
 * Step size (HNW §II.4; the PI variant of Gustafsson, Hairer–Wanner "Solving ODEs II" §IV.2, as in
 * Hairer's DOPRI5 code):
 *   h_new = h · clamp( safety · err^(-(1/5 - 0.75 β)) · err_prev^β, min_factor, max_factor ),
 * with no growth right after a rejection. A trial step that produces NaN or infinity is rejected and
 * retried with h·min_factor, so a model undefined past some point is approached rather than stepped over.
 * The first step is Hairer's estimate from f(t0, x0) and one explicit Euler step (HNW §II.4, "Starting
 * step size"), unless options.h0 is set. The step never passes t_end and the last one lands on it exactly.
 *
 * Dense output on the last accepted step [t_prev, t] (HNW §II.6, Hairer's CONTD5):
 *   u(θ) = r1 + θ (r2 + (1-θ) (r3 + θ (r4 + (1-θ) r5))),   θ = (t - t_prev)/h,
 *   r1 = x0, r2 = x1 - x0, r3 = h k1 - r2, r4 = r2 - h k7 - r3, r5 = h Σ d_i k_i,
 * continuous, 4th order, exact at both ends, and free (no extra evaluations of f).
 *
 * Errors: NonFiniteState when x0 or f(t, x) at an accepted point is not finite, or when every trial step
 * down to hmin produced non-finite values; StepSizeUnderflow when the controller wants |h| below
 * max(hmin, 16 ulp(t)); TooManySteps after max_steps attempted steps. Messages carry t and the state.
 */
template <class State>
class Dopri5 {
  public:
    using Scalar = typename State::Scalar;
    using Options = Dopri5Options<Scalar>;

    /// Prepares integration from (t0, x0) towards t_end (either direction). Evaluates f once or twice.
    template <class System>
    Dopri5(System&& f, const Scalar& t0, const State& x0, const Scalar& t_end, const Options& options = {})
        : opts_(options),
          t_end_(t_end),
          t_(t0),
          t_prev_(t0),
          x_(x0),
          x_prev_(x0),
          k1_(x0),
          k2_(x0),
          k3_(x0),
          k4_(x0),
          k5_(x0),
          k6_(x0),
          k7_(x0),
          x_new_(x0),
          xs_(x0),
          r2_(State::Zero(x0.size())),
          r3_(r2_),
          r4_(r2_),
          r5_(r2_) {
        using std::abs;
        // atol > 0: with a purely relative test a component passing through 0 would have no error scale.
        if (!(opts_.rtol >= Scalar(0)) || !(opts_.atol > Scalar(0)))
            throw std::invalid_argument("Dopri5: need rtol >= 0 and atol > 0");
        if (!(opts_.safety > Scalar(0)) || !(opts_.min_factor > Scalar(0)) ||
            !(opts_.min_factor < Scalar(1)) || !(opts_.max_factor > Scalar(1)))
            throw std::invalid_argument("Dopri5: need safety > 0 and 0 < min_factor < 1 < max_factor");
        dir_ = t_end >= t0 ? Scalar(1) : Scalar(-1);
        hmax_ = opts_.hmax > Scalar(0) ? opts_.hmax : abs(t_end - t0);
        if (!x0.allFinite())
            throw NonFiniteState(describe_state("initial state is not finite", t0, x0), value_of(t0));
        if (t_end == t0) return;
        evaluate(f, t_, x_, k1_);
        if (!k1_.allFinite())
            throw NonFiniteState(describe_state("right-hand side is not finite", t_, x_), value_of(t_));
        h_ = opts_.h0 != Scalar(0) ? dir_ * std::min(abs(opts_.h0), hmax_) : initial_step(f);
    }

    /// Takes one accepted step (rejected trials are retried internally). Call only while !done().
    template <class System>
    void step(System&& f) {
        using std::abs;
        using std::max;
        using std::min;
        using std::pow;
        if (done()) throw std::logic_error("Dopri5::step called after reaching t_end");
        const Scalar one(1);
        bool last_nonfinite = false;
        for (;;) {
            if (n_accepted_ + n_rejected_ >= opts_.max_steps)
                throw TooManySteps(describe_state("more than max_steps = " + std::to_string(opts_.max_steps) +
                                                      " steps attempted",
                                                  t_, x_),
                                   value_of(t_));
            const Scalar ulp16 =
                Scalar(16) * abs(std::nextafter(t_, dir_ * std::numeric_limits<Scalar>::infinity()) - t_);
            const Scalar hmin = max(opts_.hmin, ulp16);
            bool last = false;
            if ((t_ + Scalar(1.01) * h_ - t_end_) * dir_ >= Scalar(0)) {
                h_ = t_end_ - t_;  // a forced final step may be shorter than hmin
                last = true;
            } else if (abs(h_) < hmin) {
                std::ostringstream why;
                why << (last_nonfinite ? "right-hand side or state not finite for every step size down to "
                                       : "step size fell below hmin = ")
                    << value_of(hmin);
                const std::string msg = describe_state(why.str(), t_, x_);
                if (last_nonfinite) throw NonFiniteState(msg, value_of(t_));
                throw StepSizeUnderflow(msg, value_of(t_));
            }
            const Scalar h = h_;
            const Scalar err = attempt(f, h);
            if (!(err <= std::numeric_limits<Scalar>::max())) {  // NaN or inf somewhere in the trial
                last_nonfinite = true;
                ++n_rejected_;
                h_ = h * opts_.min_factor;
                rejected_last_ = true;
                continue;
            }
            last_nonfinite = false;
            const Scalar expo1 = Scalar(0.2) - opts_.beta * Scalar(0.75);
            const Scalar fac11 = pow(err, expo1);
            if (err <= one) {
                Scalar fac = fac11 / pow(errold_, opts_.beta);
                fac = max(one / opts_.max_factor, min(one / opts_.min_factor, fac / opts_.safety));
                Scalar h_new = h / fac;
                errold_ = max(err, Scalar(1e-4));
                accept(h, last);
                if (abs(h_new) > hmax_) h_new = dir_ * hmax_;
                if (rejected_last_ && abs(h_new) > abs(h)) h_new = h;
                rejected_last_ = false;
                h_ = h_new;
                return;
            }
            ++n_rejected_;
            h_ = h / min(one / opts_.min_factor, fac11 / opts_.safety);
            rejected_last_ = true;
        }
    }

    /// Dense output at t in [t_prev, t] of the last accepted step (CONTD5); exact at both ends.
    void dense(const Scalar& t, State& x) const {
        if (t == t_) {
            x = x_;
            return;
        }
        if (t == t_prev_) {
            x = x_prev_;
            return;
        }
        const Scalar th = (t - t_prev_) / h_last_;
        const Scalar th1 = Scalar(1) - th;
        x = x_prev_ + th * (r2_ + th1 * (r3_ + th * (r4_ + th1 * r5_)));
    }

    bool done() const { return t_ == t_end_; }
    const Scalar& t() const { return t_; }
    const State& x() const { return x_; }
    const Scalar& t_prev() const { return t_prev_; }
    const State& x_prev() const { return x_prev_; }
    const State& derivative() const { return k1_; }  ///< f(t, x) at the current point
    const Scalar& last_step_size() const { return h_last_; }
    const Scalar& next_step_size() const { return h_; }
    std::size_t accepted_steps() const { return n_accepted_; }
    std::size_t rejected_steps() const { return n_rejected_; }
    std::size_t rhs_evaluations() const { return n_rhs_; }

  private:
    // Dormand–Prince coefficients (HNW I, Table 5.2 of §II.5); built from exact integer ratios so long double
    // gets them to full precision.
    static Scalar q(long long num, long long den) { return Scalar(num) / Scalar(den); }

    template <class System>
    void evaluate(System& f, const Scalar& t, const State& x, State& xdot) {
        f(t, x, xdot);
        ++n_rhs_;
    }

    /// Hairer's HINIT: h from ‖x0‖/‖f0‖, refined with the second derivative from one Euler step.
    template <class System>
    Scalar initial_step(System& f) {
        using std::abs;
        using std::max;
        using std::min;
        using std::pow;
        using std::sqrt;
        const Eigen::Index n = x_.size();
        Scalar dnf(0), dny(0);
        for (Eigen::Index i = 0; i < n; ++i) {
            const Scalar sk = opts_.atol + opts_.rtol * abs(x_(i));
            dnf += (k1_(i) / sk) * (k1_(i) / sk);
            dny += (x_(i) / sk) * (x_(i) / sk);
        }
        dnf /= Scalar(n);
        dny /= Scalar(n);
        Scalar h =
            (dnf <= Scalar(1e-10) || dny <= Scalar(1e-10)) ? Scalar(1e-6) : sqrt(dny / dnf) * Scalar(0.01);
        h = min(h, hmax_);
        xs_ = x_ + (dir_ * h) * k1_;
        evaluate(f, t_ + dir_ * h, xs_, k2_);
        if (!k2_.allFinite()) return dir_ * h;  // the trial steps will shrink it further if need be
        Scalar der2(0);
        for (Eigen::Index i = 0; i < n; ++i) {
            const Scalar sk = opts_.atol + opts_.rtol * abs(x_(i));
            der2 += ((k2_(i) - k1_(i)) / sk) * ((k2_(i) - k1_(i)) / sk);
        }
        der2 = sqrt(der2 / Scalar(n)) / h;
        const Scalar der12 = max(abs(der2), sqrt(dnf));
        const Scalar h1 = der12 <= Scalar(1e-15) ? max(Scalar(1e-6), h * Scalar(1e-3))
                                                 : pow(Scalar(0.01) / der12, Scalar(1) / Scalar(5));
        return dir_ * min(min(Scalar(100) * h, h1), hmax_);
    }

    /// One trial step of size h from (t_, x_) with k1_ = f(t_, x_); fills k2..k7 and x_new_ and returns
    /// the scaled error norm (NaN or inf when anything went non-finite).
    template <class System>
    Scalar attempt(System& f, const Scalar& h) {
        using std::abs;
        using std::max;
        using std::sqrt;
        const Scalar c2 = q(1, 5), c3 = q(3, 10), c4 = q(4, 5), c5 = q(8, 9);
        xs_ = x_ + h * (q(1, 5) * k1_);
        evaluate(f, t_ + c2 * h, xs_, k2_);
        xs_ = x_ + h * (q(3, 40) * k1_ + q(9, 40) * k2_);
        evaluate(f, t_ + c3 * h, xs_, k3_);
        xs_ = x_ + h * (q(44, 45) * k1_ - q(56, 15) * k2_ + q(32, 9) * k3_);
        evaluate(f, t_ + c4 * h, xs_, k4_);
        xs_ =
            x_ + h * (q(19372, 6561) * k1_ - q(25360, 2187) * k2_ + q(64448, 6561) * k3_ - q(212, 729) * k4_);
        evaluate(f, t_ + c5 * h, xs_, k5_);
        xs_ = x_ + h * (q(9017, 3168) * k1_ - q(355, 33) * k2_ + q(46732, 5247) * k3_ + q(49, 176) * k4_ -
                        q(5103, 18656) * k5_);
        evaluate(f, t_ + h, xs_, k6_);
        x_new_ = x_ + h * (q(35, 384) * k1_ + q(500, 1113) * k3_ + q(125, 192) * k4_ - q(2187, 6784) * k5_ +
                           q(11, 84) * k6_);
        evaluate(f, t_ + h, x_new_, k7_);
        if (!x_new_.allFinite() || !k7_.allFinite()) return std::numeric_limits<Scalar>::quiet_NaN();
        // x5 - x4 = h Σ e_i k_i
        xs_ = h * (q(71, 57600) * k1_ - q(71, 16695) * k3_ + q(71, 1920) * k4_ - q(17253, 339200) * k5_ +
                   q(22, 525) * k6_ - q(1, 40) * k7_);
        Scalar sum(0);
        for (Eigen::Index i = 0; i < x_.size(); ++i) {
            const Scalar sc = opts_.atol + opts_.rtol * max(abs(x_(i)), abs(x_new_(i)));
            sum += (xs_(i) / sc) * (xs_(i) / sc);
        }
        return sqrt(sum / Scalar(x_.size()));
    }

    /// Commits the trial step: dense-output coefficients, then (t, x, f) ← (t + h, x_new, k7).
    void accept(const Scalar& h, bool last) {
        r2_ = x_new_ - x_;
        r3_ = h * k1_ - r2_;
        r4_ = r2_ - h * k7_ - r3_;
        r5_ = h * (q(-12715105075LL, 11282082432LL) * k1_ + q(87487479700LL, 32700410799LL) * k3_ +
                   q(-10690763975LL, 1880347072LL) * k4_ + q(701980252875LL, 199316789632LL) * k5_ +
                   q(-1453857185LL, 822651844LL) * k6_ + q(69997945LL, 29380423LL) * k7_);
        t_prev_ = t_;
        x_prev_.swap(x_);
        x_.swap(x_new_);
        k1_.swap(k7_);  // first same as last
        t_ = last ? t_end_ : t_ + h;
        h_last_ = t_ - t_prev_;
        ++n_accepted_;
    }

    Options opts_;
    Scalar t_end_, t_, t_prev_;
    Scalar dir_ = Scalar(1), hmax_ = Scalar(0), h_ = Scalar(0), h_last_ = Scalar(0), errold_ = Scalar(1e-4);
    State x_, x_prev_, k1_, k2_, k3_, k4_, k5_, k6_, k7_, x_new_, xs_, r2_, r3_, r4_, r5_;
    bool rejected_last_ = false;
    std::size_t n_accepted_ = 0, n_rejected_ = 0, n_rhs_ = 0;
};

}  // namespace eomgen
