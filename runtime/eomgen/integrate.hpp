/** @file integrate.hpp  The integration driver: steps, events, samples at requested times, one result. */
#pragma once
/*
 * Reference (namespace eomgen). Scalar = typename State::Scalar; State an Eigen column vector;
 * f(const Scalar& t, const State& x, State& xdot) any callable.
 *
 *   integrate(f, t0, x0, t_end, options = {}, events = {}, sample_times = {}, observer = {})
 *       -> IntegrationResult<State>; adaptive Dormand–Prince 5(4) (dopri5.hpp), options a
 *       Dopri5Options<Scalar> {rtol, atol, h0, hmin, hmax, max_steps, safety, min_factor, max_factor, beta}.
 *   integrate_dop853(f, t0, x0, t_end, options = {}, events = {}, sample_times = {}, observer = {})
 *       -> IntegrationResult<State>; adaptive Dormand–Prince 8(5,3), Hairer's DOP853 (dop853.hpp), options a
 *       Dop853Options<Scalar> (the fields of Dopri5Options, DOP853's defaults).
 *   integrate_adams(f, t0, x0, t_end, options = {}, events = {}, sample_times = {}, observer = {})
 *       -> IntegrationResult<State>; variable-step, variable-order Adams–Bashforth–Moulton (Shampine & Gordon's
 *       STEP, adams.hpp), options an AdamsOptions<Scalar> {rtol, atol, h0, hmin, hmax, max_steps, max_order}.
 *   integrate_with<Method>(f, t0, x0, t_end, options = {}, ...)
 *       -> the same with any adaptive stepper template Method (Dopri5, Dop853, Adams), options
 * Method<State>::Options. integrate_rk4(f, t0, x0, t_end, dt, events = {}, sample_times = {}, observer = {})
 *       -> IntegrationResult<State>; classic RK4 on the fixed grid t0 + k·dt (rk4.hpp).
 *
 *   events:       std::vector<Event<State>>, Event{name, g(t, x) -> Scalar, direction, action} with
 *                 EventDirection::{Rising, Falling, Both} and EventAction::{Stop, Record}.
 *   sample_times: std::vector<Scalar>, ordered in the direction of integration, within [t0, t_end].
 *   observer:     Observer<State> = std::function<void(const Scalar& t, const State& x)>.
 *   result:       t, x (where it ended), accepted_steps, rejected_steps, rhs_evaluations,
 *                 events (EventHit{name, t, x}, in time order), samples (Sample{t, x}),
 *                 stop_reason (StopReason::ReachedEnd or TerminalEvent), stopped_by (terminal event's name).
 *
 * Samples come from the stepper's dense output, so they cost no extra steps and do not shorten the steps.
 * With an observer, each sample goes to observer(t, x) instead of result.samples (for streaming output);
 * with an observer and no sample_times, the observer sees t0 and the end of every accepted step.
 */

#include "eomgen/adams.hpp"
#include "eomgen/dop853.hpp"
#include "eomgen/dopri5.hpp"
#include "eomgen/errors.hpp"
#include "eomgen/events.hpp"
#include "eomgen/rk4.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace eomgen {

/// Why a run ended.
enum class StopReason { ReachedEnd, TerminalEvent };

/// The state at a requested time.
template <class State>
struct Sample {
    typename State::Scalar t;
    State x;
};

/// Called with (t, x) for each sample, or for each accepted step when no sample times are given.
template <class State>
using Observer = std::function<void(const typename State::Scalar& t, const State& x)>;

/// Everything a run produced.
template <class State>
struct IntegrationResult {
    using Scalar = typename State::Scalar;
    Scalar t;  ///< where the run ended: t_end, or the terminal event's time
    State x;   ///< the state there
    std::size_t accepted_steps = 0;
    std::size_t rejected_steps = 0;
    std::size_t rhs_evaluations = 0;      ///< calls of f, including start-up and rejected trials
    std::vector<EventHit<State>> events;  ///< located events, in time order, up to the end of the run
    std::vector<EventHit<State>> switches;  ///< where f switched (EventAction::Switch), in time order
    std::vector<Sample<State>> samples;   ///< at the requested times up to the end (empty with an observer)
    StopReason stop_reason = StopReason::ReachedEnd;
    std::string stopped_by;  ///< the terminal event's name; empty when t_end was reached
};

namespace detail {

/// Keeps a parameter out of template argument deduction, so a lambda converts to the Observer.
template <class T>
struct NonDeduced {
    using type = T;
};

/// Steppers whose dense output needs extra evaluations of f (Dop853) have prepare_dense(f); the others not.
template <class Stepper, class System, class = void>
struct HasPrepareDense : std::false_type {};
template <class Stepper, class System>
struct HasPrepareDense<Stepper, System,
                       std::void_t<decltype(std::declval<Stepper&>().prepare_dense(std::declval<System&>()))>>
    : std::true_type {};

/// Steppers that can start afresh at a point and end their steps early (restart(f, t, x, h), set_end(t)): those
/// that honour EventAction::Switch.
template <class Stepper, class System, class State, class = void>
struct HasRestart : std::false_type {};
template <class Stepper, class System, class State>
struct HasRestart<Stepper, System, State,
                  std::void_t<decltype(std::declval<Stepper&>().restart(std::declval<System&>(),
                                                                        std::declval<typename State::Scalar>(),
                                                                        std::declval<const State&>())),
                              decltype(std::declval<Stepper&>().set_end(std::declval<typename State::Scalar>()))>>
    : std::true_type {};

/**
 * The loop shared by the integrators, over any stepper with step(f), done(), t(), x(), t_prev(),
 * dense(t, x) and the counters, and optionally prepare_dense(f), called on the steps where an event or a
 * sample needs the dense output inside the step. After each accepted step [ta, tb]: every event whose g
 * changed sign in its direction is located on the dense output by Brent's method to a few ulp of t; the
 * earliest terminal one (ties: the first declared) cuts the step at t_stop; hits and samples up to t_stop are
 * reported.
 */
template <class Stepper, class System, class State>
IntegrationResult<State> drive(Stepper& stepper, System& f, const typename State::Scalar& t0, const State& x0,
                               const typename State::Scalar& t_end, const std::vector<Event<State>>& events,
                               const std::vector<typename State::Scalar>& sample_times,
                               const Observer<State>& observer) {
    using Scalar = typename State::Scalar;
    using std::abs;
    using std::max;
    const Scalar dir = t_end >= t0 ? Scalar(1) : Scalar(-1);
    // "a is at or before b" in the direction of integration
    const auto not_after = [dir](const Scalar& a, const Scalar& b) { return (a - b) * dir <= Scalar(0); };

    for (std::size_t i = 0; i < sample_times.size(); ++i) {
        const Scalar& s = sample_times[i];
        if (!not_after(t0, s) || !not_after(s, t_end) || (i > 0 && !not_after(sample_times[i - 1], s)))
            throw std::invalid_argument(
                "integrate: sample times must lie in [t0, t_end] and be ordered in the direction of "
                "integration");
    }
    for (const auto& event : events)
        if (!event.g) throw std::invalid_argument("integrate: event '" + event.name + "' has no function g");

    IntegrationResult<State> result;
    result.t = t0;
    result.x = x0;
    const bool per_step = sample_times.empty() && observer;
    const auto emit = [&](const Scalar& t, const State& x) {
        if (observer)
            observer(t, x);
        else
            result.samples.push_back({t, x});
    };
    const auto evaluate_g = [&](const Event<State>& event, const Scalar& t, const State& x) {
        const Scalar value = event.g(t, x);
        if (!std::isfinite(value))
            throw NonFiniteState(describe_state("event '" + event.name + "' function is not finite", t, x),
                                 value_of(t));
        return value;
    };

    std::size_t next_sample = 0;
    while (next_sample < sample_times.size() && sample_times[next_sample] == t0) emit(t0, x0), ++next_sample;
    if (per_step) observer(t0, x0);

    std::vector<Scalar> g_prev(events.size()), g_now(events.size());
    for (std::size_t i = 0; i < events.size(); ++i) g_prev[i] = evaluate_g(events[i], t0, x0);

    struct Crossing {
        std::size_t index;
        Scalar t;
    };
    std::vector<Crossing> crossings;
    State x_tmp = x0;
    const Scalar eps = std::numeric_limits<Scalar>::epsilon();

    constexpr bool can_switch = HasRestart<Stepper, System, State>::value;
    constexpr std::size_t none = static_cast<std::size_t>(-1);
    std::size_t switching = none;  // the Switch event whose crossing the steps now end at
    Scalar t_switch(0), h_switch(0);

    for (;;) {
        if (stepper.done()) {
            if constexpr (can_switch) {
                if (switching != none) {
                    State xs = stepper.x();
                    if (events[switching].jump) events[switching].jump(t_switch, xs);
                    // At the crossing: on afresh, with the step size the crossing step had.
                    stepper.set_end(t_end);
                    stepper.restart(f, t_switch, xs, h_switch);
                    result.switches.push_back({events[switching].name, t_switch, xs});
                    if (events[switching].stop_at_switch && events[switching].stop_at_switch(t_switch, xs)) {
                        result.t = t_switch;
                        result.x = xs;
                        result.stop_reason = StopReason::TerminalEvent;
                        result.stopped_by = events[switching].name;
                        break;
                    }
                    for (std::size_t i = 0; i < events.size(); ++i) g_prev[i] = evaluate_g(events[i], t_switch, xs);
                    g_prev[switching] = Scalar(0);  // crossed here: a start value of 0 never counts again
                    switching = none;
                    continue;
                }
            }
            break;
        }
        stepper.step(f);
        const Scalar ta = stepper.t_prev(), tb = stepper.t();

        // (dense() at tb itself is exact without it)
        bool need_dense = next_sample < sample_times.size() && not_after(sample_times[next_sample], tb) &&
                          sample_times[next_sample] != tb;
        for (std::size_t i = 0; i < events.size(); ++i) {
            g_now[i] = evaluate_g(events[i], tb, stepper.x());
            need_dense = need_dense || crosses(g_prev[i], g_now[i], events[i].direction);
        }
        if constexpr (HasPrepareDense<Stepper, System>::value)
            if (need_dense) stepper.prepare_dense(f);
        crossings.clear();
        for (std::size_t i = 0; i < events.size(); ++i) {
            if (!crosses(g_prev[i], g_now[i], events[i].direction)) continue;
            // While the steps end at one switch, the others wait: each is met after the restart there.
            if (can_switch && switching != none && events[i].action == EventAction::Switch) continue;
            const auto g_dense = [&](const Scalar& s) {
                stepper.dense(s, x_tmp);
                return events[i].g(s, x_tmp);
            };
            const Scalar tol = Scalar(2) * eps * max(abs(ta), abs(tb));
            crossings.push_back({i, find_root_brent(g_dense, ta, g_prev[i], tb, g_now[i], tol)});
        }
        std::stable_sort(crossings.begin(), crossings.end(), [dir](const Crossing& a, const Crossing& b) {
            return (a.t - b.t) * dir < Scalar(0);
        });

        // Arriving at a surface that holds the motion (sliding: sticking friction), the steps shrink and their ends
        // never cross it, because the field beyond pushes back: no crossing is ever seen. Where a step brings a
        // Switch event's g towards 0 fast enough to cross within one more such step, and the surface holds the
        // motion at the step's end (stop_at_switch: true only within round-off of it), the run ends there.
        std::size_t held = none;
        for (std::size_t i = 0; i < events.size() && crossings.empty() && held == none; ++i)
            if (events[i].action == EventAction::Switch && events[i].stop_at_switch && g_now[i] != Scalar(0) &&
                (g_now[i] > Scalar(0)) == (g_prev[i] > Scalar(0)) && abs(g_now[i]) < abs(g_prev[i]) &&
                abs(g_now[i]) <= abs(g_now[i] - g_prev[i]) && events[i].stop_at_switch(tb, stepper.x()))
                held = i;
        if (held != none) {
            for (; next_sample < sample_times.size() && not_after(sample_times[next_sample], tb); ++next_sample) {
                stepper.dense(sample_times[next_sample], x_tmp);
                emit(sample_times[next_sample], x_tmp);
            }
            if (per_step) observer(tb, stepper.x());
            if constexpr (can_switch) {
                // The rest of the way, on the side the motion is on: steps from tb that end where g, extrapolated
                // linearly (it is within round-off of 0), reaches 0; the switch there ends the run as above.
                const Scalar tc = tb + (tb - ta) * g_now[held] / (g_prev[held] - g_now[held]);
                if ((tc - tb) * dir > Scalar(0) && not_after(tc, t_end)) {
                    const State xb = stepper.x();
                    stepper.restart(f, tb, xb, tb - ta);
                    stepper.set_end(tc);
                    switching = held;
                    t_switch = tc;
                    h_switch = tb - ta;
                    std::swap(g_prev, g_now);
                    continue;
                }
            }
            result.switches.push_back({events[held].name, tb, stepper.x()});
            result.t = tb;
            result.x = stepper.x();
            result.stop_reason = StopReason::TerminalEvent;
            result.stopped_by = events[held].name;
            break;
        }

        if constexpr (can_switch) {
            if (!crossings.empty() && events[crossings.front().index].action == EventAction::Switch &&
                crossings.front().t != ta) {
                // f switches inside this step: retake it from ta, to end at the crossing. The crossing was
                // located on the step's dense output, which is less accurate than the steps: first, without
                // reporting anything, secant steps on the retaken trajectory (a smooth function of where it
                // ends) until g is round-off there, or just across, within [ta, tb].
                const std::size_t k = crossings.front().index;
                const State xa = stepper.x_prev();
                const Scalar ga = g_prev[k], h0 = tb - ta;
                Scalar tc = crossings.front().t, t_last = ta, g_last = ga;
                for (int refinement = 0; refinement < 8; ++refinement) {
                    stepper.restart(f, ta, xa, h0);
                    stepper.set_end(tc);
                    while (!stepper.done()) stepper.step(f);
                    const Scalar gc = evaluate_g(events[k], tc, stepper.x());
                    const bool across = gc == Scalar(0) || (gc > Scalar(0)) != (ga > Scalar(0));
                    if ((across && abs(gc) <= Scalar(64) * eps * max(abs(ga), abs(g_now[k]))) || gc == g_last) break;
                    Scalar t_next = tc - gc * (tc - t_last) / (gc - g_last);
                    const Scalar lo = ta + (tb - ta) * Scalar(1e-3);
                    if (!((t_next - lo) * dir > Scalar(0))) t_next = lo;
                    if ((t_next - tb) * dir > Scalar(0)) t_next = tb;
                    if (t_next == tc) break;
                    t_last = tc;
                    g_last = gc;
                    tc = t_next;
                }
                switching = k;
                t_switch = tc;
                h_switch = h0;
                stepper.restart(f, ta, xa, h0);
                stepper.set_end(t_switch);
                continue;  // g_prev keeps the values at ta
            }
        }

        Scalar t_stop = tb;
        const Crossing* terminal = nullptr;
        for (const auto& c : crossings) {
            bool stop = events[c.index].action == EventAction::Stop;
            // A switch that ends the run (Event::stop_at_switch), asked on the dense output where the steps do not
            // end at switches (without restart()); the others asked it where they ended their steps, above.
            if (!can_switch && events[c.index].action == EventAction::Switch && events[c.index].stop_at_switch) {
                stepper.dense(c.t, x_tmp);
                stop = events[c.index].stop_at_switch(c.t, x_tmp);
            }
            if (stop) {
                terminal = &c;
                t_stop = c.t;
                break;
            }
        }
        for (const auto& c : crossings) {
            if (!not_after(c.t, t_stop)) break;
            stepper.dense(c.t, x_tmp);
            (events[c.index].action == EventAction::Switch ? result.switches : result.events)
                .push_back({events[c.index].name, c.t, x_tmp});
        }
        for (; next_sample < sample_times.size() && not_after(sample_times[next_sample], t_stop);
             ++next_sample) {
            stepper.dense(sample_times[next_sample], x_tmp);
            emit(sample_times[next_sample], x_tmp);
        }
        if (terminal) {
            stepper.dense(t_stop, x_tmp);
            if (per_step) observer(t_stop, x_tmp);
            result.t = t_stop;
            result.x = x_tmp;
            result.stop_reason = StopReason::TerminalEvent;
            result.stopped_by = events[terminal->index].name;
            break;
        }
        if (per_step) observer(tb, stepper.x());
        std::swap(g_prev, g_now);
    }
    if (result.stop_reason == StopReason::ReachedEnd) {
        result.t = stepper.t();
        result.x = stepper.x();
    }
    result.accepted_steps = stepper.accepted_steps();
    result.rejected_steps = stepper.rejected_steps();
    result.rhs_evaluations = stepper.rhs_evaluations();
    return result;
}

}  // namespace detail

/**
 * As integrate(), with the adaptive stepper Method<State> (Dopri5, Dop853, Adams: any class with the steppers'
 * interface, constructed from (f, t0, x0, t_end, options)); what integrate_constrained and the simulation
 * driver use to take the method as a template argument.
 */
template <template <class> class Method, class System, class State>
IntegrationResult<State> integrate_with(
    System&& f, const typename State::Scalar& t0, const State& x0, const typename State::Scalar& t_end,
    const typename detail::NonDeduced<typename Method<State>::Options>::type& options = {},
    const std::vector<Event<State>>& events = {},
    const std::vector<typename State::Scalar>& sample_times = {},
    const typename detail::NonDeduced<Observer<State>>::type& observer = {}) {
    Method<State> stepper(f, t0, x0, t_end, options);
    return detail::drive(stepper, f, t0, x0, t_end, events, sample_times, observer);
}

/**
 * Integrates x' = f(t, x) from (t0, x0) to t_end (t_end < t0 runs backwards) with adaptive Dormand–Prince
 * 5(4) (see Dopri5 for the error control, the dense output and the errors thrown), locating `events` and
 * sampling the dense output at `sample_times` (ordered, within [t0, t_end]; those after a terminal event
 * are not produced). See the reference at the top of this file.
 */
template <class System, class State>
IntegrationResult<State> integrate(System&& f, const typename State::Scalar& t0, const State& x0,
                                   const typename State::Scalar& t_end,
                                   const Dopri5Options<typename State::Scalar>& options = {},
                                   const std::vector<Event<State>>& events = {},
                                   const std::vector<typename State::Scalar>& sample_times = {},
                                   const typename detail::NonDeduced<Observer<State>>::type& observer = {}) {
    return integrate_with<Dopri5>(f, t0, x0, t_end, options, events, sample_times, observer);
}

/**
 * As integrate(), with Hairer's DOP853 (8th order; see Dop853): the cheaper choice at tight tolerances.
 * Its dense output costs three evaluations of f on each step where an event or a sample falls.
 */
template <class System, class State>
IntegrationResult<State> integrate_dop853(
    System&& f, const typename State::Scalar& t0, const State& x0, const typename State::Scalar& t_end,
    const Dop853Options<typename State::Scalar>& options = {}, const std::vector<Event<State>>& events = {},
    const std::vector<typename State::Scalar>& sample_times = {},
    const typename detail::NonDeduced<Observer<State>>::type& observer = {}) {
    return integrate_with<Dop853>(f, t0, x0, t_end, options, events, sample_times, observer);
}

/**
 * As integrate(), with variable-step, variable-order Adams–Bashforth–Moulton (orders 1 … 12; see Adams): the
 * fewest evaluations of f on smooth problems at tight tolerances (2 per step). Its dense output, the step's
 * interpolating polynomial, is free.
 */
template <class System, class State>
IntegrationResult<State> integrate_adams(
    System&& f, const typename State::Scalar& t0, const State& x0, const typename State::Scalar& t_end,
    const AdamsOptions<typename State::Scalar>& options = {}, const std::vector<Event<State>>& events = {},
    const std::vector<typename State::Scalar>& sample_times = {},
    const typename detail::NonDeduced<Observer<State>>::type& observer = {}) {
    return integrate_with<Adams>(f, t0, x0, t_end, options, events, sample_times, observer);
}

/**
 * As integrate(), with classic RK4 on the fixed grid t0 + k·dt (the last step shortened to end at t_end;
 * see Rk4Stepper). Events and samples use RK4's cubic Hermite dense output. Throws NonFiniteState when
 * the state or f becomes NaN or infinite.
 */
template <class System, class State>
IntegrationResult<State> integrate_rk4(
    System&& f, const typename State::Scalar& t0, const State& x0, const typename State::Scalar& t_end,
    const typename State::Scalar& dt, const std::vector<Event<State>>& events = {},
    const std::vector<typename State::Scalar>& sample_times = {},
    const typename detail::NonDeduced<Observer<State>>::type& observer = {}) {
    Rk4Stepper<State> stepper(f, t0, x0, t_end, dt);
    return detail::drive(stepper, f, t0, x0, t_end, events, sample_times, observer);
}

}  // namespace eomgen
