/** @file test_bodies.cpp  Body-based model files: the 5-20 pendulum and the door from bodies give the same
 * equations as written by hand. */
#include "test_paths.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace {

using GiNaC::ex;

eomgen::Model load(const std::string& name) {
    return eomgen::load_model(eomgen_test::source_dir() + "/models/" + name);
}

/// Each load makes its own symbols: map `from`'s q, q̇, q̈, parameters and t onto `to`'s, by name.
GiNaC::exmap rename(const eomgen::Model& from, const eomgen::Model& to) {
    GiNaC::exmap m{{from.t, to.t}};
    for (const auto& a : from.coordinates)
        for (const auto& b : to.coordinates)
            if (a.name == b.name) {
                m[a.q] = b.q;
                m[a.qd] = b.qd;
                m[a.qdd] = b.qdd;
            }
    for (const auto& a : from.parameters)
        for (const auto& b : to.parameters)
            if (a.name == b.name) m[a.symbol] = b.symbol;
    return m;
}

/// The equations of two models agree: T, V, M, f and the Euler–Lagrange expressions, as identities
/// (eomgen::is_zero: expanded, normal(), else at random points, for sin² + cos² = 1).
void require_same_equations(const eomgen::Model& hand, const eomgen::Model& bodies) {
    REQUIRE(hand.dof() == bodies.dof());
    const eomgen::Equations a = eomgen::derive_equations(hand);
    const eomgen::Equations b = eomgen::derive_equations(bodies);
    const GiNaC::exmap to_hand = rename(bodies, hand);
    auto same = [&](const ex& x, const ex& y) { return eomgen::is_zero(x - y.subs(to_hand), hand); };
    CHECK(same(a.T, b.T));
    CHECK(same(a.V, b.V));
    for (unsigned i = 0; i < hand.dof(); ++i) {
        CHECK(same(a.f[i], b.f[i]));
        CHECK(same(a.euler_lagrange[i], b.euler_lagrange[i]));
        for (unsigned j = 0; j < hand.dof(); ++j) CHECK(same(a.M(i, j), b.M(i, j)));
    }
}

const eomgen::Coordinate& coordinate(const eomgen::Model& m, const std::string& name) {
    for (const auto& c : m.coordinates)
        if (c.name == name) return c;
    throw std::logic_error("no coordinate " + name);
}
ex parameter(const eomgen::Model& m, const std::string& name) {
    for (const auto& p : m.parameters)
        if (p.name == name) return p.symbol;
    throw std::logic_error("no parameter " + name);
}

std::string pendulum_text(const std::string& disk, const std::string& lagrangian) {
    std::string s = "name = \"p\"\n[[coordinates]]\nname = \"theta\"\n[[coordinates]]\nname = \"phi\"\n";
    for (const char* p : {"m", "l", "M", "a", "g"})
        s += std::string("[[parameters]]\nname = \"") + p + "\"\nvalue = 1.0\n";
    return s + lagrangian + "[[bodies]]\nname = \"disk\"\nmass = \"M\"\n" + disk +
           "position = [\"0\", \"l*sin(theta) + a*sin(phi)\", \"-l*cos(theta) - a*cos(phi)\"]\n"
           "[gravity]\nvector = [0, 0, \"-g\"]\n";
}

}  // namespace

TEST_CASE("5-20 pendulum from a rod and a disk: the equations of pendulum_5_20.toml", "[bodies]") {
    const eomgen::Model hand = load("pendulum_5_20.toml");
    const eomgen::Model bodies = load("pendulum_5_20_bodies.toml");
    REQUIRE(bodies.bodies.size() == 2);
    require_same_equations(hand, bodies);

    // Per body: the rod about its end, m l² θ'²/6 and −m g l cos θ/2.
    const eomgen::Equations eq = eomgen::derive_equations(bodies);
    REQUIRE(eq.bodies.size() == 2);
    CHECK(eq.bodies[0].name == "rod");
    const ex m = parameter(bodies, "m"), l = parameter(bodies, "l"), g = parameter(bodies, "g");
    const ex theta = coordinate(bodies, "theta").q, td = coordinate(bodies, "theta").qd;
    CHECK((eq.bodies[0].T - m * l * l * td * td / 6).expand().is_zero());
    CHECK((eq.bodies[0].V + m * g * l * cos(theta) / 2).expand().is_zero());
}

TEST_CASE("door from a plate on a tilted hinge: the equations of door.toml", "[bodies]") {
    const eomgen::Model hand = load("door.toml");
    const eomgen::Model bodies = load("door_bodies.toml");
    require_same_equations(hand, bodies);
    // After the sin² + cos² tidy-up the plate's T is m w² ψ'²/6 term for term, the door's I about its hinge.
    const eomgen::Equations a = eomgen::derive_equations(hand), b = eomgen::derive_equations(bodies);
    CHECK((a.T - b.bodies[0].T.subs(rename(bodies, hand))).expand().is_zero());
    CHECK((a.V - b.bodies[0].V.subs(rename(bodies, hand))).expand().is_zero());
}

TEST_CASE("bodies: explicit inertia and other sequences, and explicit T, V combined with bodies",
          "[bodies]") {
    const eomgen::Model hand = load("pendulum_5_20.toml");
    // The disk's axis along body x with an explicit tensor, turned by phi about x ("xyz").
    const std::string rod_by_hand =
        "[lagrangian]\nT = \"1/6*m*l^2*theta'^2\"\nV = \"-1/2*m*g*l*cos(theta)\"\n";
    const eomgen::Model explicit_inertia =
        eomgen::parse_model(pendulum_text("inertia = [\"M*a^2/2\", \"M*a^2/4\", \"M*a^2/4\"]\norientation = "
                                          "[\"phi\", 0, 0]\nsequence = \"xyz\"\n",
                                          rod_by_hand),
                            "p.toml");
    require_same_equations(hand, explicit_inertia);
    const eomgen::Model full_tensor = eomgen::parse_model(
        pendulum_text("inertia = [[\"M*a^2/4\", 0, 0], [0, \"M*a^2/4\", 0], [0, 0, \"M*a^2/2\"]]\n"
                      "orientation = [\"pi/2\", \"pi/2\", \"phi\"]\n",
                      rod_by_hand),
        "p.toml");
    require_same_equations(hand, full_tensor);
}

TEST_CASE("bodies: errors located in the model file", "[bodies]") {
    const std::string lag = "[lagrangian]\nT = \"1/6*m*l^2*theta'^2\"\n";
    auto error = [&](const std::string& disk) {
        try {
            eomgen::derive_equations(eomgen::parse_model(pendulum_text(disk, lag), "p.toml"));
        } catch (const eomgen::ModelError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK_THAT(error("shape = \"thin_disk\"\ndimensions = [\"a\"]\ninertia = [1, 1, 1]\n"),
               Catch::Contains("either 'shape'") && Catch::StartsWith("p.toml:"));
    CHECK_THAT(error("mass2 = 1\n"), Catch::Contains("unknown key 'mass2' in [[bodies]]"));
    CHECK_THAT(error("shape = \"disc\"\ndimensions = [\"a\"]\n"),
               Catch::Contains("unknown shape 'disc'") && Catch::Contains("thin_disk"));
    CHECK_THAT(error("shape = \"box\"\ndimensions = [\"a\"]\n"),
               Catch::Contains("takes 3 dimension(s), not 1") && Catch::Contains("[a, b, c]"));
    CHECK_THAT(error("shape = \"thin_disk\"\ndimensions = [\"a\"]\nsequence = \"zzx\"\n"),
               Catch::Contains("Euler sequence 'zzx'"));
    CHECK_THAT(error("shape = \"thin_disk\"\ndimensions = [\"a*theta'\"]\n"),
               Catch::Contains("must not depend on velocities"));
    CHECK_THAT(error("shape = \"thin_disk\"\ndimensions = [0.5]\n"),
               Catch::Contains("write decimals as strings"));
    CHECK_THROWS_WITH(eomgen::parse_model("name = \"x\"\n[[coordinates]]\nname = \"q\"\n", "x.toml"),
                      Catch::Contains("or [[bodies]]"));
}
