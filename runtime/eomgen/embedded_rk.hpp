/** @file embedded_rk.hpp  What every adaptive embedded Runge–Kutta stepper shares: options, step-size
 * control, start. */
#pragma once

#include "eomgen/device.hpp"
#include "eomgen/errors.hpp"
#include "eomgen/step_bounds.hpp"

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
    /// The leading components the error norm counts; 0: all. Sensitivities (sensitivities.hpp) set it to the state's
    /// size to leave S out of the step-size control (CVODES's errconS = false).
    std::size_t error_components = 0;
};

namespace detail {

/// Whether every component of v is finite (the loop form, which also compiles as device code).
template <class Vec>
EOMGEN_HD bool all_finite(const Vec& v) {
    for (Eigen::Index i = 0; i < v.size(); ++i)
        if (!(v(i) - v(i) == 0)) return false;  // NaN or infinite
    return true;
}

/// Σ (e_i / sc_i)², sc_i = atol + rtol·max(|x_i|, |x_new_i|): the error norm of the embedded pairs, squared
/// and not yet divided by n.
template <class Vec, class State>
EOMGEN_HD typename State::Scalar scaled_sum_of_squares(const Vec& e, const State& x, const State& x_new,
                                                       const typename State::Scalar& atol,
                                                       const typename State::Scalar& rtol,
                                                       Eigen::Index count = -1) {
    using Scalar = typename State::Scalar;
    using std::abs;
    Scalar sum(0);
    const Eigen::Index n = count < 0 ? x.size() : count;
    for (Eigen::Index i = 0; i < n; ++i) {
        const Scalar a = abs(x(i)), b = abs(x_new(i));
        const Scalar sc = atol + rtol * (a < b ? b : a);
        sum += (e(i) / sc) * (e(i) / sc);
    }
    return sum;
}

/**
 * Hairer's HINIT (HNW I §II.4, "Starting step size"): the first step of a method of order `order` from (t, x)
 * with k1 = f(t, x), from ‖x‖/‖k1‖, refined with the second derivative from one explicit Euler step (one call
 * of eval(t, x, k), into f1; xs is scratch). Signed by dir, at most hmax.
 */
template <class Eval, class State>
EOMGEN_HD typename State::Scalar initial_step_size(Eval& eval, const typename State::Scalar& t, const State& x,
                                                   const State& k1, const typename State::Scalar& dir,
                                                   const typename State::Scalar& hmax,
                                                   const typename State::Scalar& atol,
                                                   const typename State::Scalar& rtol, int order, State& xs,
                                                   State& f1) {
    using Scalar = typename State::Scalar;
    using std::abs;
    using std::pow;
    using std::sqrt;
    const auto smaller = [](const Scalar& a, const Scalar& b) { return b < a ? b : a; };
    const auto larger = [](const Scalar& a, const Scalar& b) { return a < b ? b : a; };
    const Eigen::Index n = x.size();
    Scalar dnf(0), dny(0);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Scalar sk = atol + rtol * abs(x(i));
        dnf += (k1(i) / sk) * (k1(i) / sk);
        dny += (x(i) / sk) * (x(i) / sk);
    }
    dnf /= Scalar(n);
    dny /= Scalar(n);
    Scalar h = (dnf <= Scalar(1e-10) || dny <= Scalar(1e-10)) ? Scalar(1e-6) : sqrt(dny / dnf) * Scalar(0.01);
    h = smaller(h, hmax);
    xs = x + (dir * h) * k1;
    eval(t + dir * h, xs, f1);
    if (!all_finite(f1)) return dir * h;  // the trial steps will shrink it further if need be
    Scalar der2(0);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Scalar sk = atol + rtol * abs(x(i));
        der2 += ((f1(i) - k1(i)) / sk) * ((f1(i) - k1(i)) / sk);
    }
    der2 = sqrt(der2 / Scalar(n)) / h;
    const Scalar der12 = larger(abs(der2), sqrt(dnf));
    const Scalar h1 = der12 <= Scalar(1e-15) ? larger(Scalar(1e-6), h * Scalar(1e-3))
                                             : pow(Scalar(0.01) / der12, Scalar(1) / Scalar(order));
    return dir * smaller(smaller(Scalar(100) * h, h1), hmax);
}

/**
 * The step-size controller of the embedded pairs (HNW I §II.4; the PI variant of Gustafsson, Hairer–Wanner
 * II §IV.2, as in Hairer's DOPRI5 and DOP853 codes), for an error estimate of order q:
 *   h_new = h · clamp( safety · err^(-(1/q - w β)) · err_prev^β, min_factor, max_factor ),
 * with no growth right after a rejection. Shared by EmbeddedRk and the device member integrator.
 */
template <class Scalar>
struct StepSizeControl {
    Scalar safety, min_factor, max_factor, beta;
    Scalar expo1;  ///< 1/q − w β
    Scalar errold = Scalar(1e-4);
    bool rejected_last = false;

    EOMGEN_HD StepSizeControl(const Scalar& safety_, const Scalar& min_factor_, const Scalar& max_factor_,
                              const Scalar& beta_, int order, const Scalar& beta_weight)
        : safety(safety_),
          min_factor(min_factor_),
          max_factor(max_factor_),
          beta(beta_),
          expo1(Scalar(1) / Scalar(order) - beta_ * beta_weight) {}

    /// The next step after a trial step of size h with scaled error err: accepted (err ≤ 1) or the size to
    /// retry with. |h_new| stays within hmax (signed by dir).
    EOMGEN_HD Scalar next(const Scalar& err, const Scalar& h, const Scalar& hmax, const Scalar& dir) {
        using std::abs;
        using std::pow;
        const Scalar one(1);
        const auto smaller = [](const Scalar& a, const Scalar& b) { return b < a ? b : a; };
        const auto larger = [](const Scalar& a, const Scalar& b) { return a < b ? b : a; };
        const Scalar fac11 = pow(err, expo1);
        if (err <= one) {
            Scalar fac = fac11 / pow(errold, beta);
            fac = larger(one / max_factor, smaller(one / min_factor, fac / safety));
            Scalar h_new = h / fac;
            errold = larger(err, Scalar(1e-4));
            if (abs(h_new) > hmax) h_new = dir * hmax;
            if (rejected_last && abs(h_new) > abs(h)) h_new = h;
            rejected_last = false;
            return h_new;
        }
        rejected_last = true;
        return h / smaller(one / min_factor, fac11 / safety);
    }

    /// The size to retry with after a trial step of size h that produced NaN or infinity.
    EOMGEN_HD Scalar after_non_finite(const Scalar& h) {
        rejected_last = true;
        return h * min_factor;
    }
};

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
        if (done()) throw std::logic_error(std::string(name_) + "::step called after reaching t_end");
        const Scalar one(1);
        bool last_nonfinite = false;
        for (;;) {
            const bool last = detail::bound_trial_step(h_, t_, x_, t_end_, dir_, opts_.hmin,
                                                       n_accepted_ + n_rejected_, opts_.max_steps, last_nonfinite);
            const Scalar h = h_;
            const Scalar err = self().attempt(f, h);
            if (!(err <= std::numeric_limits<Scalar>::max())) {  // NaN or inf somewhere in the trial
                last_nonfinite = true;
                ++n_rejected_;
                h_ = control_.after_non_finite(h);
                continue;
            }
            last_nonfinite = false;
            h_ = control_.next(err, h, hmax_, dir_);
            if (err <= one) {
                self().accept(h, last);
                return;
            }
            ++n_rejected_;
        }
    }

    bool done() const { return t_ == t_end_; }

    /// Starts afresh at (t, x): f is evaluated there (no first-same-as-last stage carried across a switch of f)
    /// and the next trial step is h (0: the one the controller chose). The driver's move at a switching surface
    /// (EventAction::Switch): back to the start of the step that crossed it, and on from the crossing.
    template <class System>
    void restart(System&& f, const Scalar& t, const State& x, const Scalar& h = Scalar(0)) {
        t_ = t;
        t_prev_ = t;
        x_ = x;
        x_prev_ = x;
        evaluate(f, t_, x_, k1_);
        if (!k1_.allFinite())
            throw NonFiniteState(describe_state("right-hand side is not finite", t_, x_), value_of(t_));
        if (h != Scalar(0)) h_ = h;
    }
    /// Where the steps end: t_end, or for a while a switch's time before it (the last step lands on it exactly).
    void set_end(const Scalar& t) { t_end_ = t; }

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
          xs_(x0),
          control_(options.safety, options.min_factor, options.max_factor, options.beta, order, beta_weight) {
        using std::abs;
        // atol > 0: with a purely relative test a component passing through 0 would have no error scale.
        if (!(opts_.rtol >= Scalar(0)) || !(opts_.atol > Scalar(0)))
            throw std::invalid_argument(std::string(name_) + ": need rtol >= 0 and atol > 0");
        if (!(opts_.safety > Scalar(0)) || !(opts_.min_factor > Scalar(0)) ||
            !(opts_.min_factor < Scalar(1)) || !(opts_.max_factor > Scalar(1)))
            throw std::invalid_argument(std::string(name_) +
                                        ": need safety > 0 and 0 < min_factor < 1 < max_factor");
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

    /// The scaled norm sqrt((1/n) Σ (e_i / sc_i)²), sc_i = atol + rtol·max(|x_i|, |x_new_i|), of an error e, over
    /// the first n = error_count() components.
    template <class Vec>
    Scalar scaled_norm(const Vec& e) const {
        using std::sqrt;
        return sqrt(scaled_sum_of_squares(e) / Scalar(error_count()));
    }
    /// Σ (e_i / sc_i)², the sum inside scaled_norm.
    template <class Vec>
    Scalar scaled_sum_of_squares(const Vec& e) const {
        return detail::scaled_sum_of_squares(e, x_, x_new_, opts_.atol, opts_.rtol, error_count());
    }
    /// How many leading components the error norm counts (Options::error_components; all when 0 or too many).
    Eigen::Index error_count() const {
        const Eigen::Index m = Eigen::Index(opts_.error_components);
        return m > 0 && m < x_.size() ? m : x_.size();
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
    Scalar dir_ = Scalar(1), hmax_ = Scalar(0), h_ = Scalar(0), h_last_ = Scalar(0);
    State x_, x_prev_, k1_, x_new_, xs_;  ///< xs_: the stage argument, scratch for the derived stepper
    StepSizeControl<Scalar> control_;
    std::size_t n_accepted_ = 0, n_rejected_ = 0, n_rhs_ = 0;

  private:
    Derived& self() { return static_cast<Derived&>(*this); }

    /// Hairer's HINIT (initial_step_size above); one evaluation of f.
    template <class System>
    Scalar initial_step(System& f, int order) {
        auto eval = [&](const Scalar& t, const State& x, State& xdot) { evaluate(f, t, x, xdot); };
        State& f1 = x_new_;  // free until the first trial step
        return initial_step_size(eval, t_, x_, k1_, dir_, hmax_, opts_.atol, opts_.rtol, order, xs_, f1);
    }
};

}  // namespace detail
}  // namespace eomgen
