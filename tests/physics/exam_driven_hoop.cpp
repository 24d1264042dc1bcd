/** @file exam_driven_hoop.cpp  A coordinate driven by a rheonomic constraint whose own inertia vanishes
 * (the hoop's angle, where the bead is on the axis): the constrained system is regular although M is
 * singular there. Against the same bead with the spin substituted into T (examples/bead_on_hoop.toml). */
#include "eomgen/constraints.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/models/bead_on_hoop.hpp"
#include "eomgen/models/hoop_driven.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace {

using Driven = eomgen::models::hoop_driven::Model<double>;
using Substituted = eomgen::models::bead_on_hoop::Model<double>;

eomgen::Dopri5Options<double> tight() {
    eomgen::Dopri5Options<double> o;
    o.rtol = 1e-12;
    o.atol = 1e-14;
    o.max_steps = 10000000;
    return o;
}

}  // namespace

TEST_CASE("driven hoop: M is singular on the axis, the constrained solve is not", "[physics][constraints]") {
    Driven::Params p;
    Driven::State x = Driven::default_state();  // a = 0: the bead on the axis, sin a = 0
    Driven::MassMatrix M;
    Driven::mass_matrix(0.0, x.head<Driven::nq>(), p, M);
    REQUIRE(M(1, 1) == 0.0);
    Driven::State xdot;
    REQUIRE_NOTHROW(Driven::rhs(0.0, x, p, xdot));
    // On the axis the bead feels neither gravity's torque nor the centrifugal one: a'' = 0, and the
    // hoop turns at its prescribed rate (phi'' = 0).
    CHECK(xdot(0) == Approx(x(2)));
    CHECK(xdot(2) == Approx(0.0).margin(1e-12));
    CHECK(xdot(3) == Approx(0.0).margin(1e-12));
}

TEST_CASE("driven hoop: the same motion as the bead with the spin substituted, through the axis",
          "[physics][constraints]") {
    Driven::Params pd;
    Substituted::Params ps;
    REQUIRE(pd.w == ps.w);
    REQUIRE(pd.R == ps.R);
    std::vector<double> times;
    for (int k = 1; k <= 100; ++k) times.push_back(0.05 * k);
    const auto rd = eomgen::integrate_constrained<Driven>(pd, 0.0, Driven::default_state(), times, tight());
    Substituted::State s0;
    s0 << 0.0, 2.0;  // the driven model's a and a'
    auto f = [&ps](const double& t, const Substituted::State& x, Substituted::State& xdot) {
        Substituted::rhs(t, x, ps, xdot);
    };
    const auto rs = eomgen::integrate(f, 0.0, s0, times.back(), tight(), {}, times);
    REQUIRE(rs.samples.size() == times.size());
    int crossings = 0;
    for (std::size_t k = 0; k < times.size(); ++k) {
        const auto& d = rd.run.samples[k + 1];  // sample 0 is t = 0
        const auto& s = rs.samples[k];
        REQUIRE(d.t == s.t);
        INFO("t = " << d.t);
        CHECK(d.x(0) == Approx(s.x(0)).margin(1e-8));   // a
        CHECK(d.x(2) == Approx(s.x(1)).margin(1e-7));   // a'
        CHECK(d.x(1) == Approx(pd.w * d.t).margin(1e-9));  // phi = w t
        if (k > 0 && std::signbit(d.x(0)) != std::signbit(rd.run.samples[k].x(0))) ++crossings;
    }
    CHECK(crossings >= 2);  // the bead passed the axis, where M is singular
    CHECK(rd.max_position_residual <= 1e-10);
}
