/**
 * @file sliding.hpp  Sliding along a switching surface (Filippov): what a jump of f does when both sides push into
 * the surface, as Coulomb friction holds a block to a belt (sticking).
 *
 * f(t, x) jumps across s(t, x) = 0 (sign(s) in the model). With f⁻ and f⁺ the fields on either side at a point of
 * the surface and ṡ± = ∇s·f± + ∂s/∂t, the motion crosses where ṡ⁻ and ṡ⁺ have one sign, and slides where ṡ⁻ > 0 > ṡ⁺:
 * then it follows the convex combination that keeps s = 0 (A. F. Filippov, "Differential Equations with
 * Discontinuous Righthand Sides", 1988, §2.4),
 *
 *     f_s = α f⁺ + (1 − α) f⁻,   α = ṡ⁻ / (ṡ⁻ − ṡ⁺) ∈ (0, 1),
 *
 * until ṡ⁺ rises to 0 (it leaves into s > 0) or ṡ⁻ falls to 0 (into s < 0). For Coulomb friction with
 * s = v_belt − ẋ, α sets the friction the contact needs, and the exit is where that exceeds its bound.
 *
 * The model computes sign(s) from the state, so the one-sided fields are read just off the surface, at
 * x ± δ n and x ± 2δ n with n = ∇s/|∇s|² (s moves by ±δ, ±2δ) and extrapolated to the surface,
 * f±(x) ≈ 2 f(x ± δ n) − f(x ± 2δ n), which leaves an error O(δ²) where f is smooth on each side; ∇s by central
 * differences. Four evaluations of f per evaluation of f_s.
 */
#pragma once

#include "eomgen/events.hpp"
#include "eomgen/integrate.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace eomgen {

/// One switching surface s of a right-hand side f, with what sliding along it needs.
template <class State>
class SlidingSurface {
  public:
    using Scalar = typename State::Scalar;
    using Field = std::function<void(const Scalar& t, const State& x, State& xdot)>;
    using Surface = std::function<Scalar(const Scalar& t, const State& x)>;

    SlidingSurface(Field f, Surface s) : f_(std::move(f)), s_(std::move(s)) {}

    /// The fields on either side at (t, x), f⁻ and f⁺, and ṡ on either side.
    struct Sides {
        State minus, plus;
        Scalar sdot_minus, sdot_plus;
    };

    Sides sides(const Scalar& t, const State& x) const {
        using std::abs;
        using std::sqrt;
        const Scalar eps = std::numeric_limits<Scalar>::epsilon();
        // ∇s and ∂s/∂t by central differences.
        State grad = x;
        State y = x;
        for (Eigen::Index i = 0; i < x.size(); ++i) {
            const Scalar h = sqrt(eps) * (Scalar(1) + abs(x(i)));
            y(i) = x(i) + h;
            const Scalar up = s_(t, y);
            y(i) = x(i) - h;
            const Scalar down = s_(t, y);
            y(i) = x(i);
            grad(i) = (up - down) / (Scalar(2) * h);
        }
        const Scalar ht = sqrt(eps) * (Scalar(1) + abs(t));
        const Scalar dsdt = (s_(t + ht, x) - s_(t - ht, x)) / (Scalar(2) * ht);
        const Scalar norm2 = grad.squaredNorm();
        Sides out{x, x, Scalar(0), Scalar(0)};
        if (!(norm2 > Scalar(0))) return out;
        const State n = grad / norm2;
        const Scalar delta = sqrt(eps) * (Scalar(1) + x.cwiseAbs().maxCoeff() * sqrt(norm2));
        State a = x, b = x;
        for (int side = -1; side <= 1; side += 2) {
            f_(t, x + Scalar(side) * delta * n, a);
            f_(t, x + Scalar(2 * side) * delta * n, b);
            State& g = side < 0 ? out.minus : out.plus;
            g = Scalar(2) * a - b;
            (side < 0 ? out.sdot_minus : out.sdot_plus) = grad.dot(g) + dsdt;
        }
        return out;
    }

    /// Whether the motion slides at (t, x): both sides push into the surface by more than round-off.
    bool attracting(const Scalar& t, const State& x) const {
        using std::abs;
        const Sides s = sides(t, x);
        const Scalar margin = Scalar(1e-9) * (abs(s.sdot_minus) + abs(s.sdot_plus));
        return s.sdot_minus > margin && s.sdot_plus < -margin;
    }

    /// Filippov's field f_s at (t, x) (see the file comment).
    void sliding_field(const Scalar& t, const State& x, State& xdot) const {
        const Sides s = sides(t, x);
        const Scalar alpha = s.sdot_minus / (s.sdot_minus - s.sdot_plus);
        xdot = alpha * s.plus + (Scalar(1) - alpha) * s.minus;
    }

    /// The terminal events that end sliding: ṡ⁺ rising to 0 (the motion leaves into s > 0), ṡ⁻ falling to 0.
    std::vector<Event<State>> exits(const std::string& name) const {
        const SlidingSurface self = *this;
        return {{name + ": leaves to s > 0", [self](const Scalar& t, const State& x) { return self.sides(t, x).sdot_plus; },
                 EventDirection::Rising, EventAction::Stop},
                {name + ": leaves to s < 0", [self](const Scalar& t, const State& x) { return self.sides(t, x).sdot_minus; },
                 EventDirection::Falling, EventAction::Stop}};
    }

  private:
    Field f_;
    Surface s_;
};

/**
 * For a run that does not follow sliding (rk4 and radau5, which cannot restart at a switch; a constrained model):
 * each Switch event of `events` without a stop_at_switch of its own ends the run where the motion would slide along
 * it (SlidingSurface::attracting of f); returns those events' names, so that the caller can say why it stopped.
 */
template <class State, class Field>
std::vector<std::string> stop_where_sliding(std::vector<Event<State>>& events, Field f) {
    using Scalar = typename State::Scalar;
    std::vector<std::string> names;
    for (Event<State>& e : events)
        if (e.action == EventAction::Switch && !e.stop_at_switch) {
            const auto surface = std::make_shared<SlidingSurface<State>>(
                [f](const Scalar& t, const State& x, State& xdot) { f(t, x, xdot); }, e.g);
            e.stop_at_switch = [surface](const Scalar& t, const State& x) { return surface->attracting(t, x); };
            names.push_back(e.name);
        }
    return names;
}

/**
 * What a run that follows sliding needs to know of its Switch events (integrate_sliding_with): which of them it
 * follows, whether the motion slides along one at (t, x) (both sides push into it), the field while it slides, the
 * events that end the sliding, and what arriving does to the state (nothing, for a plain run; the sensitivities'
 * projection onto the surface's tangent, sliding_sensitivities.hpp).
 */
template <class State>
struct SlidingRules {
    using Scalar = typename State::Scalar;
    using Field = std::function<void(const Scalar& t, const State& x, State& xdot)>;
    std::vector<bool> follows;  ///< one per event: sliding along it is followed
    std::function<bool(std::size_t event, const Scalar& t, const State& x)> holds;
    std::function<Field(std::size_t event)> field;
    std::function<std::vector<Event<State>>(std::size_t event)> exits;
    std::function<void(std::size_t event, const Scalar& t, State& x)> arrive;  ///< empty: nothing
    /// Per event (or empty: none): left out while the motion slides, where it means nothing (a graze's watch on ṡ,
    /// grazing.hpp, whose f is not the sliding one).
    std::vector<bool> idle_while_sliding;
};

/// Which of its events a run slides along where it ends (none: it does not), so that a run continued from there (a
/// constrained run's next segment, after its projection onto the constraints) goes on sliding.
struct SlidingCarry {
    static constexpr std::size_t none = static_cast<std::size_t>(-1);
    std::size_t surface = none;
};

/**
 * As integrate_with<Method>, where the Switch events that `rules` follows may also be where the motion slides: at
 * each crossing of one, if the surface holds the motion, the run goes on with the rules' field until one of its exits,
 * then with f again. The result holds the whole run; its events include, for each sliding interval, "<switch>:
 * slides" where it starts and its exit ("<switch>: leaves to s > 0", …) where it ends, and its counters add up the
 * segments'. With `carry`, a run whose last call ended sliding starts sliding along the same surface (no new
 * "slides" event), and `carry` says where this one ended.
 */
template <template <class> class Method, class System, class State>
IntegrationResult<State> integrate_sliding_with(
    System&& f, const typename State::Scalar& t0, const State& x0, const typename State::Scalar& t_end,
    const typename detail::NonDeduced<typename Method<State>::Options>::type& options,
    std::vector<Event<State>> events, const SlidingRules<State>& rules,
    const std::vector<typename State::Scalar>& sample_times = {},
    const typename detail::NonDeduced<Observer<State>>::type& observer = {}, SlidingCarry* carry = nullptr) {
    using Scalar = typename State::Scalar;
    for (std::size_t i = 0; i < events.size(); ++i)
        if (rules.follows[i])
            events[i].stop_at_switch = [&rules, i](const Scalar& t, const State& x) { return rules.holds(i, t, x); };

    IntegrationResult<State> total;
    total.t = t0;
    total.x = x0;
    Scalar t = t0;
    State x = x0;
    constexpr std::size_t none = static_cast<std::size_t>(-1);
    std::size_t sliding = carry && carry->surface < events.size() && rules.follows[carry->surface] ? carry->surface
                                                                                                    : none;
    const Scalar dir = t_end >= t0 ? Scalar(1) : Scalar(-1);
    // A start on a surface that holds the motion (a door released at rest against its hinges' friction): sliding
    // from t0.
    for (std::size_t i = 0; i < events.size() && sliding == none && t0 != t_end; ++i)
        if (rules.follows[i] && events[i].g(t0, x0) == Scalar(0) && rules.holds(i, t0, x0)) {
            sliding = i;
            if (rules.arrive) rules.arrive(i, t0, x);
            total.events.push_back({events[i].name + ": slides", t0, x});
        }
    for (bool first = true;; first = false) {
        // Samples after this segment's start (at it, for the first); the observer sees each point once.
        std::vector<Scalar> times;
        for (const Scalar& s : sample_times)
            if ((s - t) * dir > Scalar(0) || (first && s == t)) times.push_back(s);
        Observer<State> watch = observer;
        if (observer && sample_times.empty() && !first) {
            bool skip = true;
            watch = [&observer, skip](const Scalar& tt, const State& xx) mutable {
                if (skip) {
                    skip = false;
                    return;
                }
                observer(tt, xx);
            };
        }
        IntegrationResult<State> r;
        if (sliding == none) {
            r = integrate_with<Method>(f, t, x, t_end, options, events, times, watch);
        } else {
            const typename SlidingRules<State>::Field slide = rules.field(sliding);
            std::vector<Event<State>> during;
            for (std::size_t i = 0; i < events.size(); ++i)
                if (events[i].action != EventAction::Switch &&
                    !(i < rules.idle_while_sliding.size() && rules.idle_while_sliding[i]))
                    during.push_back(events[i]);
            for (Event<State>& e : rules.exits(sliding)) during.push_back(std::move(e));
            r = integrate_with<Method>(slide, t, x, t_end, options, during, times, watch);
        }
        total.accepted_steps += r.accepted_steps;
        total.rejected_steps += r.rejected_steps;
        total.rhs_evaluations += r.rhs_evaluations;
        total.events.insert(total.events.end(), r.events.begin(), r.events.end());
        total.switches.insert(total.switches.end(), r.switches.begin(), r.switches.end());
        total.samples.insert(total.samples.end(), r.samples.begin(), r.samples.end());
        t = r.t;
        x = r.x;
        total.t = t;
        total.x = x;
        if (r.stop_reason == StopReason::ReachedEnd) {
            if (carry) carry->surface = sliding;
            break;
        }
        std::size_t which = none;
        for (std::size_t i = 0; i < events.size() && which == none; ++i)
            if (events[i].name == r.stopped_by) which = i;
        if (sliding == none && which != none && rules.follows[which]) {
            sliding = which;  // both sides push in: on along the surface
            if (rules.arrive) rules.arrive(which, t, x);
            total.x = x;
            total.events.push_back({events[which].name + ": slides", t, x});
            continue;
        }
        if (sliding != none && r.stopped_by.rfind(events[sliding].name + ": leaves", 0) == 0) {
            sliding = none;  // (the exit is among r.events already)
            continue;
        }
        total.stop_reason = StopReason::TerminalEvent;
        total.stopped_by = r.stopped_by;
        if (carry) carry->surface = sliding;
        break;
    }
    return total;
}

/**
 * The rules that follow Filippov's sliding along each Switch event of `events` without a stop_at_switch of its own
 * (SlidingSurface of `field`); the others are left as they are. The rules hold copies of `field` and the events'
 * functions, and may outlive them.
 */
template <class State>
SlidingRules<State> filippov_rules(const typename SlidingSurface<State>::Field& field,
                                   const std::vector<Event<State>>& events) {
    using Scalar = typename State::Scalar;
    const auto surfaces = std::make_shared<std::vector<std::shared_ptr<SlidingSurface<State>>>>(events.size());
    SlidingRules<State> rules;
    rules.follows.assign(events.size(), false);
    for (std::size_t i = 0; i < events.size(); ++i)
        if (events[i].action == EventAction::Switch && !events[i].stop_at_switch) {
            (*surfaces)[i] = std::make_shared<SlidingSurface<State>>(field, events[i].g);
            rules.follows[i] = true;
        }
    rules.holds = [surfaces](std::size_t i, const Scalar& t, const State& x) { return (*surfaces)[i]->attracting(t, x); };
    rules.field = [surfaces](std::size_t i) -> typename SlidingRules<State>::Field {
        const auto surface = (*surfaces)[i];
        return [surface](const Scalar& t, const State& x, State& xdot) { surface->sliding_field(t, x, xdot); };
    };
    std::vector<std::string> names;
    for (const Event<State>& e : events) names.push_back(e.name);
    rules.exits = [surfaces, names](std::size_t i) { return (*surfaces)[i]->exits(names[i]); };
    return rules;
}

/**
 * As integrate_with<Method>, where the Switch events of `events` may also be where the motion slides: at each
 * crossing of one, if both sides push into it (SlidingSurface::attracting), the run goes on with Filippov's field
 * until the motion leaves the surface, then with f again (integrate_sliding_with). A Switch event with a
 * stop_at_switch of its own is left as it is.
 */
template <template <class> class Method, class System, class State>
IntegrationResult<State> integrate_sliding(
    System&& f, const typename State::Scalar& t0, const State& x0, const typename State::Scalar& t_end,
    const typename detail::NonDeduced<typename Method<State>::Options>::type& options,
    std::vector<Event<State>> events, const std::vector<typename State::Scalar>& sample_times = {},
    const typename detail::NonDeduced<Observer<State>>::type& observer = {}) {
    using Scalar = typename State::Scalar;
    const typename SlidingSurface<State>::Field field = [&f](const Scalar& t, const State& x, State& xdot) {
        f(t, x, xdot);
    };
    const SlidingRules<State> rules = filippov_rules(field, events);
    return integrate_sliding_with<Method>(f, t0, x0, t_end, options, std::move(events), rules, sample_times, observer);
}

}  // namespace eomgen
