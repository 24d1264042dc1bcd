/** @file test_constraints.cpp  Constraint Jacobians, gamma, integrability verdicts and the errors on bad constraints. */
#include "test_paths.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace {

/// A model on coordinates x, y, th with T = (x'² + y'² + th'²)/2 and the given constraints (kind, expr).
eomgen::Model with_constraints(const std::vector<std::pair<std::string, std::string>>& constraints) {
    std::string s = "name = \"c\"\n";
    // Initial values where every constraint below is regular (at q = 0 some have a zero gradient, refused).
    for (const char* c : {"x", "y", "th"}) s += std::string("[[coordinates]]\nname = \"") + c + "\"\ninitial = 0.7\n";
    s += "[[parameters]]\nname = \"l\"\nvalue = 1.0\n";
    s += "[lagrangian]\nT = \"1/2*(x'^2 + y'^2 + th'^2)\"\n";
    int k = 0;
    for (const auto& [kind, expr] : constraints)
        s += "[[constraints]]\nname = \"c" + std::to_string(k++) + "\"\nkind = \"" + kind + "\"\nexpr = \"" + expr + "\"\n";
    return eomgen::parse_model(s, "c.toml");
}

}  // namespace

TEST_CASE("holonomic constraint: Jacobian, velocity level and gamma", "[constraints]") {
    const eomgen::Model md = with_constraints({{"holonomic", "x^2 + y^2 - l^2"}});
    const eomgen::Equations eq = eomgen::derive_equations(md);
    REQUIRE(eq.constraints.size() == 1);
    const auto& c = eq.constraints[0];
    const GiNaC::ex x = md.coordinates[0].q, y = md.coordinates[1].q, xd = md.coordinates[0].qd,
                    yd = md.coordinates[1].qd;
    REQUIRE((c.jacobian[0] - 2 * x).expand().is_zero());
    REQUIRE((c.jacobian[1] - 2 * y).expand().is_zero());
    REQUIRE(c.jacobian[2].is_zero());
    REQUIRE(c.bias.is_zero());
    REQUIRE((c.gamma + 2 * (xd * xd + yd * yd)).expand().is_zero());  // d²/dt²(x²+y²) = 2(ẋ²+ẏ²) + 2(xẍ+yÿ)
}

TEST_CASE("integrability: exact, integrable with a factor, and truly nonholonomic", "[constraints][integrability]") {
    // Each in a model of its own: the three together would fix every velocity (no motion left, refused).
    auto alone = [](const std::string& expr) {
        return eomgen::derive_equations(with_constraints({{"nonholonomic", expr}})).constraints[0];
    };
    const auto exact = alone("x' - 2*y*y'");                 // d(x − y²)
    const auto in_x_th = alone("y*x' - x*th'");              // in (x, th): y dx − x dth
    const auto skate = alone("sin(th)*x' - cos(th)*y'");     // the skate
    REQUIRE(exact.exact);
    REQUIRE(exact.integrable);
    REQUIRE_FALSE(in_x_th.exact);
    REQUIRE_FALSE(skate.exact);
    REQUIRE_FALSE(skate.integrable);
    REQUIRE(skate.verdict.find("not integrable") != std::string::npos);
}

TEST_CASE("integrability of y dx - x dth: a 1-form in 3 variables that has no integrating factor", "[constraints]") {
    // ω = y dx − x dθ: dω = dy∧dx − dx∧dθ, ω∧dω = −y dx∧dx∧dθ... = x dθ∧dy∧dx ≠ 0 for x ≠ 0.
    const eomgen::Equations eq = eomgen::derive_equations(with_constraints({{"nonholonomic", "y*x' - x*th'"}}));
    REQUIRE_FALSE(eq.constraints[0].integrable);
    // whereas x dy − y dx (no θ) has the integrating factor 1/x²: d(y/x).
    const eomgen::Equations eq2 = eomgen::derive_equations(with_constraints({{"nonholonomic", "x*y' - y*x'"}}));
    REQUIRE_FALSE(eq2.constraints[0].exact);
    REQUIRE(eq2.constraints[0].integrable);
}

TEST_CASE("Frobenius for two constraints", "[constraints][integrability]") {
    const eomgen::Equations together =
        eomgen::derive_equations(with_constraints({{"nonholonomic", "x'"}, {"nonholonomic", "y' - th'"}}));
    REQUIRE(together.frobenius.find("satisfy the Frobenius condition") != std::string::npos);
    // Each alone is not integrable, but two constraints on three coordinates leave a line field, and a
    // line field always has integral curves: Frobenius must not over-report.
    const eomgen::Equations line = eomgen::derive_equations(
        with_constraints({{"nonholonomic", "x' - sin(th)*y'"}, {"nonholonomic", "th' - cos(th)*y'"}}));
    REQUIRE_FALSE(line.constraints[0].integrable);
    REQUIRE(line.frobenius.find("satisfy the Frobenius condition") != std::string::npos);
}

TEST_CASE("the rolling sphere's constraints are not integrable, as the seed proves", "[constraints][integrability]") {
    const eomgen::Model md = eomgen::load_model(eomgen_test::source_dir() + "/models/rolling_sphere.toml");
    const eomgen::Equations eq = eomgen::derive_equations(md);
    for (const auto& c : eq.constraints) {
        INFO(c.name << ": " << c.verdict);
        REQUIRE_FALSE(c.exact);
        REQUIRE_FALSE(c.integrable);
    }
    REQUIRE(eq.frobenius.find("not integrable") != std::string::npos);
    // φ is cyclic and no constraint involves φ': p_φ = I ω_z is conserved; x, y are cyclic but constrained.
    bool p_phi = false, p_x = false;
    for (const auto& c : eq.conserved) {
        p_phi = p_phi || c.name == "p_phi";
        p_x = p_x || c.name == "p_x";
    }
    REQUIRE(p_phi);
    REQUIRE_FALSE(p_x);
}

TEST_CASE("bad constraints are errors at the constraint", "[constraints][errors]") {
    REQUIRE_THROWS_WITH(eomgen::derive_equations(with_constraints({{"nonholonomic", "x'^2 - y'"}})),
                        Catch::Contains("not linear in the velocities"));
    REQUIRE_THROWS_WITH(eomgen::derive_equations(with_constraints({{"holonomic", "x - y"}, {"holonomic", "3*y - 3*x"}})),
                        Catch::Contains("'c1' is redundant"));
    REQUIRE_THROWS_WITH(eomgen::derive_equations(with_constraints({{"holonomic", "l - 1"}})),
                        Catch::Contains("does not depend on the coordinates"));
    REQUIRE_THROWS_WITH(with_constraints({{"holonomic", "x' - y"}}), Catch::Contains("no velocities"));
    REQUIRE_THROWS_WITH(with_constraints({{"sliding", "x - y"}}), Catch::Contains("neither"));
}

TEST_CASE("forces and dissipation enter f, h and cyclic momenta are not claimed conserved", "[mechanics][forces]") {
    const eomgen::Model md = eomgen::parse_model(
        "[[coordinates]]\nname = \"x\"\n[[coordinates]]\nname = \"y\"\n[[parameters]]\nname = \"c\"\nvalue = 1.0\n"
        "[lagrangian]\nT = \"1/2*(x'^2 + y'^2)\"\nR = \"1/2*c*x'^2\"\n[forces]\ny = \"sin(t)\"\n",
        "f.toml");
    const eomgen::Equations eq = eomgen::derive_equations(md);
    const GiNaC::ex c = md.parameters[0].symbol;
    REQUIRE((eq.f[0] + c * md.coordinates[0].qd).expand().is_zero());
    REQUIRE((eq.f[1] - GiNaC::sin(md.t)).expand().is_zero());
    REQUIRE(eq.conserved.empty());
}
