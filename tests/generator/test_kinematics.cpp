/** @file test_kinematics.cpp  Euler-angle kinematics: Goldstein (4.87), ω from Ȧ Aᵀ for every sequence, the
 * rolling sphere. */
#include "test_paths.hpp"
#include "mechanics/kinematics.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace {

using GiNaC::ex;
using GiNaC::matrix;

/// A model with coordinates phi, theta, psi (and time t) to differentiate along.
eomgen::Model angles_model() {
    return eomgen::parse_model(
        "name = \"angles\"\n[[coordinates]]\nname = \"phi\"\n[[coordinates]]\nname = \"theta\"\n"
        "[[coordinates]]\nname = \"psi\"\n[[parameters]]\nname = \"l\"\nvalue = 1.0\n"
        "[lagrangian]\nT = \"phi'^2 + theta'^2 + psi'^2\"\n",
        "angles.toml");
}

bool same(const matrix& a, const matrix& b, const eomgen::Model& model) {
    for (unsigned i = 0; i < a.rows(); ++i)
        for (unsigned j = 0; j < a.cols(); ++j)
            if (!eomgen::is_zero(a(i, j) - b(i, j), model)) return false;
    return true;
}

bool same_exactly(const matrix& a, const matrix& b) {
    for (unsigned i = 0; i < a.rows(); ++i)
        for (unsigned j = 0; j < a.cols(); ++j)
            if (!(a(i, j) - b(i, j)).expand().is_zero()) return false;
    return true;
}

}  // namespace

TEST_CASE("z-x-z angular velocity is Goldstein (4.87) in body axes and its space-axis twin", "[kinematics]") {
    const eomgen::Model md = angles_model();
    const ex phi = md.coordinates[0].q, theta = md.coordinates[1].q, psi = md.coordinates[2].q;
    const ex pd = md.coordinates[0].qd, td = md.coordinates[1].qd, sd = md.coordinates[2].qd;
    const matrix body = eomgen::body_angular_velocity({phi, theta, psi}, md);
    CHECK(same_exactly(body, matrix{{pd * sin(theta) * sin(psi) + td * cos(psi)},
                                    {pd * sin(theta) * cos(psi) - td * sin(psi)},
                                    {pd * cos(theta) + sd}}));
    const matrix space = eomgen::space_angular_velocity({phi, theta, psi}, md);
    CHECK(same_exactly(space, matrix{{td * cos(phi) + sd * sin(theta) * sin(phi)},
                                     {td * sin(phi) - sd * sin(theta) * cos(phi)},
                                     {pd + sd * cos(theta)}}));
    // Goldstein (4.46): A = BCD, its last row the body z axis in space components.
    const matrix A = eomgen::euler_rotation({phi, theta, psi});
    CHECK((A(2, 0) - sin(theta) * sin(phi)).expand().is_zero());
    CHECK((A(2, 1) + sin(theta) * cos(phi)).expand().is_zero());
    CHECK((A(2, 2) - cos(theta)).expand().is_zero());
}

TEST_CASE("every Euler sequence: composed ω equals the one from [ω']x = A Ȧᵀ, and ω = Aᵀ ω'",
          "[kinematics]") {
    const eomgen::Model md = angles_model();
    const std::array<ex, 3> angles = {md.coordinates[0].q, md.coordinates[1].q, md.coordinates[2].q};
    int sequences = 0;
    for (const char* seq :
         {"xyx", "xyz", "xzx", "xzy", "yxy", "yxz", "yzx", "yzy", "zxy", "zxz", "zyx", "zyz"}) {
        INFO(seq);
        REQUIRE(eomgen::valid_euler_sequence(seq));
        ++sequences;
        const matrix A = eomgen::euler_rotation(angles, seq);
        const matrix A_dot = eomgen::time_derivative(A, md);
        const matrix body = eomgen::body_angular_velocity(angles, md, seq);
        CHECK(same(body, eomgen::body_angular_velocity_from_rotation(A, A_dot), md));
        CHECK(same(eomgen::space_angular_velocity(angles, md, seq), A.transpose().mul(body), md));
        CHECK(same(A.mul(A.transpose()), matrix{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, md));
    }
    CHECK(sequences == 12);
    CHECK_FALSE(eomgen::valid_euler_sequence("zzx"));
    CHECK_THROWS_WITH(eomgen::euler_rotation(angles, "zxx"), Catch::Contains("no axis twice in a row"));
}

TEST_CASE("rolling sphere (Ex. 25): T and the no-slip constraints rebuilt from the kinematics",
          "[kinematics]") {
    const eomgen::Model md = eomgen::load_model(eomgen_test::source_dir() + "/models/rolling_sphere.toml");
    auto q = [&](const std::string& name) -> const eomgen::Coordinate& {
        for (const auto& c : md.coordinates)
            if (c.name == name) return c;
        FAIL("no coordinate " << name);
        return md.coordinates[0];
    };
    auto p = [&](const std::string& name) -> ex {
        for (const auto& c : md.parameters)
            if (c.name == name) return c.symbol;
        return 0;
    };
    const matrix w = eomgen::space_angular_velocity({q("phi").q, q("theta").q, q("psi").q}, md);
    const matrix v = eomgen::time_derivative(matrix{{q("x").q}, {q("y").q}, {p("R")}}, md);
    const ex m = p("m"), I = p("I"), R = p("R");
    const ex w2 = w(0, 0) * w(0, 0) + w(1, 0) * w(1, 0) + w(2, 0) * w(2, 0);
    const ex v2 = v(0, 0) * v(0, 0) + v(1, 0) * v(1, 0) + v(2, 0) * v(2, 0);
    CHECK(eomgen::is_zero(m * v2 / 2 + I * w2 / 2 - md.T.expr, md));
    // Contact point at (0, 0, −R) from the centre: v + ω × (0, 0, −R) = 0; roll_x is its −x, roll_y its y.
    const matrix slip = v.add(eomgen::skew(w).mul(matrix{{0}, {0}, {-R}}));
    REQUIRE(md.constraints.size() == 2);
    CHECK((slip(0, 0) + md.constraints[0].expr.expr).expand().is_zero());
    CHECK((slip(1, 0) - md.constraints[1].expr.expr).expand().is_zero());
    CHECK(slip(2, 0).is_zero());
}

TEST_CASE("a point of a body: the pendulum bob's position and speed", "[kinematics]") {
    const eomgen::Model md = angles_model();
    const ex theta = md.coordinates[1].q, td = md.coordinates[1].qd, l = md.parameters[0].symbol;
    // A body turned by theta about the space x axis ("xyz" with only the first angle); the bob at body (0, 0,
    // −l).
    const matrix A = eomgen::euler_rotation({theta, 0, 0}, "xyz");
    const matrix r = eomgen::point_position(matrix{{0}, {0}, {0}}, A, matrix{{0}, {0}, {-l}});
    CHECK(same_exactly(r, matrix{{0}, {l * sin(theta)}, {-l * cos(theta)}}));
    const matrix v = eomgen::time_derivative(r, md);
    CHECK(eomgen::is_zero(v(0, 0) * v(0, 0) + v(1, 0) * v(1, 0) + v(2, 0) * v(2, 0) - l * l * td * td, md));
}
