/** @file test_tops.cpp  Rigid bodies of the seed from body descriptions: heavy top's steady precession, the
 * rolling cone's T (5-17). */
#include "test_paths.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

namespace {

using GiNaC::ex;

ex symbol_of(const eomgen::Model& m, const std::string& name) {
    for (const auto& p : m.parameters)
        if (p.name == name) return p.symbol;
    throw std::logic_error("no parameter " + name);
}
const eomgen::Coordinate& coordinate(const eomgen::Model& m, const std::string& name) {
    for (const auto& c : m.coordinates)
        if (c.name == name) return c;
    throw std::logic_error("no coordinate " + name);
}

}  // namespace

TEST_CASE("heavy symmetric top: steady precession obeys I cos(theta) phi'^2 - I3 w3 phi' + M g l = 0",
          "[bodies][top]") {
    const eomgen::Model md = eomgen::load_model(eomgen_test::source_dir() + "/models/heavy_symmetric_top.toml");
    const eomgen::Equations eq = eomgen::derive_equations(md);
    const auto &phi = coordinate(md, "phi"), &theta = coordinate(md, "theta"), &psi = coordinate(md, "psi");
    const ex M = symbol_of(md, "M"), l = symbol_of(md, "l"), g = symbol_of(md, "g"), I1 = symbol_of(md, "I1"),
             I3 = symbol_of(md, "I3");
    const ex I = I1 + M * l * l, w3 = psi.qd + phi.qd * cos(theta.q);
    // Steady precession: theta' = 0 and no accelerations.
    const GiNaC::exmap steady{{theta.qd, 0}, {phi.qdd, 0}, {theta.qdd, 0}, {psi.qdd, 0}};
    unsigned k = 0;
    while (md.coordinates[k].name != "theta") ++k;
    const ex el_theta = eq.euler_lagrange[k].subs(steady);
    // Euler angles are singular at sin(theta) = 0, reported as a warning.
    REQUIRE(eq.warnings.size() == 1);
    CHECK(eq.warnings[0].find("det M = 0 where sin(theta) = 0") != std::string::npos);
    CHECK(eomgen::is_zero(
        el_theta + sin(theta.q) * (I * cos(theta.q) * phi.qd * phi.qd - I3 * w3 * phi.qd + M * g * l), md));

    // The slow and fast roots at the model's defaults make the theta equation vanish.
    GiNaC::exmap values;
    for (const auto& p : md.parameters) values[p.symbol] = p.value;
    const double th = 0.6, w3v = 100.0;  // fast enough for real roots: I3² w3² > 4 I cos(theta) M g l
    const double Iv = 0.0004 + 0.5 * 0.05 * 0.05, I3v = 0.0006, Mgl = 0.5 * 9.81 * 0.05;
    const double disc = std::sqrt(I3v * I3v * w3v * w3v - 4 * Iv * std::cos(th) * Mgl);
    for (const double rate :
         {(I3v * w3v - disc) / (2 * Iv * std::cos(th)), (I3v * w3v + disc) / (2 * Iv * std::cos(th))}) {
        values[theta.q] = th;
        values[phi.qd] = rate;
        values[psi.qd] = w3v - rate * std::cos(th);
        const double r = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(el_theta.subs(values))).to_double();
        CHECK(r == Approx(0.0).margin(1e-12));
    }
}

TEST_CASE("5-17 rolling cone: T = 3 M h^2 theta'^2 (1 + 5 cos^2 alpha) / 40", "[bodies][cone]") {
    // Apex fixed at the origin, the line of contact at angle theta in the table z = 0, the axis
    // (cos a cos theta, cos a sin theta, sin a) in z-x-z angles (theta + pi/2, pi/2 - a, psi). Rolling
    // makes the contact line the instantaneous axis: omega_z = theta' + psi' sin a = 0, integrated as
    // psi = -theta/sin(a). Centre of mass 3h/4 from the apex along the axis.
    const eomgen::Model md = eomgen::parse_model(R"toml(
name = "rolling_cone"
[[coordinates]]
name = "theta"
[[parameters]]
name = "M"
value = 1.0
[[parameters]]
name = "h"
value = 1.0
[[parameters]]
name = "alpha"
value = 0.4
[[bodies]]
name = "cone"
mass = "M"
shape = "solid_cone"
dimensions = ["h*sin(alpha)/cos(alpha)", "h"]
position = ["3*h/4*cos(alpha)*cos(theta)", "3*h/4*cos(alpha)*sin(theta)", "3*h/4*sin(alpha)"]
orientation = ["theta + pi/2", "pi/2 - alpha", "-theta/sin(alpha)"]
)toml",
                                                 "cone.toml");
    const eomgen::Equations eq = eomgen::derive_equations(md);
    const ex M = symbol_of(md, "M"), h = symbol_of(md, "h"), a = symbol_of(md, "alpha");
    const ex td = md.coordinates[0].qd;
    REQUIRE(eq.bodies.size() == 1);
    CHECK(eomgen::is_zero(eq.bodies[0].T - 3 * M * h * h * td * td * (1 + 5 * pow(cos(a), 2)) / 40, md));
}
