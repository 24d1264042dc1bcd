/** @file exam_door.cpp  Goldstein ch. 5 Ex. 30: the tilted door's closing time and speed against the closed form. */
#include "eomgen/integrate.hpp"
#include "eomgen/models/door.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

namespace {

using Door = eomgen::models::door::Model<double>;
const double kPi = std::acos(-1.0);

/// ∫₀^{π/2} dψ / √(sin ψ) = (√π/2) Γ(1/4)/Γ(3/4) = 2.6220575542921198...: the closing-time integral.
double closing_integral() { return std::sqrt(kPi) / 2 * std::tgamma(0.25) / std::tgamma(0.75); }

struct Closing {
    double t;        ///< time from ψ = 0 to ψ = −π/2
    double psi_dot;  ///< ψ̇ there
    std::size_t rhs_evaluations;
};

/// Lets the door go from rest at ψ = 0 and stops at ψ = −π/2 by event location on the dense output of the
/// adaptive stepper Method.
template <template <class> class Method = eomgen::Dopri5>
Closing simulate_closing(const Door::Params& p, double rtol = 1e-13, double atol = 1e-15) {
    Door::State x0 = Door::State::Zero();
    auto f = [&p](const double& t, const Door::State& x, Door::State& xdot) { Door::rhs(t, x, p, xdot); };
    eomgen::Event<Door::State> shut{"shut", [](const double&, const Door::State& x) { return x(0) + kPi / 2; },
                                    eomgen::EventDirection::Falling, eomgen::EventAction::Stop};
    typename Method<Door::State>::Options opt;
    opt.rtol = rtol;
    opt.atol = atol;
    const auto r = eomgen::integrate_with<Method>(f, 0.0, x0, 100.0, opt, {shut});
    REQUIRE(r.stop_reason == eomgen::StopReason::TerminalEvent);
    REQUIRE(r.stopped_by == "shut");
    return {r.t, r.x(1), r.rhs_evaluations};
}

}  // namespace

TEST_CASE("door: closing time and final speed match the closed form to 1e-9", "[physics][door][events]") {
    // Energy: (1/6) m w² ψ̇² = −(m g/2) w sin θ sin ψ, so ψ̇_f = √(3 g sin θ / w) and
    // Δt = √(w / (3 g sin θ)) ∫₀^{π/2} dψ/√(sin ψ).
    for (const double theta : {0.0234, 0.1, 0.5, kPi / 2})
        for (const double w : {0.9, 1.3}) {
            Door::Params p;
            p.theta = theta;
            p.w = w;
            p.g = 9.8;
            const Closing c = simulate_closing(p);
            const double dt_exact = closing_integral() * std::sqrt(w / (3 * p.g * std::sin(theta)));
            const double speed_exact = std::sqrt(3 * p.g * std::sin(theta) / w);
            INFO("theta = " << theta << ", w = " << w);
            REQUIRE(c.t == Approx(dt_exact).epsilon(1e-9));
            REQUIRE(-c.psi_dot == Approx(speed_exact).epsilon(1e-9));
            // The seed's 1.51 is 2.6220575542/√3 = 1.5138...: Δt = 1.5138 √(w/(g sin θ)).
            REQUIRE(c.t / std::sqrt(w / (p.g * std::sin(theta))) == Approx(1.5138).epsilon(1e-4));
        }
}

/// The largest relative error of the closing time over a grid of tilts and widths, with Method at rtol, atol,
/// against the closed form in long double (so that its own rounding stays far below the errors checked).
template <template <class> class Method>
double worst_closing_error(double rtol, double atol) {
    const long double pi = 3.141592653589793238462643383279502884L;
    const long double integral = std::sqrt(pi) / 2 * std::tgamma(0.25L) / std::tgamma(0.75L);
    double worst = 0;
    for (const double theta : {0.0234, 0.1, kPi / 2})
        for (const double w : {0.9, 1.3}) {
            Door::Params p;
            p.theta = theta;
            p.w = w;
            p.g = 9.8;
            const Closing c = simulate_closing<Method>(p, rtol, atol);
            const long double dt_exact = integral * std::sqrt(w / (3 * p.g * std::sin((long double)theta)));
            const double rel = double(std::abs(c.t - dt_exact) / dt_exact);
            UNSCOPED_INFO("theta = " << theta << ", w = " << w << ": relative error " << rel << " with "
                                     << c.rhs_evaluations << " evaluations of f");
            worst = std::max(worst, rel);
        }
    return worst;
}

TEST_CASE("door: DOP853 gets the closing time to 1e-13 of the closed form at rtol 1e-14", "[physics][door][dop853]") {
    CHECK(worst_closing_error<eomgen::Dop853>(1e-14, 1e-16) <= 1e-13);
}

TEST_CASE("door: variable-order Adams gets the closing time to 1e-13 of the closed form at rtol 1e-14",
          "[physics][door][adams]") {
    // Located by the terminal event on the interpolating polynomial of the last step.
    CHECK(worst_closing_error<eomgen::Adams>(1e-14, 1e-16) <= 1e-13);
}

TEST_CASE("door: a 3 s closing of a 0.9 m door means a hinge tilt of about 1.34 degrees", "[physics][door]") {
    // Find θ with a closing time of 3 s from the simulation alone (secant on θ), then compare.
    Door::Params p;
    p.w = 0.9;
    p.g = 9.8;
    auto closing_time = [&p](double theta) {
        Door::Params q = p;
        q.theta = theta;
        return simulate_closing(q, 1e-12).t - 3.0;
    };
    double a = 0.01, b = 0.05, fa = closing_time(a), fb = closing_time(b);
    for (int i = 0; i < 50 && std::abs(fb) > 1e-12; ++i) {
        const double c = b - fb * (b - a) / (fb - fa);
        a = b;
        fa = fb;
        b = c;
        fb = closing_time(b);
    }
    const double theta_deg = b * 180 / kPi;
    const double exact = std::asin(p.w / p.g * std::pow(closing_integral() / std::sqrt(3.0) / 3.0, 2)) * 180 / kPi;
    REQUIRE(theta_deg == Approx(exact).epsilon(1e-8));
    REQUIRE(theta_deg == Approx(1.34).margin(0.005));
}

TEST_CASE("door: energy is conserved along the closing", "[physics][door]") {
    Door::Params p;
    p.theta = 0.3;
    Door::State x0 = Door::State::Zero();
    auto f = [&p](const double& t, const Door::State& x, Door::State& xdot) { Door::rhs(t, x, p, xdot); };
    eomgen::Dopri5Options<double> opt;
    opt.rtol = 1e-12;
    opt.atol = 1e-14;
    std::vector<double> times;
    for (int k = 0; k <= 100; ++k) times.push_back(0.2 * k);
    const auto r = eomgen::integrate(f, 0.0, x0, 20.0, opt, {}, times);
    const double h0 = Door::energy(0, x0.head<1>(), x0.tail<1>(), p);
    for (const auto& s : r.samples)
        REQUIRE(Door::energy(s.t, s.x.head<1>(), s.x.tail<1>(), p) == Approx(h0).epsilon(1e-10));
}
