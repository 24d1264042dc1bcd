/** @file test_families.cpp  The n-link model families against pendulums derived by hand. */
#include "mechanics/lagrangian.hpp"
#include "model/families.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

namespace {

eomgen::Model family(const std::string& spec) {
    return eomgen::parse_model(eomgen::family_model_text(eomgen::parse_family_spec(spec)),
                               "--family " + spec);
}

const GiNaC::symbol& parameter(const eomgen::Model& m, const std::string& name) {
    for (const eomgen::Parameter& p : m.parameters)
        if (p.name == name) return p.symbol;
    throw std::logic_error("no parameter " + name);
}

/// a − b with sin²x replaced by 1 − cos²x, expanded: zero exactly when a = b as trigonometric polynomials.
GiNaC::ex difference(const GiNaC::ex& a, const GiNaC::ex& b) {
    const GiNaC::ex x = GiNaC::wild(0);
    return (a - b)
        .expand()
        .subs(GiNaC::pow(GiNaC::sin(x), 2) == 1 - GiNaC::pow(GiNaC::cos(x), 2),
              GiNaC::subs_options::algebraic)
        .expand();
}

}  // namespace

TEST_CASE("family options are read and checked", "[families]") {
    const eomgen::FamilySpec p = eomgen::parse_family_spec("pendulum:n=20");
    REQUIRE(p.family == "pendulum");
    REQUIRE(p.n == 20);
    REQUIRE(eomgen::family_model_name(p) == "pendulum_20");
    REQUIRE(eomgen::parse_family_spec("rods:n=8").family == "rods");
    REQUIRE_THROWS_AS(eomgen::parse_family_spec("pendulum"), std::invalid_argument);
    REQUIRE_THROWS_AS(eomgen::parse_family_spec("pendulum:n=0"), std::invalid_argument);
    REQUIRE_THROWS_AS(eomgen::parse_family_spec("pendulum:n=x"), std::invalid_argument);
    REQUIRE_THROWS_AS(eomgen::parse_family_spec("chain:n=3"), std::invalid_argument);
}

TEST_CASE("the 1-link pendulum family is the simple pendulum", "[families]") {
    const eomgen::Model m = family("pendulum:n=1");
    const eomgen::Equations eq = eomgen::derive_equations(m);
    const GiNaC::ex m1 = parameter(m, "m1"), l1 = parameter(m, "l1"), g = parameter(m, "g");
    const GiNaC::ex th = m.coordinates[0].q;
    // M = m l², f = −m g l sin θ (Goldstein §1.4; θ from the downward vertical).
    REQUIRE(difference(eq.M(0, 0), m1 * l1 * l1).is_zero());
    REQUIRE(difference(eq.f[0], -m1 * g * l1 * GiNaC::sin(th)).is_zero());
}

TEST_CASE("the 2-link pendulum family is the double pendulum derived by hand", "[families]") {
    const eomgen::Model m = family("pendulum:n=2");
    const eomgen::Equations eq = eomgen::derive_equations(m);
    const GiNaC::ex m1 = parameter(m, "m1"), m2 = parameter(m, "m2"), l1 = parameter(m, "l1"),
                    l2 = parameter(m, "l2"), g = parameter(m, "g");
    const GiNaC::ex a = m.coordinates[0].q, b = m.coordinates[1].q;
    const GiNaC::ex ad = m.coordinates[0].qd, bd = m.coordinates[1].qd;
    // By hand: x1 = l1 sin a, y1 = −l1 cos a, x2 = x1 + l2 sin b, y2 = y1 − l2 cos b, so
    // T = (m1 + m2) l1² ȧ²/2 + m2 l2² ḃ²/2 + m2 l1 l2 ȧ ḃ cos(a − b), V = −(m1 + m2) g l1 cos a − m2 g l2 cos
    // b:
    //   M = [[(m1 + m2) l1², m2 l1 l2 cos(a − b)], [m2 l1 l2 cos(a − b), m2 l2²]],
    //   f = [−m2 l1 l2 ḃ² sin(a − b) − (m1 + m2) g l1 sin a,  m2 l1 l2 ȧ² sin(a − b) − m2 g l2 sin b],
    // with cos(a − b) and sin(a − b) written out, since GiNaC does not apply the addition theorems.
    const GiNaC::ex cos_ab = GiNaC::cos(a) * GiNaC::cos(b) + GiNaC::sin(a) * GiNaC::sin(b);
    const GiNaC::ex sin_ab = GiNaC::sin(a) * GiNaC::cos(b) - GiNaC::cos(a) * GiNaC::sin(b);
    REQUIRE(difference(eq.M(0, 0), (m1 + m2) * l1 * l1).is_zero());
    REQUIRE(difference(eq.M(0, 1), m2 * l1 * l2 * cos_ab).is_zero());
    REQUIRE(difference(eq.M(1, 0), m2 * l1 * l2 * cos_ab).is_zero());
    REQUIRE(difference(eq.M(1, 1), m2 * l2 * l2).is_zero());
    REQUIRE(
        difference(eq.f[0], -m2 * l1 * l2 * bd * bd * sin_ab - (m1 + m2) * g * l1 * GiNaC::sin(a)).is_zero());
    REQUIRE(difference(eq.f[1], m2 * l1 * l2 * ad * ad * sin_ab - m2 * g * l2 * GiNaC::sin(b)).is_zero());
}

TEST_CASE("the 1-rod family is the physical pendulum of a uniform rod", "[families]") {
    const eomgen::Model m = family("rods:n=1");
    const eomgen::Equations eq = eomgen::derive_equations(m);
    const GiNaC::ex m1 = parameter(m, "m1"), l1 = parameter(m, "l1"), g = parameter(m, "g");
    // About its end: I = m l²/3, and the centre at l/2 gives f = −m g (l/2) sin θ.
    REQUIRE(difference(eq.M(0, 0), m1 * l1 * l1 / 3).is_zero());
    REQUIRE(difference(eq.f[0], -m1 * g * l1 / 2 * GiNaC::sin(m.coordinates[0].q)).is_zero());
}
