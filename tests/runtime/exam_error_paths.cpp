/** @file exam_error_paths.cpp  Failures are reported as typed errors with t and the state, never as NaN. */
#include "../approx.hpp"

#include "eomgen/errors.hpp"
#include "eomgen/integrate.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using State = Eigen::Vector2d;

void oscillator(const double&, const State& x, State& xdot) {
    xdot(0) = x(1);
    xdot(1) = -x(0);
}

/// "t = <t>" as describe_state writes it.
std::string t_text(double t) {
    std::ostringstream os;
    os << std::setprecision(std::numeric_limits<double>::max_digits10) << "t = " << t;
    return os.str();
}

}  // namespace

TEST_CASE("a right-hand side returning NaN raises NonFiniteState with the time", "[runtime][errors]") {
    const auto nan_rhs = [](const double&, const State&, State& xdot) {
        xdot.setConstant(std::numeric_limits<double>::quiet_NaN());
    };
    try {
        eomgen::integrate(nan_rhs, 0.25, State(1.0, 0.0), 1.0);
        FAIL("no exception");
    } catch (const eomgen::NonFiniteState& e) {
        CHECK(e.t() == 0.25);
        CHECK_THAT(e.what(), Catch::Contains("t = 0.25"));
    }
    CHECK_THROWS_AS(eomgen::integrate_rk4(nan_rhs, 0.25, State(1.0, 0.0), 1.0, 0.1), eomgen::NonFiniteState);

    // NaN only from t = 1 on: the integrator closes in on t = 1 and reports where it stood.
    const auto nan_after_one = [](const double& t, const State& x, State& xdot) {
        oscillator(t, x, xdot);
        if (t >= 1.0) xdot(1) = std::numeric_limits<double>::quiet_NaN();
    };
    try {
        eomgen::integrate(nan_after_one, 0.0, State(1.0, 0.0), 2.0);
        FAIL("no exception");
    } catch (const eomgen::NonFiniteState& e) {
        INFO(e.what());
        CHECK(e.t() < 1.0);
        CHECK(e.t() > 1.0 - 1e-12);
        CHECK_THAT(e.what(), Catch::Contains(t_text(e.t())));
    }
    try {
        eomgen::integrate_rk4(nan_after_one, 0.0, State(1.0, 0.0), 2.0, 0.3);
        FAIL("no exception");
    } catch (const eomgen::NonFiniteState& e) {
        INFO(e.what());
        CHECK(e.t() == Approx(0.9));  // the last finite state, before the step that reached t >= 1
        CHECK_THAT(e.what(), Catch::Contains(t_text(e.t())));
    }
}

TEST_CASE("blow-up x' = x^2 from x(0) = 1 to t = 2 fails loudly near t = 1", "[runtime][errors]") {
    using State1 = Eigen::Matrix<double, 1, 1>;
    const auto blow_up = [](const double&, const State1& x, State1& xdot) { xdot(0) = x(0) * x(0); };
    for (double rtol : {1e-6, 1e-10}) {
        eomgen::Dopri5Options<double> opts;
        opts.rtol = rtol;
        bool typed = false;
        double t_fail = 0;
        std::string what;
        try {
            const auto r = eomgen::integrate(blow_up, 0.0, State1(1.0), 2.0, opts);
            FAIL("returned x = " << r.x(0) << " at t = " << r.t);
        } catch (const eomgen::StepSizeUnderflow& e) {
            typed = true;
            t_fail = e.t();
            what = e.what();
        } catch (const eomgen::NonFiniteState& e) {
            typed = true;
            t_fail = e.t();
            what = e.what();
        }
        // A loose tolerance may step just past the pole before the controller gives up; either way the
        // run ends with a typed error close to t = 1.
        INFO("rtol " << rtol << ": " << what);
        CHECK(typed);
        CHECK(t_fail == Approx(1.0).margin(1e-6));
    }
}

TEST_CASE("max_steps and hmin are enforced", "[runtime][errors]") {
    eomgen::Dopri5Options<double> opts;
    opts.max_steps = 20;
    try {
        eomgen::integrate(oscillator, 0.0, State(1.0, 0.0), 1000.0, opts);
        FAIL("no exception");
    } catch (const eomgen::TooManySteps& e) {
        CHECK(e.t() > 0.0);
        CHECK_THAT(e.what(), Catch::Contains("max_steps = 20") && Catch::Contains(t_text(e.t())));
    }
    eomgen::Dopri5Options<double> tight;
    tight.rtol = 1e-12;
    tight.hmin = 0.1;
    CHECK_THROWS_AS(eomgen::integrate(oscillator, 0.0, State(1.0, 0.0), 10.0, tight),
                    eomgen::StepSizeUnderflow);
}

TEST_CASE("bad arguments and bad event functions are reported", "[runtime][errors]") {
    const std::vector<eomgen::Event<State>> nan_event{
        {"nan", [](const double& t, const State&) { return t > 1 ? std::nan("") : 1.0; }}};
    CHECK_THROWS_AS(eomgen::integrate(oscillator, 0.0, State(1.0, 0.0), 2.0, {}, nan_event),
                    eomgen::NonFiniteState);
    CHECK_THROWS_AS(eomgen::integrate(oscillator, 0.0, State(1.0, 0.0), 2.0, {}, {}, {1.0, 0.5}),
                    std::invalid_argument);
    CHECK_THROWS_AS(eomgen::integrate(oscillator, 0.0, State(1.0, 0.0), 2.0, {}, {}, {3.0}),
                    std::invalid_argument);
    CHECK_THROWS_AS(eomgen::integrate(oscillator, 0.0, State(std::nan(""), 0.0), 2.0),
                    eomgen::NonFiniteState);
    CHECK_THROWS_AS(eomgen::integrate_rk4(oscillator, 0.0, State(1.0, 0.0), 2.0, 0.0), std::invalid_argument);
    eomgen::Dopri5Options<double> relative_only;
    relative_only.atol = 0;
    CHECK_THROWS_AS(eomgen::integrate(oscillator, 0.0, State(1.0, 0.0), 2.0, relative_only),
                    std::invalid_argument);
    // Every runtime error is a SimulationError.
    CHECK_THROWS_AS(eomgen::integrate(oscillator, 0.0, State(std::nan(""), 0.0), 2.0),
                    eomgen::SimulationError);
}
