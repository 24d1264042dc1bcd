/** @file test_lagrangian.cpp  Euler–Lagrange derivation: known answers and the checks on T. */
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace {

/// A one-file model with the given coordinates (names), parameters (names) and T, V.
std::string model_text(const std::vector<std::string>& coords, const std::string& T, const std::string& V,
                       const std::vector<std::string>& params = {"m", "g", "l", "k"}) {
    std::string s = "name = \"test\"\n";
    for (const std::string& c : coords) s += "[[coordinates]]\nname = \"" + c + "\"\n";
    for (const std::string& p : params) s += "[[parameters]]\nname = \"" + p + "\"\nvalue = 1.0\n";
    s += "[lagrangian]\nT = \"" + T + "\"\nV = \"" + V + "\"\n";
    return s;
}

eomgen::Equations derive(const std::string& text) {
    return eomgen::derive_equations(eomgen::parse_model(text, "test.toml"));
}

}  // namespace

TEST_CASE("simple pendulum: m l² θ̈ + m g l sin θ = 0", "[mechanics]") {
    const eomgen::Model md = eomgen::parse_model(model_text({"th"}, "1/2*m*l^2*th'^2", "-m*g*l*cos(th)"), "p.toml");
    const eomgen::Equations eq = eomgen::derive_equations(md);
    const GiNaC::ex m = md.parameters[0].symbol, g = md.parameters[1].symbol, l = md.parameters[2].symbol;
    const auto& th = md.coordinates[0];
    REQUIRE((eq.M(0, 0) - m * l * l).expand().is_zero());
    REQUIRE((eq.f[0] + m * g * l * GiNaC::sin(th.q)).expand().is_zero());
    REQUIRE((eq.energy - (m * l * l * th.qd * th.qd / 2 - m * g * l * GiNaC::cos(th.q))).expand().is_zero());
    REQUIRE(eq.conserved.size() == 1);
}

TEST_CASE("a cyclic coordinate conserves its momentum", "[mechanics]") {
    // Central force in the plane: φ is cyclic, p_φ = m r² φ̇.
    const eomgen::Model md =
        eomgen::parse_model(model_text({"r", "ph"}, "1/2*m*(r'^2 + r^2*ph'^2)", "1/2*k*r^2"), "c.toml");
    const eomgen::Equations eq = eomgen::derive_equations(md);
    REQUIRE(eq.cyclic == std::vector<bool>{false, true});
    REQUIRE(eq.conserved.size() == 2);
    REQUIRE(eq.conserved[1].name == "p_ph");
    const GiNaC::ex m = md.parameters[0].symbol;
    const GiNaC::ex r = md.coordinates[0].q;
    REQUIRE((eq.conserved[1].value - m * r * r * md.coordinates[1].qd).expand().is_zero());
}

TEST_CASE("explicit time dependence: h is not listed as conserved", "[mechanics]") {
    // A pendulum whose length is driven: l(t) = l (1 + sin t)/2 ... enters T through a parameter of t.
    const eomgen::Equations eq = derive(model_text({"th"}, "1/2*m*(l*(2 + sin(t)))^2*th'^2", "-m*g*l*cos(th)"));
    REQUIRE(eq.explicit_time);
    REQUIRE(eq.conserved.empty());
}

TEST_CASE("gyroscopic (linear-in-velocity) terms enter f, not M", "[mechanics]") {
    // Charged particle in a uniform magnetic field, symmetric gauge: L = m v²/2 + (qB/2)(x ẏ − y ẋ).
    const eomgen::Model md =
        eomgen::parse_model(model_text({"x", "y"}, "1/2*m*(x'^2 + y'^2) + k/2*(x*y' - y*x')", "0"), "b.toml");
    const eomgen::Equations eq = eomgen::derive_equations(md);
    const GiNaC::ex m = md.parameters[0].symbol, k = md.parameters[3].symbol;
    REQUIRE((eq.M(0, 0) - m).expand().is_zero());
    REQUIRE(eq.M(0, 1).is_zero());
    REQUIRE((eq.f[0] - k * md.coordinates[1].qd).expand().is_zero());   // m ẍ = k ẏ
    REQUIRE((eq.f[1] + k * md.coordinates[0].qd).expand().is_zero());   // m ÿ = −k ẋ
}

TEST_CASE("T that is not quadratic in the velocities is an error at T", "[mechanics][errors]") {
    const std::string text = model_text({"x"}, "m*x'^3", "0");
    try {
        derive(text);
        FAIL("no error");
    } catch (const eomgen::ModelError& e) {
        INFO(e.what());
        REQUIRE(std::string(e.what()).find("test.toml:") == 0);
        REQUIRE(std::string(e.what()).find("quadratic") != std::string::npos);
        REQUIRE(e.where().line > 0);
    }
    REQUIRE_THROWS_AS(derive(model_text({"x"}, "m*sin(x')", "0")), eomgen::ModelError);
    REQUIRE_THROWS_AS(derive(model_text({"x"}, "m*sqrt(1 + x'^2)", "0")), eomgen::ModelError);
}

TEST_CASE("an identically singular mass matrix is an error that names the missing velocity", "[mechanics][errors]") {
    // T does not involve y' at all (y is in V: a coordinate in nothing at all is another error); and a T in
    // (x' + y')² only has rank 1.
    for (const std::string& T : {std::string("1/2*m*x'^2"), std::string("1/2*m*(x' + y')^2")}) {
        try {
            derive(model_text({"x", "y"}, T, "m*y"));
            FAIL("no error for T = " << T);
        } catch (const eomgen::ModelError& e) {
            INFO(e.what());
            REQUIRE(std::string(e.what()).find("singular") != std::string::npos);
            REQUIRE(std::string(e.what()).find("y'") != std::string::npos);
        }
    }
}

TEST_CASE("a mass matrix singular only at some q is accepted", "[mechanics]") {
    // Spherical pendulum: M = diag(m l², m l² sin² θ) is singular at θ = 0 only.
    REQUIRE_NOTHROW(derive(model_text({"th", "ph"}, "1/2*m*l^2*(th'^2 + sin(th)^2*ph'^2)", "-m*g*l*cos(th)")));
}

TEST_CASE("is_zero sees through trigonometric identities numerically", "[mechanics]") {
    const eomgen::Model md = eomgen::parse_model(model_text({"x"}, "1/2*m*x'^2", "0"), "z.toml");
    const GiNaC::ex x = md.coordinates[0].q;
    REQUIRE(eomgen::is_zero(GiNaC::pow(GiNaC::sin(x), 2) + GiNaC::pow(GiNaC::cos(x), 2) - 1, md));
    REQUIRE_FALSE(eomgen::is_zero(GiNaC::pow(GiNaC::sin(x), 2) - GiNaC::pow(GiNaC::cos(x), 2), md));
}
