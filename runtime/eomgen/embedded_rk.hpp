/** @file embedded_rk.hpp  What every adaptive embedded Runge–Kutta stepper shares: options, step-size
 * control, start. */
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
 * Settings of the adaptive embedded Runge–Kutta steppers (Dopri5, Dop853). Defaults are those of Hairer's
 * DOPRI5 code (HNW "Solving ODEs I", §II.4 and the appendix listing), except the tolerances; Dop853Options
 * has the same fields with DOP853's defaults.
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

namespace detail {

/**
 * The part of an adaptive embedded Runge–Kutta stepper that does not depend on its tableau (CRTP: Derived
 * is the stepper). Derived provides
 *   Scalar attempt(f, h)      one trial step of size h from (t_, x_) with k1_ = f(t_, x_): fills x_new_ and
 *                             f(t_ + h, x_new_) (its first-same-as-last stage), returns the scaled error
 *                             norm, NaN or inf when anything in the trial was not finite;
 *   void accept(h, last)      its dense-output coefficients, then commit(h, last, fsal).
 *
 * Step-size control (HNW I §II.4; the PI variant of Gustafsson, Hairer–Wanner "Solving ODEs II" §IV.2, as
 * in Hairer's DOPRI5 and DOP853 codes), for a method whose error estimate has order q:
 *   h_new = h · clamp( safety · err^(-(1/q - w β)) · err_prev^β, min_factor, max_factor ),
 * w = 0.75 (DOPRI5) or 0.2 (DOP853), with no growth right after a rejection. A trial step that produces NaN
 * or infinity is rejected and retried with h·min_factor, so a model undefined past some point is approached
 * rather than stepped over. The first step is Hairer's HINIT estimate from f(t0, x0) and one explicit Euler
 * step (HNW I §II.4, "Starting step size"), unless options.h0 is set. The step never passes t_end and the
 * last one lands on it exactly.
 *
 * Errors: NonFiniteState when x0 or f(t, x) at an accepted point is not finite, or when every trial step
 * down to hmin produced non-finite values; StepSizeUnderflow when the controller wants |h| below
 * max(hmin, 16 ulp(t)); TooManySteps after max_steps attempted steps. Messages carry t and the state.
 */
template <class Derived, class State>
class EmbeddedRk {
  public:
    using Scalar = typename State::Scalar;

    /// Takes one accepted step (rejected trials are retried internally). Call only while !done().
    template <class System>
    void step(System&& f) {
        using std::abs;
        using std::max;
        using std::min;
        using std::pow;
        if (done()) throw std::logic_error(std::string(name_) + "::step called after reaching t_end");
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
            const Scalar err = self().attempt(f, h);
            if (!(err <= std::numeric_limits<Scalar>::max())) {  // NaN or inf somewhere in the trial
                last_nonfinite = true;
                ++n_rejected_;
                h_ = h * opts_.min_factor;
                rejected_last_ = true;
                continue;
            }
            last_nonfinite = false;
            const Scalar fac11 = pow(err, expo1_);
            if (err <= one) {
                Scalar fac = fac11 / pow(errold_, opts_.beta);
                fac = max(one / opts_.max_factor, min(one / opts_.min_factor, fac / opts_.safety));
                Scalar h_new = h / fac;
                errold_ = max(err, Scalar(1e-4));
                self().accept(h, last);
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

  protected:
    /// Checks the options and x0, evaluates f(t0, x0) and picks the first step (one more evaluation).
    /// `order` is the order q of the error estimate, `beta_weight` the w above; `name` goes into messages.
    template <class System, class Options>
    EmbeddedRk(System& f, const Scalar& t0, const State& x0, const Scalar& t_end, const Options& options,
               const char* name, int order, const Scalar& beta_weight)
        : opts_(options),
          name_(name),
          t_end_(t_end),
          t_(t0),
          t_prev_(t0),
          x_(x0),
          x_prev_(x0),
          k1_(x0),
          x_new_(x0),
          xs_(x0) {
        using std::abs;
        // atol > 0: with a purely relative test a component passing through 0 would have no error scale.
        if (!(opts_.rtol >= Scalar(0)) || !(opts_.atol > Scalar(0)))
            throw std::invalid_argument(std::string(name_) + ": need rtol >= 0 and atol > 0");
        if (!(opts_.safety > Scalar(0)) || !(opts_.min_factor > Scalar(0)) ||
            !(opts_.min_factor < Scalar(1)) || !(opts_.max_factor > Scalar(1)))
            throw std::invalid_argument(std::string(name_) +
                                        ": need safety > 0 and 0 < min_factor < 1 < max_factor");
        expo1_ = Scalar(1) / Scalar(order) - opts_.beta * beta_weight;
        dir_ = t_end >= t0 ? Scalar(1) : Scalar(-1);
        hmax_ = opts_.hmax > Scalar(0) ? opts_.hmax : abs(t_end - t0);
        if (!x0.allFinite())
            throw NonFiniteState(describe_state("initial state is not finite", t0, x0), value_of(t0));
        if (t_end == t0) return;
        evaluate(f, t_, x_, k1_);
        if (!k1_.allFinite())
            throw NonFiniteState(describe_state("right-hand side is not finite", t_, x_), value_of(t_));
        h_ = opts_.h0 != Scalar(0) ? dir_ * std::min(abs(opts_.h0), hmax_) : initial_step(f, order);
    }

    template <class System>
    void evaluate(System& f, const Scalar& t, const State& x, State& xdot) {
        f(t, x, xdot);
        ++n_rhs_;
    }

    /// The scaled norm sqrt((1/n) Σ (e_i / sc_i)²), sc_i = atol + rtol·max(|x_i|, |x_new_i|), of an error e.
    template <class Vec>
    Scalar scaled_norm(const Vec& e) const {
        using std::sqrt;
        return sqrt(scaled_sum_of_squares(e) / Scalar(x_.size()));
    }
    /// Σ (e_i / sc_i)², the sum inside scaled_norm.
    template <class Vec>
    Scalar scaled_sum_of_squares(const Vec& e) const {
        using std::abs;
        using std::max;
        Scalar sum(0);
        for (Eigen::Index i = 0; i < x_.size(); ++i) {
            const Scalar sc = opts_.atol + opts_.rtol * max(abs(x_(i)), abs(x_new_(i)));
            sum += (e(i) / sc) * (e(i) / sc);
        }
        return sum;
    }

    /// The dense output where it is exact by construction: x at t == t() or t == t_prev(). Returns whether
    /// t was one of them.
    bool dense_at_node(const Scalar& t, State& x) const {
        if (t == t_)
            x = x_;
        else if (t == t_prev_)
            x = x_prev_;
        else
            return false;
        return true;
    }

    /// Commits the accepted trial step: (t, x, f) ← (t + h, x_new, fsal), the old point kept as t_prev,
    /// x_prev.
    void commit(const Scalar& h, bool last, State& fsal) {
        t_prev_ = t_;
        x_prev_.swap(x_);
        x_.swap(x_new_);
        k1_.swap(fsal);
        t_ = last ? t_end_ : t_ + h;
        h_last_ = t_ - t_prev_;
        ++n_accepted_;
    }

    Dopri5Options<Scalar> opts_;
    const char* name_;
    Scalar t_end_, t_, t_prev_;
    Scalar dir_ = Scalar(1), hmax_ = Scalar(0), h_ = Scalar(0), h_last_ = Scalar(0), errold_ = Scalar(1e-4);
    Scalar expo1_ = Scalar(0);
    State x_, x_prev_, k1_, x_new_, xs_;  ///< xs_: the stage argument, scratch for the derived stepper
    bool rejected_last_ = false;
    std::size_t n_accepted_ = 0, n_rejected_ = 0, n_rhs_ = 0;

  private:
    Derived& self() { return static_cast<Derived&>(*this); }

    /// Hairer's HINIT: h from ‖x0‖/‖f0‖, refined with the second derivative from one Euler step.
    template <class System>
    Scalar initial_step(System& f, int order) {
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
        State& f1 = x_new_;  // free until the first trial step
        evaluate(f, t_ + dir_ * h, xs_, f1);
        if (!f1.allFinite()) return dir_ * h;  // the trial steps will shrink it further if need be
        Scalar der2(0);
        for (Eigen::Index i = 0; i < n; ++i) {
            const Scalar sk = opts_.atol + opts_.rtol * abs(x_(i));
            der2 += ((f1(i) - k1_(i)) / sk) * ((f1(i) - k1_(i)) / sk);
        }
        der2 = sqrt(der2 / Scalar(n)) / h;
        const Scalar der12 = max(abs(der2), sqrt(dnf));
        const Scalar h1 = der12 <= Scalar(1e-15) ? max(Scalar(1e-6), h * Scalar(1e-3))
                                                 : pow(Scalar(0.01) / der12, Scalar(1) / Scalar(order));
        return dir_ * min(min(Scalar(100) * h, h1), hmax_);
    }
};

}  // namespace detail
}  // namespace eomgen
