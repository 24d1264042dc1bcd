/** @file exam_adams.cpp  The variable-order Adams stepper (adams.hpp) against closed forms: fixed-order
 * convergence, tolerance proportionality, invariants, dense output and events beside DOP853, errors. */
#include "closed_forms.hpp"

#include "eomgen/adams.hpp"
#include "eomgen/errors.hpp"
#include "eomgen/integrate.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using eomgen::test::kepler;
using eomgen::test::fitted_slope;
using eomgen::test::kepler_exact;
using eomgen::test::Oscillator;
using State4 = Eigen::Vector4d;

eomgen::AdamsOptions<double> tolerances(double rtol, double atol) {
    eomgen::AdamsOptions<double> opts;
    opts.rtol = rtol;
    opts.atol = atol;
    return opts;
}

/// Kepler's energy v²/2 − 1/r (−1/2 for a = 1) and angular momentum x v_y − y v_x (√(1 − e²)).
double kepler_energy(const State4& x) {
    return 0.5 * (x(2) * x(2) + x(3) * x(3)) - 1 / std::hypot(x(0), x(1));
}
double kepler_momentum(const State4& x) {
    return x(0) * x(3) - x(1) * x(2);
}

}  // namespace

TEST_CASE("Adams at fixed order k and constant steps converges like h^(k+1) on a Kepler orbit",
          "[runtime][adams]") {
    // max_order = k caps the order; tolerances so loose that every step is accepted and hmax = h holds the
    // step at h once the start (order 1 from h0 = 1e-7, the step doubling and the order rising by one each
    // step) has reached it. The start's error, ~h0² ≈ 1e-14, is far below the errors fitted. With local
    // extrapolation the corrector of a step "at order k" has order k + 1, so the global error of a nonlinear
    // problem (every order condition counts) falls like h^(k+1). Orders above 4 are left to the adaptive
    // tests: at these h their own estimates prefer lower orders, which the loop below would catch.
    const double e = 0.1, t_end = 4.0;
    const State4 x0 = kepler_exact(0.0, e), exact = kepler_exact(t_end, e);
    for (int k = 1; k <= 4; ++k) {
        std::vector<double> hs, errs;
        for (int n : {30, 40, 60, 80, 120}) {
            const double h = t_end / n;
            eomgen::AdamsOptions<double> opts = tolerances(1e10, 1e10);
            opts.h0 = 1e-7;
            opts.hmax = h;
            opts.max_order = k;
            eomgen::Adams<State4> stepper(kepler<State4>, 0.0, x0, t_end, opts);
            std::size_t full_steps = 0;
            while (!stepper.done()) {
                stepper.step(kepler<State4>);
                if (stepper.done() || stepper.last_step_size() < 0.999 * h) continue;
                ++full_steps;
                REQUIRE(stepper.last_order() == k);  // every step of size h was taken at order k
            }
            CHECK(full_steps + 1 >= std::size_t(n) - 2);
            CHECK(stepper.rejected_steps() == 0);
            CHECK(stepper.rhs_evaluations() == 2 * stepper.accepted_steps() + 1);  // PECE, f(t0) once
            hs.push_back(h);
            errs.push_back((stepper.x() - exact).lpNorm<Eigen::Infinity>());
        }
        const double order = fitted_slope(hs, errs);
        INFO("k = " << k << ": errors " << errs[0] << " … " << errs.back() << ", fitted order " << order);
        CHECK(std::abs(order - (k + 1)) <= 0.3);
    }
}

TEST_CASE("Adams: the error falls in proportion to the tolerance on the oscillator and Kepler orbits",
          "[runtime][adams]") {
    // Tolerance proportionality: over 1e-6 … 1e-13 the global error follows the tolerance with slope ≈ 1,
    // and stays within a modest factor of it (the error is controlled per step, so it accumulates over the
    // steps of ten periods).
    const Oscillator<Eigen::Vector2d> osc{1.3};
    const Eigen::Vector2d y0(1.0, -0.4);
    const double e = 0.3, period = 2 * std::acos(-1.0);
    const State4 x0 = kepler_exact(0.0, e);
    std::vector<double> tols, osc_errs, kep_errs;
    for (double tol = 1e-6; tol > 1e-13; tol /= 10) {
        const auto r = eomgen::integrate_adams(osc, 0.0, y0, 50.0, tolerances(tol, tol));
        const auto k = eomgen::integrate_adams(kepler<State4>, 0.0, x0, 3 * period, tolerances(tol, tol));
        tols.push_back(tol);
        osc_errs.push_back((r.x - osc.exact(50.0, y0)).lpNorm<Eigen::Infinity>());
        kep_errs.push_back((k.x - x0).lpNorm<Eigen::Infinity>());
        INFO("tol " << tol << ": oscillator " << osc_errs.back() << " (" << r.rhs_evaluations
                    << " f), Kepler " << kep_errs.back() << " (" << k.rhs_evaluations << " f)");
        CHECK(osc_errs.back() < 300 * tol);
        CHECK(kep_errs.back() < 3000 * tol);
        CHECK(r.rhs_evaluations == 2 * r.accepted_steps + r.rejected_steps + 1);
    }
    const double osc_slope = fitted_slope(tols, osc_errs), kep_slope = fitted_slope(tols, kep_errs);
    INFO("slopes: oscillator " << osc_slope << ", Kepler " << kep_slope);
    CHECK(osc_slope >= 0.8);
    CHECK(osc_slope <= 1.25);
    CHECK(kep_slope >= 0.8);
    CHECK(kep_slope <= 1.25);
}

TEST_CASE("Adams keeps Kepler's energy and angular momentum along the trajectory and runs backwards",
          "[runtime][adams]") {
    const double e = 0.5, period = 2 * std::acos(-1.0);
    const State4 x0 = kepler_exact(0.0, e);
    double drift_h = 0, drift_l = 0;
    std::size_t seen = 0;
    const auto r = eomgen::integrate_adams(
        kepler<State4>, 0.0, x0, 5 * period, tolerances(1e-12, 1e-14), {}, {},
        [&](const double&, const State4& x) {
            drift_h = std::max(drift_h, std::abs(kepler_energy(x) + 0.5));
            drift_l = std::max(drift_l, std::abs(kepler_momentum(x) - std::sqrt(1 - e * e)));
            ++seen;
        });
    INFO("drift of h " << drift_h << ", of L " << drift_l << " over " << r.accepted_steps << " steps");
    CHECK(seen == r.accepted_steps + 1);  // t0 and every step's end
    CHECK(drift_h < 1e-9);
    CHECK(drift_l < 1e-9);
    CHECK((r.x - x0).lpNorm<Eigen::Infinity>() < 1e-8);

    // Backwards from the end of one period to its start, and from the start to −period.
    const auto back = eomgen::integrate_adams(kepler<State4>, period, x0, 0.0, tolerances(1e-12, 1e-14));
    CHECK(back.t == 0.0);
    CHECK((back.x - x0).lpNorm<Eigen::Infinity>() < 1e-9);
    const Oscillator<Eigen::Vector2d> osc{2.0};
    const Eigen::Vector2d y0(0.2, 1.0);
    const auto ob = eomgen::integrate_adams(osc, 0.0, y0, -7.5, tolerances(1e-12, 1e-14));
    CHECK((ob.x - osc.exact(-7.5, y0)).lpNorm<Eigen::Infinity>() < 1e-9);
}

TEST_CASE("Adams dense output and events agree with the closed form and with DOP853", "[runtime][adams]") {
    // Samples between steps are as good as the steps' ends, and cost nothing.
    const Oscillator<Eigen::Vector2d> osc{1.0};
    const Eigen::Vector2d y0(1.0, 0.3);
    std::vector<double> times;
    for (int i = 0; i <= 97; ++i) times.push_back(0.1 * i + 0.013);
    const auto r = eomgen::integrate_adams(osc, 0.0, y0, 10.0, tolerances(1e-11, 1e-13), {}, times);
    const auto plain = eomgen::integrate_adams(osc, 0.0, y0, 10.0, tolerances(1e-11, 1e-13));
    REQUIRE(r.samples.size() == times.size());
    double sample_err = 0;
    for (const auto& s : r.samples)
        sample_err = std::max(sample_err, (s.x - osc.exact(s.t, y0)).lpNorm<Eigen::Infinity>());
    const double end_err = (r.x - osc.exact(10.0, y0)).lpNorm<Eigen::Infinity>();
    INFO("sample error " << sample_err << ", end error " << end_err << " in " << r.accepted_steps
                         << " steps");
    CHECK(sample_err < 3 * end_err + 1e-11);
    CHECK(r.rhs_evaluations == plain.rhs_evaluations);
    CHECK(r.accepted_steps == plain.accepted_steps);

    // Inside one step the interpolant is exact at both ends, and between them it follows the flow through the
    // step's end (the oscillator's closed form from (t, x), which leaves out the error accumulated before)
    // to within a step's local error, about the tolerance: on a step well into the run (order > 1).
    eomgen::Adams<Eigen::Vector2d> stepper(osc, 0.0, y0, 10.0, tolerances(1e-10, 1e-12));
    while (stepper.t() < 5.0) stepper.step(osc);
    CHECK(stepper.last_order() >= 5);
    Eigen::Vector2d x;
    stepper.dense(stepper.t(), x);
    CHECK(x == stepper.x());
    stepper.dense(stepper.t_prev(), x);
    CHECK(x == stepper.x_prev());
    const double ta = stepper.t_prev(), hs = stepper.last_step_size();
    double inside = 0;
    for (double th : {0.01, 0.1, 0.37, 0.5, 0.81, 0.99}) {
        stepper.dense(ta + th * hs, x);
        inside = std::max(inside,
                          (x - osc.exact(ta + th * hs - stepper.t(), stepper.x())).lpNorm<Eigen::Infinity>());
    }
    INFO("interpolant against the local flow: " << inside << " on a step of " << hs);
    CHECK(inside < 1e-10);
    CHECK(inside > 0);

    // Events on Kepler's orbit: y falls through 0 at apoapsis, t = (k + 1/2)·period, located on the dense
    // output; and the same times as DOP853 finds.
    const double e = 0.5, period = 2 * std::acos(-1.0);
    const State4 x0 = kepler_exact(0.0, e);
    const std::vector<eomgen::Event<State4>> events{
        {"apoapsis", [](const double&, const State4& s) { return s(1); }, eomgen::EventDirection::Falling,
         eomgen::EventAction::Record},
        {"x = 0", [](const double&, const State4& s) { return s(0); }, eomgen::EventDirection::Both,
         eomgen::EventAction::Record}};
    const auto a =
        eomgen::integrate_adams(kepler<State4>, 0.0, x0, 3 * period, tolerances(1e-12, 1e-14), events);
    eomgen::Dop853Options<double> d_opts;
    d_opts.rtol = 1e-12;
    d_opts.atol = 1e-14;
    const auto d = eomgen::integrate_dop853(kepler<State4>, 0.0, x0, 3 * period, d_opts, events);
    REQUIRE(a.events.size() == 9);  // 3 apoapses, 6 crossings of x = 0
    REQUIRE(d.events.size() == a.events.size());
    int apoapsis = 0;
    for (std::size_t i = 0; i < a.events.size(); ++i) {
        INFO("event " << i << " " << a.events[i].name << " at " << a.events[i].t);
        CHECK(a.events[i].name == d.events[i].name);
        CHECK(std::abs(a.events[i].t - d.events[i].t) < 1e-9);
        CHECK((a.events[i].x - kepler_exact(a.events[i].t, e)).lpNorm<Eigen::Infinity>() < 1e-8);
        if (a.events[i].name == "apoapsis")
            CHECK(std::abs(a.events[i].t - (apoapsis++ + 0.5) * period) < 1e-9);
    }

    // A terminal event ends the run there.
    const std::vector<eomgen::Event<State4>> stop{
        {"apoapsis", events[0].g, eomgen::EventDirection::Falling, eomgen::EventAction::Stop}};
    const auto s =
        eomgen::integrate_adams(kepler<State4>, 0.0, x0, 3 * period, tolerances(1e-12, 1e-14), stop);
    CHECK(s.stop_reason == eomgen::StopReason::TerminalEvent);
    CHECK(std::abs(s.t - 0.5 * period) < 1e-9);
}

TEST_CASE("Adams in long double goes past double's precision", "[runtime][adams]") {
    using StateL = Eigen::Matrix<long double, 4, 1>;
    const double e = 0.1;
    // kepler_exact is double, so the check is the energy, which needs no closed form.
    const StateL x0 = kepler_exact(0.0, e).cast<long double>();
    eomgen::AdamsOptions<long double> opts;
    opts.rtol = 1e-17L;
    opts.atol = 1e-19L;
    const auto r = eomgen::integrate_adams(kepler<StateL>, 0.0L, x0, 20.0L, opts);
    const long double r_len = std::hypot(r.x(0), r.x(1));
    const long double h = 0.5L * (r.x(2) * r.x(2) + r.x(3) * r.x(3)) - 1 / r_len;
    const long double h0 = 0.5L * (x0(2) * x0(2) + x0(3) * x0(3)) - 1 / std::hypot(x0(0), x0(1));
    INFO("energy drift " << double(std::abs(h - h0)) << " in " << r.accepted_steps << " steps");
    CHECK(std::abs(h - h0) < 1e-16L);
}

TEST_CASE("Adams reports failures with t and the state", "[runtime][adams]") {
    using V1 = Eigen::Matrix<double, 1, 1>;
    const V1 one = V1::Constant(1.0);
    // x' = x² from x(0) = 1 blows up at t = 1: the step size collapses there.
    const auto blow_up = [](const double&, const V1& x, V1& xdot) { xdot(0) = x(0) * x(0); };
    try {
        eomgen::integrate_adams(blow_up, 0.0, one, 2.0, tolerances(1e-8, 1e-8));
        FAIL("no error thrown");
    } catch (const eomgen::StepSizeUnderflow& err) {
        CHECK(err.t() == Approx(1.0).epsilon(1e-3));
        CHECK(std::string(err.what()).find("with state [") != std::string::npos);
    } catch (const eomgen::NonFiniteState& err) {
        CHECK(err.t() == Approx(1.0).epsilon(1e-3));
    }
    // x' = −1/(2 sqrt(1 − t)) is undefined past t = 1 (NaN): approached, then reported as not finite.
    const auto undefined = [](const double& t, const V1&, V1& xdot) { xdot(0) = -0.5 / std::sqrt(1 - t); };
    try {
        eomgen::integrate_adams(undefined, 0.0, one, 2.0, tolerances(1e-8, 1e-8));
        FAIL("no error thrown");
    } catch (const eomgen::SimulationError& err) {
        CHECK(err.t() == Approx(1.0).epsilon(1e-3));
        CHECK(std::string(err.what()).find(" at t = ") != std::string::npos);
    }
    auto few = tolerances(1e-12, 1e-12);
    few.max_steps = 10;
    const Oscillator<Eigen::Vector2d> osc{1.0};
    CHECK_THROWS_AS(eomgen::integrate_adams(osc, 0.0, Eigen::Vector2d(1, 0), 100.0, few),
                    eomgen::TooManySteps);
    CHECK_THROWS_AS(eomgen::integrate_adams(osc, 0.0, Eigen::Vector2d(std::nan(""), 0), 1.0, few),
                    eomgen::NonFiniteState);
    auto bad = tolerances(1e-8, 0.0);
    CHECK_THROWS_AS(eomgen::integrate_adams(osc, 0.0, Eigen::Vector2d(1, 0), 1.0, bad),
                    std::invalid_argument);
    bad = tolerances(1e-8, 1e-8);
    bad.max_order = 13;
    CHECK_THROWS_AS(eomgen::integrate_adams(osc, 0.0, Eigen::Vector2d(1, 0), 1.0, bad),
                    std::invalid_argument);
    // t_end == t0: nothing to do, no evaluation.
    const auto none = eomgen::integrate_adams(osc, 1.0, Eigen::Vector2d(1, 0), 1.0, tolerances(1e-8, 1e-8));
    CHECK(none.rhs_evaluations == 0);
    CHECK(none.x == Eigen::Vector2d(1, 0));
}
