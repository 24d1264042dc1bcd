/** @file step_bounds.hpp  The bounds an adaptive stepper puts on each trial step: the number of steps, the
 * last step onto t_end, the smallest step. */
#pragma once

#include "eomgen/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>

namespace eomgen::detail {

/**
 * Run before each trial step of size h from (t, x) towards t_end (dir = ±1, the direction of integration):
 * throws TooManySteps once `attempted` (accepted + rejected steps) has reached max_steps; when the step would
 * reach t_end, or come within (reach − 1)·h of it, sets h = t_end − t and returns true (the last step, which
 * may be shorter than hmin); otherwise throws when |h| < max(hmin, 16 ulp(t)): NonFiniteState when the last
 * trial failed on non-finite values (`nonfinite`), StepSizeUnderflow else. Messages carry t and x.
 */
template <class Scalar, class State>
bool bound_trial_step(Scalar& h, const Scalar& t, const State& x, const Scalar& t_end, const Scalar& dir,
                      const Scalar& hmin, std::size_t attempted, std::size_t max_steps, bool nonfinite,
                      const Scalar& reach = Scalar(1.01)) {
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
    std::ostringstream why;
    why << (nonfinite ? "right-hand side or state not finite for every step size down to "
                      : "step size fell below hmin = ")
        << value_of(smallest);
    if (nonfinite) throw NonFiniteState(describe_state(why.str(), t, x), value_of(t));
    throw StepSizeUnderflow(describe_state(why.str(), t, x), value_of(t));
}

}  // namespace eomgen::detail
