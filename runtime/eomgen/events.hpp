/** @file events.hpp  Events g(t, x) = 0: their description, sign-change detection and root location. */
#pragma once

#include "eomgen/device.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace eomgen {

/// Which sign changes of g count: rising (g goes from < 0 to ≥ 0), falling (> 0 to ≤ 0), or both.
enum class EventDirection : int { Falling = -1, Both = 0, Rising = 1 };

/**
 * What the driver does at an event: stop the run there (terminal), record it and go on, or treat it as a
 * switching surface of f (a kink or a jump: the argument of abs, sign, max … in a model): the step that crossed it
 * is retaken to end at the crossing and the stepper restarts there, so that no step straddles it and the method
 * keeps its order. Switches are reported in IntegrationResult::switches. Steppers without restart() (rk4,
 * radau5) record them and go on (or stop there, where stop_at_switch says so, on the dense output).
 */
enum class EventAction { Stop, Record, Switch };

/**
 * An event: the time t* where g(t*, x(t*)) = 0 with the requested direction of crossing. `g` sees the
 * dense-output state, so it must be continuous in (t, x) for the location to be meaningful.
 */
template <class State>
struct Event {
    using Scalar = typename State::Scalar;
    std::string name;
    std::function<Scalar(const Scalar& t, const State& x)> g;
    EventDirection direction = EventDirection::Both;
    EventAction action = EventAction::Record;
    /// For a Switch event: asked at each crossing (t, x), true ends the run there as a terminal event — where the
    /// field on both sides pushes into the surface and the motion slides along it (sliding.hpp), which a caller
    /// integrates with another right-hand side. Empty: never.
    std::function<bool(const Scalar& t, const State& x)> stop_at_switch;
    /// For a Switch event: applied to the state where the steps restart at a crossing, by the steppers that end
    /// their steps there (restart()): the jump of the sensitivities by the saltation matrix (saltation.hpp). Empty:
    /// the state goes on as it is.
    std::function<void(const Scalar& t, State& x)> jump;
};

/// One located event: which one, when, and the (dense-output) state there.
template <class State>
struct EventHit {
    std::string name;
    typename State::Scalar t;
    State x;
};

/**
 * Whether g changed sign across a step, from g_start to g_end, in the given direction. A start value of
 * exactly 0 never counts: that root belongs to the previous step (or to t0), and counting it again would
 * report one crossing twice. An end value of exactly 0 does count. Two crossings within one step cancel
 * and are not seen; bound the step size (Dopri5Options::hmax) below the fastest oscillation of g.
 */
template <class Scalar>
EOMGEN_HD bool crosses(const Scalar& g_start, const Scalar& g_end, EventDirection direction) {
    const bool rising = g_start < Scalar(0) && g_end >= Scalar(0);
    const bool falling = g_start > Scalar(0) && g_end <= Scalar(0);
    switch (direction) {
        case EventDirection::Rising:
            return rising;
        case EventDirection::Falling:
            return falling;
        case EventDirection::Both:
            break;
    }
    return rising || falling;
}

/**
 * Brent's method (R. P. Brent, "Algorithms for Minimization without Derivatives", 1973, ch. 4; the
 * netlib `zeroin`): a root of the continuous g in the bracket [a, b] with g(a) = ga, g(b) = gb of
 * opposite signs (or one of them 0), by inverse quadratic interpolation, secant steps and bisection,
 * never leaving the bracket and converging at least as fast as bisection.
 *
 * It stops when the bracket is narrower than 2·(2 eps |t| + tol/2), i.e. a few ulp of t for tol of a
 * few ulp. It returns the bracket end on b's side of the root (where g has gb's sign, or is 0), so the
 * state returned for an event has already crossed: a terminal "hit the ground" event ends on or below
 * the ground, and a restart from there does not detect the same crossing again.
 */
template <class Scalar, class G>
EOMGEN_HD Scalar find_root_brent(G&& g, Scalar a, Scalar ga, Scalar b, Scalar gb, const Scalar& tol) {
    using std::abs;
    const Scalar eps = std::numeric_limits<Scalar>::epsilon();
    const Scalar zero(0), half(0.5), two(2), three(3);
    if (gb == zero) return b;
    if (ga == zero) return a;
    const bool gb_positive = gb > zero;  // the side the caller wants the answer on
    Scalar c = a, gc = ga, d = b - a, e = d;
    for (int iteration = 0; iteration < 400; ++iteration) {
        if ((gb > zero) == (gc > zero)) {  // keep the root between b and c
            c = a;
            gc = ga;
            d = b - a;
            e = d;
        }
        if (abs(gc) < abs(gb)) {  // b is the best estimate so far
            a = b;
            b = c;
            c = a;
            ga = gb;
            gb = gc;
            gc = ga;
        }
        const Scalar tol1 = two * eps * abs(b) + half * tol;
        const Scalar xm = half * (c - b);
        if (abs(xm) <= tol1 || gb == zero) break;
        if (abs(e) >= tol1 && abs(ga) > abs(gb)) {
            // Interpolate: secant when only two distinct points, inverse quadratic otherwise.
            Scalar p, qq;
            const Scalar s = gb / ga;
            if (a == c) {
                p = two * xm * s;
                qq = Scalar(1) - s;
            } else {
                const Scalar qa = ga / gc, r = gb / gc;
                p = s * (two * xm * qa * (qa - r) - (b - a) * (r - Scalar(1)));
                qq = (qa - Scalar(1)) * (r - Scalar(1)) * (s - Scalar(1));
            }
            if (p > zero)
                qq = -qq;
            else
                p = -p;
            if (two * p < std::min(three * xm * qq - abs(tol1 * qq), abs(e * qq))) {
                e = d;
                d = p / qq;
            } else {  // interpolation would leave the bracket or converge too slowly: bisect
                d = xm;
                e = d;
            }
        } else {
            d = xm;
            e = d;
        }
        a = b;
        ga = gb;
        b += abs(d) > tol1 ? d : (xm > zero ? tol1 : -tol1);
        gb = g(b);
    }
    if (gb == zero || (gb > zero) == gb_positive) return b;
    return c;
}

}  // namespace eomgen
