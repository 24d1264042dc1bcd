/** @file step_bounds.hpp  The bounds an adaptive stepper puts on each trial step: the number of steps, the
 * last step onto t_end, the smallest step. */
#pragma once

#include "eomgen/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace eomgen::detail {

/**
 * Run before each trial step of size h from (t, x) towards t_end (dir = ±1, the direction of integration):
 * throws TooManySteps once `attempted` (accepted + rejected steps) has reached max_steps; when the step would
 * reach t_end, or come within (reach − 1)·h of it, sets h = t_end − t and returns true (the last step, which
 * may be shorter than hmin); otherwise, when |h| < max(hmin, 16 ulp(t)), calls `underflow(that bound)`, which
 * must throw (it says why the steps shrank: the stepper knows). Returns false for an ordinary step.
 */
template <class Scalar, class State, class Underflow>
bool bound_trial_step(Scalar& h, const Scalar& t, const State& x, const Scalar& t_end, const Scalar& dir,
                      const Scalar& hmin, std::size_t attempted, std::size_t max_steps, Underflow&& underflow,
                      const Scalar& reach) {
    using std::abs;
    if (attempted >= max_steps)
        throw TooManySteps(
            describe_state("more than max_steps = " + std::to_string(max_steps) + " steps attempted", t, x),
            value_of(t));
    if ((t + reach * h - t_end) * dir >= Scalar(0)) {
        h = t_end - t;
        return true;
    }
    const Scalar ulp16 =
        Scalar(16) * abs(std::nextafter(t, dir * std::numeric_limits<Scalar>::infinity()) - t);
    const Scalar smallest = std::max(hmin, ulp16);
    if (abs(h) >= smallest) return false;
    underflow(smallest);
    throw std::logic_error("bound_trial_step: the underflow handler returned");
}

/**
 * As above, for the explicit steppers, whose only reasons to shrink a step are its error and non-finite
 * values: below the bound it throws NonFiniteState when the last trial failed on non-finite values
 * (`nonfinite`), StepSizeUnderflow else. Messages carry t and x.
 */
template <class Scalar, class State>
bool bound_trial_step(Scalar& h, const Scalar& t, const State& x, const Scalar& t_end, const Scalar& dir,
                      const Scalar& hmin, std::size_t attempted, std::size_t max_steps, bool nonfinite,
                      const Scalar& reach = Scalar(1.01)) {
    return bound_trial_step(
        h, t, x, t_end, dir, hmin, attempted, max_steps,
        [&](const Scalar& smallest) {
            std::ostringstream why;
            why << (nonfinite ? "right-hand side or state not finite for every step size down to "
                              : "step size fell below hmin = ")
                << value_of(smallest);
            if (nonfinite) throw NonFiniteState(describe_state(why.str(), t, x), value_of(t));
            throw StepSizeUnderflow(describe_state(why.str(), t, x), value_of(t));
        },
        reach);
}

}  // namespace eomgen::detail
