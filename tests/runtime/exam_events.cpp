/** @file exam_events.cpp  Event location on dense output: zero crossings of an oscillator at known times. */
#include "../approx.hpp"

#include "eomgen/events.hpp"
#include "eomgen/integrate.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using eomgen::EventAction;
using eomgen::EventDirection;
using eomgen::test::AllClose;

/// x'' = -x from [1, 0]: x = cos t, crossing zero falling at π/2 + 2kπ and rising at 3π/2 + 2kπ.
template <class State>
void oscillator(const typename State::Scalar&, const State& x, State& xdot) {
    xdot(0) = x(1);
    xdot(1) = -x(0);
}

template <class State>
eomgen::Event<State> level(const std::string& name, typename State::Scalar value, EventDirection direction,
                           EventAction action) {
    return {name, [value](const typename State::Scalar&, const State& x) { return x(0) - value; }, direction,
            action};
}

const double pi = std::acos(-1.0);

}  // namespace

TEST_CASE("Brent's method finds a root to a few ulp and returns the far side of the bracket",
          "[runtime][events]") {
    const auto g = [](double t) { return std::cos(t); };
    const double eps = std::numeric_limits<double>::epsilon();
    const double tol = 2 * eps * 2.0;  // as the driver sets it: 2 eps max(|ta|, |tb|)
    const double root = eomgen::find_root_brent(g, 1.0, g(1.0), 2.0, g(2.0), tol);
    // The final bracket is at most 2 (2 eps |t| + tol/2) wide: within 8 ulp of π/2.
    CHECK(std::abs(root - pi / 2) <= 8 * eps * (pi / 2));
    CHECK(g(root) <= 0.0);  // on b's side: g(2) < 0
    const double back = eomgen::find_root_brent(g, 2.0, g(2.0), 1.0, g(1.0), tol);
    CHECK(std::abs(back - pi / 2) <= 8 * eps * (pi / 2));
    CHECK(g(back) >= 0.0);
    CHECK(eomgen::find_root_brent(g, 0.0, 1.0, pi / 2, 0.0, tol) == pi / 2);  // a root at an end
}

TEST_CASE("crosses(): direction filtering, and a start exactly on the root does not count",
          "[runtime][events]") {
    using eomgen::crosses;
    CHECK(crosses(-1.0, 1.0, EventDirection::Rising));
    CHECK(!crosses(-1.0, 1.0, EventDirection::Falling));
    CHECK(crosses(1.0, -1.0, EventDirection::Falling));
    CHECK(crosses(1.0, 0.0, EventDirection::Both));
    CHECK(!crosses(0.0, 1.0, EventDirection::Both));
    CHECK(!crosses(1.0, 2.0, EventDirection::Both));
}

TEST_CASE("a zero crossing of the oscillator is located to 1e-12 of the exact time", "[runtime][events]") {
    using State = Eigen::Vector2d;
    eomgen::Dopri5Options<double> opts;
    opts.rtol = 1e-12;
    opts.atol = 1e-14;
    const std::vector<eomgen::Event<State>> events{
        level<State>("x = 0", 0.0, EventDirection::Both, EventAction::Record)};
    const auto r = eomgen::integrate(oscillator<State>, 0.0, State(1.0, 0.0), 10.0, opts, events);
    REQUIRE(r.events.size() == 3);  // π/2, 3π/2, 5π/2 < 10
    double worst = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        const double exact = pi / 2 + k * pi;
        CHECK(r.events[k].name == "x = 0");
        worst = std::max(worst, std::abs(r.events[k].t - exact));
        CHECK(std::abs(r.events[k].x(0)) < 1e-12);
        CHECK(std::abs(std::abs(r.events[k].x(1)) - 1.0) < 1e-12);
    }
    INFO("worst event time error " << worst);
    CHECK(worst <= 1e-12);
    CHECK(r.t == 10.0);
    CHECK(r.stop_reason == eomgen::StopReason::ReachedEnd);
}

TEST_CASE("direction filtering: rising, falling, both", "[runtime][events]") {
    using State = Eigen::Vector2d;
    eomgen::Dopri5Options<double> opts;
    opts.rtol = 1e-10;
    const std::vector<eomgen::Event<State>> events{
        level<State>("rise", 0.0, EventDirection::Rising, EventAction::Record),
        level<State>("fall", 0.0, EventDirection::Falling, EventAction::Record),
        level<State>("both", 0.0, EventDirection::Both, EventAction::Record)};
    const auto r = eomgen::integrate(oscillator<State>, 0.0, State(1.0, 0.0), 10.0, opts, events);
    std::vector<double> rise, fall, both;
    for (const auto& hit : r.events)
        (hit.name == "rise" ? rise : hit.name == "fall" ? fall : both).push_back(hit.t);
    REQUIRE(rise.size() == 1);
    REQUIRE(fall.size() == 2);
    REQUIRE(both.size() == 3);
    CHECK(rise[0] == Approx(3 * pi / 2).margin(1e-9));
    CHECK(fall[0] == Approx(pi / 2).margin(1e-9));
    CHECK(fall[1] == Approx(5 * pi / 2).margin(1e-9));
    for (std::size_t i = 1; i < r.events.size(); ++i)
        CHECK(r.events[i - 1].t <= r.events[i].t);  // time order
}

TEST_CASE("a terminal event ends the run at exactly its time and state, samples stop there",
          "[runtime][events]") {
    using State = Eigen::Vector2d;
    eomgen::Dopri5Options<double> opts;
    opts.rtol = 1e-12;
    opts.atol = 1e-14;
    const std::vector<eomgen::Event<State>> events{
        level<State>("record rise", 0.0, EventDirection::Rising, EventAction::Record),
        level<State>("stop at x = -0.5 rising", -0.5, EventDirection::Rising, EventAction::Stop)};
    std::vector<double> times;
    for (int i = 0; i <= 100; ++i) times.push_back(0.1 * i);
    const auto r = eomgen::integrate(oscillator<State>, 0.0, State(1.0, 0.0), 10.0, opts, events, times);
    // cos t = -0.5 rising at t = 4π/3; the rising zero at 3π/2 comes after and is not reached.
    CHECK(r.stop_reason == eomgen::StopReason::TerminalEvent);
    CHECK(r.stopped_by == "stop at x = -0.5 rising");
    CHECK(std::abs(r.t - 4 * pi / 3) < 1e-12);
    REQUIRE(r.events.size() == 1);
    CHECK(r.events[0].t == r.t);
    CHECK(r.events[0].x == r.x);
    CHECK(r.x(0) >= -0.5);  // the returned state is on or past the surface
    REQUIRE_THAT(Eigen::MatrixXd(r.x), AllClose(State(std::cos(r.t), -std::sin(r.t)), 0, 1e-12));
    REQUIRE(!r.samples.empty());
    CHECK(r.samples.back().t <= r.t);
    CHECK(r.samples.size() == std::size_t(std::floor(r.t / 0.1)) + 1);
}

TEST_CASE("several events in one step: the earliest terminal one wins, records before it are kept",
          "[runtime][events]") {
    using State = Eigen::Vector2d;
    // RK4 with dt = 0.5: cos t passes 0.5 (t = 1.047), 0.45 (1.104) and 0.4 (1.159) in the step [1, 1.5].
    const auto a = level<State>("A x=0.4", 0.4, EventDirection::Falling, EventAction::Stop);
    const auto b_stop = level<State>("B x=0.5", 0.5, EventDirection::Falling, EventAction::Stop);
    const auto b_rec = level<State>("B x=0.5", 0.5, EventDirection::Falling, EventAction::Record);
    const auto c = level<State>("C x=0.45", 0.45, EventDirection::Falling, EventAction::Record);

    const auto r1 = eomgen::integrate_rk4(oscillator<State>, 0.0, State(1.0, 0.0), 3.0, 0.5, {a, b_stop, c});
    CHECK(r1.stopped_by == "B x=0.5");
    REQUIRE(r1.events.size() == 1);
    CHECK(r1.t == Approx(std::acos(0.5)).margin(2e-3));

    const auto r2 = eomgen::integrate_rk4(oscillator<State>, 0.0, State(1.0, 0.0), 3.0, 0.5, {a, b_rec, c});
    CHECK(r2.stopped_by == "A x=0.4");
    REQUIRE(r2.events.size() == 3);
    CHECK(r2.events[0].name == "B x=0.5");
    CHECK(r2.events[1].name == "C x=0.45");
    CHECK(r2.events[2].name == "A x=0.4");
    CHECK(r2.events[1].t == Approx(std::acos(0.45)).margin(2e-3));
    CHECK(r2.t == r2.events[2].t);
    // Located on RK4's Hermite interpolant: g vanishes there to rounding, whatever RK4's own error.
    for (const auto& hit : r2.events)
        CHECK(std::abs(hit.x(0) - (hit.name[0] == 'A' ? 0.4 : hit.name[0] == 'B' ? 0.5 : 0.45)) < 1e-14);
}

TEST_CASE("long double: an event is located beyond double precision", "[runtime][events][long double]") {
    using State = Eigen::Matrix<long double, 2, 1>;
    eomgen::Dopri5Options<long double> opts;
    opts.rtol = 1e-17L;
    opts.atol = 1e-19L;
    const std::vector<eomgen::Event<State>> events{
        level<State>("x = 0", 0.0L, EventDirection::Falling, EventAction::Stop)};
    const auto r = eomgen::integrate(oscillator<State>, 0.0L, State(1.0L, 0.0L), 4.0L, opts, events);
    const long double half_pi = 1.57079632679489661923132169163975144L;
    INFO("long double event error " << double(r.t - half_pi));
    CHECK(std::abs(r.t - half_pi) < 1e-16L);
    CHECK(r.stopped_by == "x = 0");
}
