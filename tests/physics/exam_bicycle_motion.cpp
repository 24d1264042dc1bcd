/** @file exam_bicycle_motion.cpp  The Whipple bicycle's full nonlinear equations (models/whipple_bicycle.toml):
 *  uncontrolled at 5 m/s, between the weave and capsize speeds, it rights itself after a sideways push; energy and
 *  the five contact constraints are kept to the integrator's tolerance. */
#include "eomgen/constraints.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/models/whipple_bicycle.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using Bike = eomgen::models::whipple_bicycle::Model<double>;

TEST_CASE("bicycle: at 5 m/s a roll push dies out, energy and the contacts kept over 10 s", "[physics][bicycle]") {
    const Bike::Params p;
    Bike::State x0 = Bike::default_state();  // upright, x' = v, the wheels rolling at -v/r
    x0(Bike::nq + 3) = 0.5;                   // phi': a push sideways, 0.5 rad/s
    eomgen::Dopri5Options<double> o;
    o.rtol = 1e-12;
    o.atol = 1e-14;
    o.max_steps = 10000000;
    std::vector<double> times;
    for (int k = 1; k <= 200; ++k) times.push_back(10.0 * k / 200);
    const auto r = eomgen::integrate_constrained<Bike>(p, 0.0, x0, times, o, /*project_initial=*/true);
    REQUIRE(r.run.samples.size() == 201);
    const auto& first = r.run.samples.front().x;
    const double h0 = Bike::energy(0, first.head<Bike::nq>(), first.tail<Bike::nq>(), p);
    double drift = 0, max_roll = 0;
    for (const auto& s : r.run.samples) {
        drift = std::max(drift, std::abs(Bike::energy(s.t, s.x.head<Bike::nq>(), s.x.tail<Bike::nq>(), p) / h0 - 1));
        max_roll = std::max(max_roll, std::abs(s.x(3)));
    }
    CHECK(drift < 1e-9);
    CHECK(r.max_position_residual < 1e-10);
    CHECK(r.max_velocity_residual < 1e-10);
    const auto& last = r.run.samples.back().x;
    CHECK(max_roll > 0.02);                          // it did lean
    CHECK(std::abs(last(3)) < 0.05 * max_roll);      // and came back upright (slowest mode: e^(-0.32 t))
    CHECK(std::abs(last(Bike::nq + 3)) < 0.05 * 0.5);
    CHECK(-last(Bike::nq + 5) * p.rR == Approx(5.0).epsilon(0.02));  // the rear wheel still rolls at about 5 m/s
}
