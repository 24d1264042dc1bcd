/** @file exam_dop853.cpp  DOP853 against closed forms: order 8, dense output of order 7, counts, errors, long
 * double. */
#include "../approx.hpp"
#include "closed_forms.hpp"

#include "eomgen/dop853.hpp"
#include "eomgen/errors.hpp"
#include "eomgen/integrate.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace {

using eomgen::test::AllClose;
using eomgen::test::kepler;
using eomgen::test::kepler_exact;
using eomgen::test::Oscillator;

/// Options that accept every step of size h: tolerances so loose that err ≪ 1, h0 = hmax = h.
template <class Scalar>
eomgen::Dop853Options<Scalar> fixed_step(const Scalar& h) {
    eomgen::Dop853Options<Scalar> opts;
    opts.rtol = opts.atol = Scalar(1e10);
    opts.h0 = opts.hmax = h;
    return opts;
}


}  // namespace

TEST_CASE("DOP853 converges with order 8 at fixed steps on a Kepler orbit (e = 0.1)", "[runtime][dop853]") {
    // One period of a nonlinear problem (a linear one would test only some of the order conditions) at N
    // fixed steps; the global error must fall like h^8. e = 0.1 keeps these N in the asymptotic range, and
    // the errors (1e-8 … 1e-13) far above rounding.
    const double e = 0.1, period = 2 * std::acos(-1.0);
    const Eigen::Vector4d x0 = kepler_exact(0.0, e);
    std::vector<double> hs, errs;
    for (int n : {20, 30, 40, 60, 80}) {
        const double h = period / n;
        const auto r = eomgen::integrate_dop853(kepler<Eigen::Vector4d>, 0.0, x0, period, fixed_step(h));
        REQUIRE(r.t == period);
        CHECK(r.rejected_steps == 0);
        CHECK(r.accepted_steps == std::size_t(n));
        // f(t0), then 12 per step (the 13th stage is the next step's first); no dense output was asked for.
        CHECK(r.rhs_evaluations == 12 * r.accepted_steps + 1);
        hs.push_back(h);
        errs.push_back((r.x - x0).lpNorm<Eigen::Infinity>());
    }
    const double order = eomgen::test::fitted_slope(hs, errs);
    INFO("errors " << errs[0] << " " << errs[1] << " " << errs[2] << " " << errs[3] << " " << errs[4]
                   << "; fitted order " << order);
    CHECK(order >= 7.5);
    CHECK(order <= 8.7);
}

TEST_CASE("DOP853 dense output has order 7: local error O(h^8) inside a step", "[runtime][dop853]") {
    // The first step of a Kepler orbit (nonlinear, so every order condition of the interpolant counts) from
    // the exact x0: the interpolant's error inside it is its local error, which for a 7th-order continuous
    // extension shrinks like h^8 (the step's end, 8th order, like h^9).
    using State = Eigen::Vector4d;
    const double e = 0.1;
    const State x0 = kepler_exact(0.0, e);
    std::vector<double> hs, errs;
    for (double h : {0.8, 0.6, 0.4, 0.3}) {
        eomgen::Dop853<State> stepper(kepler<State>, 0.0, x0, 10.0, fixed_step(h));
        stepper.step(kepler<State>);
        REQUIRE(stepper.t() == h);
        State x;
        CHECK_THROWS_AS(stepper.dense(0.5 * h, x), std::logic_error);  // the extra stages are not made yet
        const std::size_t before = stepper.rhs_evaluations();
        stepper.prepare_dense(kepler<State>);
        stepper.prepare_dense(kepler<State>);  // once per step
        CHECK(stepper.rhs_evaluations() == before + 3);
        double err = 0;
        for (double th : {0.1, 0.3, 0.5, 0.7, 0.9}) {
            stepper.dense(th * h, x);
            err = std::max(err, (x - kepler_exact(th * h, e)).lpNorm<Eigen::Infinity>());
        }
        // exact at both ends
        stepper.dense(0.0, x);
        CHECK(x == x0);
        stepper.dense(h, x);
        CHECK(x == stepper.x());
        hs.push_back(h);
        errs.push_back(err);
    }
    const double order = eomgen::test::fitted_slope(hs, errs);
    INFO("dense local errors " << errs[0] << " " << errs[1] << " " << errs[2] << " " << errs[3] << ", slope "
                               << order);
    CHECK(order >= 7.5);
    CHECK(order <= 8.7);

    // Adaptive run with samples: the values between steps are as good as those at the steps.
    const Oscillator<Eigen::Vector2d> osc{1.0};
    const Eigen::Vector2d y0(1.0, 0.3);
    eomgen::Dop853Options<double> opts;
    opts.rtol = 1e-11;
    opts.atol = 1e-13;
    std::vector<double> times;
    for (int i = 0; i <= 97; ++i) times.push_back(0.1 * i + 0.013);
    const auto r = eomgen::integrate_dop853(osc, 0.0, y0, 10.0, opts, {}, times);
    REQUIRE(r.samples.size() == times.size());
    double sample_err = 0;
    for (const auto& s : r.samples)
        sample_err = std::max(sample_err, (s.x - osc.exact(s.t, y0)).lpNorm<Eigen::Infinity>());
    const double end_err = (r.x - osc.exact(10.0, y0)).lpNorm<Eigen::Infinity>();
    INFO("sample error " << sample_err << ", end error " << end_err << " in " << r.accepted_steps
                         << " steps");
    CHECK(sample_err < 3 * end_err + 1e-12);
    // Each step with a sample inside pays the 3 dense stages; none other does.
    const auto plain = eomgen::integrate_dop853(osc, 0.0, y0, 10.0, opts);
    CHECK(r.accepted_steps == plain.accepted_steps);
    CHECK(r.rhs_evaluations > plain.rhs_evaluations);
    CHECK(r.rhs_evaluations <= plain.rhs_evaluations + 3 * plain.accepted_steps);
    CHECK((r.rhs_evaluations - plain.rhs_evaluations) % 3 == 0);
}

TEST_CASE("DOP853 at tight tolerance: Kepler orbit, events, backwards, fewer evaluations than DOPRI5",
          "[runtime][dop853]") {
    const double e = 0.5, period = 2 * std::acos(-1.0);
    const Eigen::Vector4d x0 = kepler_exact(0.0, e);
    eomgen::Dop853Options<double> opts;
    opts.rtol = 1e-12;
    opts.atol = 1e-14;
    // y crosses 0 falling at apoapsis, t = period/2: located on the dense output.
    const std::vector<eomgen::Event<Eigen::Vector4d>> events{
        {"apoapsis", [](const double&, const Eigen::Vector4d& x) { return x(1); },
         eomgen::EventDirection::Falling, eomgen::EventAction::Record}};
    const auto r = eomgen::integrate_dop853(kepler<Eigen::Vector4d>, 0.0, x0, 2 * period, opts, events);
    const double err = (r.x - x0).lpNorm<Eigen::Infinity>();
    INFO("Kepler error " << err << " in " << r.accepted_steps << " steps, " << r.rhs_evaluations << " f");
    CHECK(err < 1e-10);
    REQUIRE(r.events.size() == 2);
    CHECK(r.events[0].t == Approx(period / 2).margin(1e-11));
    CHECK(r.events[1].t == Approx(1.5 * period).margin(1e-11));

    eomgen::Dopri5Options<double> opts5;
    opts5.rtol = opts.rtol;
    opts5.atol = opts.atol;
    const auto r5 = eomgen::integrate(kepler<Eigen::Vector4d>, 0.0, x0, 2 * period, opts5, events);
    INFO("DOPRI5: " << r5.rhs_evaluations << " f, error " << (r5.x - x0).lpNorm<Eigen::Infinity>());
    CHECK(r.rhs_evaluations < r5.rhs_evaluations);

    // Backwards from the end of the second period to the start.
    const auto back = eomgen::integrate_dop853(kepler<Eigen::Vector4d>, 2 * period, r.x, 0.0, opts);
    CHECK(back.t == 0.0);
    REQUIRE_THAT(Eigen::MatrixXd(back.x), AllClose(x0, 0, 1e-9));

    // The same run on a dynamic-size state takes the same steps.
    const Eigen::VectorXd x0d = x0;
    const auto rd = eomgen::integrate_dop853(kepler<Eigen::VectorXd>, 0.0, x0d, 2 * period, opts);
    CHECK(rd.accepted_steps == r.accepted_steps);
    REQUIRE_THAT(Eigen::MatrixXd(rd.x), AllClose(r.x, 1e-14, 1e-14));
}

TEST_CASE("DOP853 reports failures like DOPRI5: NaN, blow-up, max_steps, bad options",
          "[runtime][dop853][errors]") {
    using State = Eigen::Vector2d;
    const Oscillator<State> osc;
    const auto nan_after_one = [&osc](const double& t, const State& x, State& xdot) {
        osc(t, x, xdot);
        if (t >= 1.0) xdot(1) = std::numeric_limits<double>::quiet_NaN();
    };
    try {
        eomgen::integrate_dop853(nan_after_one, 0.0, State(1.0, 0.0), 2.0);
        FAIL("no exception");
    } catch (const eomgen::NonFiniteState& e) {
        INFO(e.what());
        CHECK(e.t() < 1.0);
        CHECK(e.t() > 1.0 - 1e-12);
        CHECK_THAT(e.what(), Catch::Contains("with state"));
    }
    using State1 = Eigen::Matrix<double, 1, 1>;
    const auto blow_up = [](const double&, const State1& x, State1& xdot) { xdot(0) = x(0) * x(0); };
    try {
        eomgen::Dop853Options<double> opts;
        opts.rtol = 1e-10;
        const auto r = eomgen::integrate_dop853(blow_up, 0.0, State1(1.0), 2.0, opts);
        FAIL("returned x = " << r.x(0) << " at t = " << r.t);
    } catch (const eomgen::SimulationError& e) {
        INFO(e.what());
        CHECK(e.t() == Approx(1.0).margin(1e-6));
    }
    eomgen::Dop853Options<double> few;
    few.max_steps = 20;
    try {
        eomgen::integrate_dop853(osc, 0.0, State(1.0, 0.0), 1000.0, few);
        FAIL("no exception");
    } catch (const eomgen::TooManySteps& e) {
        CHECK_THAT(e.what(), Catch::Contains("max_steps = 20"));
    }
    eomgen::Dop853Options<double> bad;
    bad.atol = 0;
    CHECK_THROWS_AS(eomgen::integrate_dop853(osc, 0.0, State(1.0, 0.0), 1.0, bad), std::invalid_argument);
    CHECK_THROWS_AS(eomgen::integrate_dop853(osc, 0.0, State(std::nan(""), 0.0), 1.0),
                    eomgen::NonFiniteState);
    // DOP853's own controller defaults (Hairer's dop853.f), the other fields as DOPRI5's.
    const eomgen::Dop853Options<double> defaults;
    CHECK(defaults.min_factor == 0.333);
    CHECK(defaults.max_factor == 6.0);
    CHECK(defaults.beta == 0.0);
}

TEST_CASE("long double: DOP853 reaches beyond double precision, order 8 at errors below 1e-16",
          "[runtime][dop853][long double]") {
    using State = Eigen::Matrix<long double, 2, 1>;
    const Oscillator<State> osc;
    const State x0(1.0L, 0.0L);
    eomgen::Dop853Options<long double> opts;
    opts.rtol = 1e-18L;
    opts.atol = 1e-20L;
    const long double t_end = 2 * 3.14159265358979323846264338327950288L;
    const auto r = eomgen::integrate_dop853(osc, 0.0L, x0, t_end, opts, {}, {t_end / 3});
    const long double err = (r.x - osc.exact(t_end, x0)).lpNorm<Eigen::Infinity>();
    const long double sample_err = (r.samples.at(0).x - osc.exact(t_end / 3, x0)).lpNorm<Eigen::Infinity>();
    INFO("long double DOP853 error " << double(err) << ", sample " << double(sample_err) << " in "
                                     << r.accepted_steps << " steps");
    CHECK(err < 1e-16L);
    CHECK(sample_err < 1e-16L);

    // The tableau holds to long double: the order is still 8 where double's rounding would hide it.
    std::vector<double> hs, errs;
    for (int n : {12, 16, 24, 32}) {
        const long double h = 2.0L / n;
        const auto ri = eomgen::integrate_dop853(osc, 0.0L, x0, 2.0L, fixed_step(h));
        hs.push_back(double(h));
        errs.push_back(double((ri.x - osc.exact(2.0L, x0)).lpNorm<Eigen::Infinity>()));
    }
    const double order = eomgen::test::fitted_slope(hs, errs);
    INFO("long double errors " << errs[0] << " " << errs[1] << " " << errs[2] << " " << errs[3] << ", order "
                               << order);
    CHECK(errs[3] < 1e-16);
    CHECK(order >= 7.5);
    CHECK(order <= 8.7);
}
