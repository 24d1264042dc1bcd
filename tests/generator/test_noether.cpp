/** @file test_noether.cpp  Conserved quantities of rotations and translations (mechanics/noether.hpp): found where
 * L, the forces and the constraints have the symmetry, with their closed forms, constant along the equations of
 * motion at random states; nothing reported where there is no symmetry. And Hamilton's equations of a constrained
 * model carrying the multipliers. */
#include "test_paths.hpp"
#include "mechanics/double_evaluator.hpp"
#include "mechanics/hamiltonian.hpp"
#include "mechanics/lagrangian.hpp"
#include "mechanics/noether.hpp"
#include "model/model_file.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace {

const std::string kSource = eomgen_test::source_dir();

std::string coordinates(const std::vector<std::string>& names) {
    std::string s;
    double x = 0.3;
    for (const std::string& n : names) {
        s += "[[coordinates]]\nname = \"" + n + "\"\ninitial = " + std::to_string(x) + "\nrate = 0.2\n";
        x += 0.4;
    }
    return s;
}

std::string parameters(const std::vector<std::string>& names) {
    std::string s;
    for (const std::string& n : names) s += "[[parameters]]\nname = \"" + n + "\"\nvalue = 1.3\n";
    return s;
}

struct Derived {
    eomgen::Model model;
    eomgen::Equations eq;
};

Derived derive(const std::string& text) {
    eomgen::Model m = eomgen::parse_model(text, "noether.toml");
    eomgen::Equations e = eomgen::derive_equations(m);
    return {std::move(m), std::move(e)};
}

std::vector<std::string> names(const eomgen::Equations& eq) {
    std::vector<std::string> out;
    for (const auto& c : eq.conserved) out.push_back(c.name);
    std::sort(out.begin(), out.end());
    return out;
}

const eomgen::ConservedQuantity& quantity(const eomgen::Equations& eq, const std::string& name) {
    const auto it = std::find_if(eq.conserved.begin(), eq.conserved.end(), [&](const auto& c) { return c.name == name; });
    REQUIRE(it != eq.conserved.end());
    return *it;
}

GiNaC::symbol sym(const eomgen::Model& m, const std::string& name, int level = 0) {
    for (const auto& c : m.coordinates)
        if (c.name == name) return level == 0 ? c.q : level == 1 ? c.qd : c.qdd;
    for (const auto& p : m.parameters)
        if (p.name == name) return p.symbol;
    FAIL("no symbol " << name);
    return {};
}

/// dJ/dt along the unconstrained equations M q̈ = f, at random states: 0 for a conserved J.
void constant_along_motion(const Derived& d, const GiNaC::ex& J) {
    const std::size_t n = d.model.dof();
    const GiNaC::ex dJ = eomgen::time_derivative(J, d.model);
    for (unsigned seed = 40; seed < 43; ++seed) {
        GiNaC::exmap at = eomgen::random_point(d.model, seed);
        Eigen::MatrixXd M(n, n);
        Eigen::VectorXd f(n);
        for (unsigned i = 0; i < n; ++i) {
            f(i) = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(d.eq.f[i].subs(at))).to_double();
            for (unsigned j = 0; j < n; ++j)
                M(i, j) = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(d.eq.M(i, j).subs(at))).to_double();
        }
        const Eigen::VectorXd qdd = M.lu().solve(f);
        for (unsigned i = 0; i < n; ++i) at[d.model.coordinates[i].qdd] = qdd(i);
        const double rate = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(dJ.subs(at))).to_double();
        CHECK(std::abs(rate) < 1e-12);
    }
}

}  // namespace

TEST_CASE("noether: a particle held on a sphere, in Cartesian coordinates, keeps L_z (not L_x, L_y: gravity)",
          "[noether]") {
    const Derived d = derive("name = \"on_sphere\"\n" + coordinates({"x", "y", "z"}) + parameters({"m", "R", "g"}) +
                             "[lagrangian]\nT = \"m/2*(x'^2 + y'^2 + z'^2)\"\nV = \"m*g*z\"\n"
                             "[[constraints]]\nname = \"sphere\"\nexpr = \"x^2 + y^2 + z^2 - R^2\"\n");
    CHECK(names(d.eq) == std::vector<std::string>{"L_z", "h"});
    const auto& m = d.model;
    const GiNaC::ex expected = sym(m, "m") * (sym(m, "x") * sym(m, "y", 1) - sym(m, "y") * sym(m, "x", 1));
    CHECK((quantity(d.eq, "L_z").value - expected).expand().is_zero());
    CHECK(quantity(d.eq, "L_z").reason.find("δx = -y, δy = x") != std::string::npos);

    // Hamilton's equations hold the constraint force: p_x' = 2 x λ, p_z' = −m g + 2 z λ.
    const eomgen::Hamiltonian h = eomgen::derive_hamiltonian(d.model, d.eq);
    REQUIRE(h.symbolic);
    REQUIRE(h.lambda.size() == 1);
    CHECK((h.pdot[0] - 2 * sym(m, "x") * h.lambda[0]).expand().is_zero());
    CHECK((h.pdot[2] - (-sym(m, "m") * sym(m, "g") + 2 * sym(m, "z") * h.lambda[0])).expand().is_zero());
}

TEST_CASE("noether: the Kepler problem in Cartesian coordinates keeps its angular momentum", "[noether]") {
    const Derived d = derive("name = \"kepler\"\n" + coordinates({"x", "y"}) + parameters({"m", "k"}) +
                             "[lagrangian]\nT = \"m/2*(x'^2 + y'^2)\"\nV = \"-k/sqrt(x^2 + y^2)\"\n");
    CHECK(names(d.eq) == std::vector<std::string>{"L_z", "h"});
    constant_along_motion(d, quantity(d.eq, "L_z").value);
}

TEST_CASE("noether: a particle in a central field in space keeps all three components", "[noether]") {
    const Derived d = derive("name = \"central3\"\n" + coordinates({"x", "y", "z"}) + parameters({"m", "k"}) +
                             "[lagrangian]\nT = \"m/2*(x'^2 + y'^2 + z'^2)\"\nV = \"k/2*(x^2 + y^2 + z^2)^2\"\n");
    CHECK(names(d.eq) == std::vector<std::string>{"L_x", "L_y", "L_z", "h"});
    for (const char* c : {"L_x", "L_y", "L_z"}) constant_along_motion(d, quantity(d.eq, c).value);
    const auto& m = d.model;
    // L_y = z p_x − x p_z.
    CHECK((quantity(d.eq, "L_y").value -
           sym(m, "m") * (sym(m, "z") * sym(m, "x", 1) - sym(m, "x") * sym(m, "z", 1)))
              .expand()
              .is_zero());
}

TEST_CASE("noether: two carts joined by a spring keep their total momentum", "[noether]") {
    const Derived d = derive("name = \"carts\"\n" + coordinates({"x1", "x2"}) + parameters({"m1", "m2", "k"}) +
                             "[lagrangian]\nT = \"m1/2*x1'^2 + m2/2*x2'^2\"\nV = \"k/2*(x2 - x1)^2\"\n");
    CHECK(names(d.eq) == std::vector<std::string>{"P_x1_x2", "h"});
    const auto& m = d.model;
    const GiNaC::ex P = quantity(d.eq, "P_x1_x2").value;
    const GiNaC::ex expected = sym(m, "m1") * sym(m, "x1", 1) + sym(m, "m2") * sym(m, "x2", 1);
    CHECK(((P - expected).expand().is_zero() || (P + expected).expand().is_zero()));
    constant_along_motion(d, P);
}

TEST_CASE("noether: the heavy top keeps p_phi and p_psi as before, and nothing else", "[noether]") {
    const eomgen::Model m = eomgen::load_model(kSource + "/models/heavy_symmetric_top.toml");
    const eomgen::Equations eq = eomgen::derive_equations(m);
    CHECK(names(eq) == std::vector<std::string>{"h", "p_phi", "p_psi"});
}

TEST_CASE("noether: nothing is reported where there is no symmetry", "[noether]") {
    SECTION("an anisotropic oscillator") {
        const Derived d = derive("name = \"aniso\"\n" + coordinates({"x", "y"}) + parameters({"m", "kx", "ky"}) +
                                 "[lagrangian]\nT = \"m/2*(x'^2 + y'^2)\"\nV = \"kx/2*x^2 + ky/2*y^2\"\n");
        CHECK(names(d.eq) == std::vector<std::string>{"h"});
    }
    SECTION("a central field with drag along x only") {
        const Derived d = derive("name = \"dragged\"\n" + coordinates({"x", "y"}) + parameters({"m", "k", "c"}) +
                                 "[lagrangian]\nT = \"m/2*(x'^2 + y'^2)\"\nV = \"k/2*(x^2 + y^2)\"\n"
                                 "[forces]\nx = \"-c*x'\"\n");
        CHECK(names(d.eq).empty());
    }
    SECTION("the double pendulum and the Cartesian pendulum") {
        for (const char* path : {"/examples/double_pendulum.toml", "/models/pendulum_cartesian.toml"}) {
            const eomgen::Model m = eomgen::load_model(kSource + path);
            const eomgen::Equations eq = eomgen::derive_equations(m);
            INFO(path);
            CHECK(names(eq) == std::vector<std::string>{"h"});
        }
    }
}

TEST_CASE("double evaluator: the value evalf gives, shared nodes and temporaries included", "[noether]") {
    const GiNaC::symbol x("x"), y("y");
    const GiNaC::exmap at{{x, GiNaC::numeric(3, 10)}, {y, GiNaC::numeric(-7, 5)}};
    eomgen::DoubleEvaluator v = eomgen::DoubleEvaluator::at(at);
    const GiNaC::ex shared = GiNaC::sin(x) * GiNaC::exp(y);
    for (const GiNaC::ex& e : {shared + GiNaC::pow(shared, 2) / (1 + x * x), GiNaC::sqrt(x * x + y * y) - GiNaC::Pi * y,
                               GiNaC::atan(y) * GiNaC::cosh(x) + GiNaC::log(x) / GiNaC::pow(y, 3)}) {
        const double expected = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
        REQUIRE(v(e).has_value());
        CHECK(*v(e) == Approx(expected).epsilon(1e-14));
    }
    // Temporaries made and freed one after another must not read each other's values.
    for (int k = 1; k <= 5; ++k) CHECK(*v(GiNaC::ex(x) * k) == Approx(0.3 * k).epsilon(1e-15));
    CHECK_FALSE(v(GiNaC::log(y)).has_value());             // not a real number
    CHECK_FALSE(v(GiNaC::symbol("z") + 1).has_value());   // no value for z
}
