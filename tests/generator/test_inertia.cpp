/** @file test_inertia.cpp  Inertia tensors: the 5-15 triangle, every shape against an independent
 * integration, parallel axes, principal axes. */
#include "mechanics/inertia.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <cmath>

namespace {

using GiNaC::ex;
using GiNaC::matrix;
using GiNaC::numeric;
using GiNaC::symbol;

bool same(const matrix& a, const matrix& b) {
    if (a.rows() != b.rows() || a.cols() != b.cols()) return false;
    for (unsigned i = 0; i < a.rows(); ++i)
        for (unsigned j = 0; j < a.cols(); ++j)
            if (!(a(i, j) - b(i, j)).normal().is_zero()) return false;
    return true;
}

matrix column(const ex& a, const ex& b, const ex& c) {
    return matrix{{a}, {b}, {c}};
}

/// An axisymmetric body (axis z) integrated independently of integrate_mass_properties, in cylindrical
/// coordinates: a ring of radius s weighs 2π s ρ ds dz, contributes s² to I_zz and s²/2 + z² to I_xx.
/// Returns diag(I_xx, I_xx, I_zz) about the centre of mass. `solid` false: a flat disk (no z).
struct Axisymmetric {
    ex mass, zc;
    matrix inertia{3, 3};
};
Axisymmetric axisymmetric(const ex& rho, const symbol& s, const ex& s_lo, const ex& s_hi, const symbol& z,
                          const ex& z_lo, const ex& z_hi, bool solid) {
    auto integrate = [&](const ex& f) {
        ex r = GiNaC::integral(s, s_lo, s_hi, (2 * GiNaC::Pi * s * rho * f).expand()).eval_integ();
        if (solid) r = GiNaC::integral(z, z_lo, z_hi, r.expand()).eval_integ();
        return r.normal();
    };
    Axisymmetric b;
    b.mass = integrate(1);
    b.zc = (integrate(z) / b.mass).normal();
    const ex s2 = integrate(s * s), z2 = integrate(pow(z - b.zc, 2));
    b.inertia = matrix{{(s2 / 2 + z2).normal(), 0, 0}, {0, (s2 / 2 + z2).normal(), 0}, {0, 0, s2}};
    return b;
}

}  // namespace

TEST_CASE("5-15 right-triangle plate: tensor about the right angle, exact principal moments and axes",
          "[inertia]") {
    const symbol x("x"), y("y"), z("z"), M("M"), a("a");
    const eomgen::MassProperties p =
        eomgen::integrate_mass_properties(2 * M / (a * a), x, y, z, {{x, 0, a - y}, {y, 0, a}});
    const ex k = M * a * a / 12;
    REQUIRE((p.mass - M).normal().is_zero());
    REQUIRE(same(p.centre, column(a / 3, a / 3, 0)));
    const matrix corner{{2 * k, -k, 0}, {-k, 2 * k, 0}, {0, 0, 4 * k}};
    REQUIRE(same(p.inertia_origin, corner));
    REQUIRE(same(p.inertia_centre, eomgen::right_triangle_plate_inertia(M, a, a)));

    const eomgen::PrincipalAxes pa = eomgen::principal_axes(corner);
    REQUIRE(pa.exact);
    REQUIRE(pa.moments.size() == 3);
    CHECK((pa.moments[0] - k).normal().is_zero());
    CHECK((pa.moments[1] - 3 * k).normal().is_zero());
    CHECK((pa.moments[2] - 4 * k).normal().is_zero());
    const ex r = 1 / GiNaC::sqrt(ex(2));
    CHECK(same(pa.axes[0], column(r, r, 0)));
    CHECK(same(pa.axes[1], column(r, -r, 0)));
    CHECK(same(pa.axes[2], column(0, 0, 1)));
}

TEST_CASE("box, plates and rod against integrate_mass_properties over Cartesian bounds", "[inertia]") {
    const symbol x("x"), y("y"), z("z"), M("M"), a("a"), b("b"), c("c"), l("l");
    const auto box = eomgen::integrate_mass_properties(
        M / (a * b * c), x, y, z, {{x, -a / 2, a / 2}, {y, -b / 2, b / 2}, {z, -c / 2, c / 2}});
    CHECK((box.mass - M).normal().is_zero());
    CHECK(same(box.inertia_centre, eomgen::box_inertia(M, a, b, c)));
    const auto plate =
        eomgen::integrate_mass_properties(M / (a * b), x, y, z, {{x, -a / 2, a / 2}, {y, -b / 2, b / 2}});
    CHECK(same(plate.inertia_centre, eomgen::rectangular_plate_inertia(M, a, b)));
    const auto rod = eomgen::integrate_mass_properties(M / l, x, y, z, {{z, 0, l}});  // from one end
    CHECK(same(rod.centre, column(0, 0, l / 2)));
    CHECK(same(rod.inertia_centre, eomgen::thin_rod_inertia(M, l)));
    CHECK(same(rod.inertia_origin, matrix{{M * l * l / 3, 0, 0}, {0, M * l * l / 3, 0}, {0, 0, 0}}));
    // Unequal legs: x from 0 to a(1 − y/b).
    const auto tri =
        eomgen::integrate_mass_properties(2 * M / (a * b), x, y, z, {{x, 0, a * (1 - y / b)}, {y, 0, b}});
    CHECK(same(tri.centre, column(a / 3, b / 3, 0)));
    CHECK(same(tri.inertia_centre, eomgen::right_triangle_plate_inertia(M, a, b)));
}

TEST_CASE("round shapes against an independent integration in cylindrical coordinates", "[inertia]") {
    const symbol s("s"), z("z"), M("M"), R("R"), h("h"), R1("R1");
    const ex pi = GiNaC::Pi;
    SECTION("cylinder") {
        const auto b = axisymmetric(M / (pi * R * R * h), s, 0, R, z, -h / 2, h / 2, true);
        CHECK((b.mass - M).normal().is_zero());
        CHECK(same(b.inertia, eomgen::cylinder_inertia(M, R, h)));
    }
    SECTION("thin disk") {
        const auto b = axisymmetric(M / (pi * R * R), s, 0, R, z, 0, 0, false);
        CHECK(same(b.inertia, eomgen::thin_disk_inertia(M, R)));
    }
    SECTION("solid cone, apex at z = 0, centre of mass 3h/4 from the apex") {
        const auto b = axisymmetric(3 * M / (pi * R * R * h), s, 0, R * z / h, z, 0, h, true);
        CHECK((b.mass - M).normal().is_zero());
        CHECK((b.zc - 3 * h / 4).normal().is_zero());
        CHECK(same(b.inertia, eomgen::solid_cone_inertia(M, R, h)));
    }
    SECTION("solid sphere") {
        const auto b =
            axisymmetric(3 * M / (4 * pi * R * R * R), s, 0, GiNaC::sqrt(R * R - z * z), z, -R, R, true);
        CHECK((b.mass - M).normal().is_zero());
        CHECK(same(b.inertia, eomgen::solid_sphere_inertia(M, R)));
    }
    SECTION("ring: an annulus of mass M as its inner radius reaches the outer") {
        const auto b = axisymmetric(1, s, R1, R, z, 0, 0, false);
        matrix per_mass(3, 3);
        for (unsigned i = 0; i < 3; ++i)
            per_mass(i, i) = (M * b.inertia(i, i) / b.mass).normal().subs(R1 == R).normal();
        CHECK(same(per_mass, eomgen::ring_inertia(M, R)));
    }
    SECTION("hollow sphere: a shell of mass M as its inner radius reaches the outer") {
        // The full ball minus the inner ball (one region with a hole is not given by bounds).
        const auto outer = axisymmetric(1, s, 0, GiNaC::sqrt(R * R - z * z), z, -R, R, true);
        const auto inner = axisymmetric(1, s, 0, GiNaC::sqrt(R1 * R1 - z * z), z, -R1, R1, true);
        const ex mass = outer.mass - inner.mass;
        const ex i = (M * (outer.inertia(2, 2) - inner.inertia(2, 2)) / mass).normal().subs(R1 == R).normal();
        CHECK((i - eomgen::hollow_sphere_inertia(M, R)(2, 2)).normal().is_zero());
        const ex ix =
            (M * (outer.inertia(0, 0) - inner.inertia(0, 0)) / mass).normal().subs(R1 == R).normal();
        CHECK((ix - eomgen::hollow_sphere_inertia(M, R)(0, 0)).normal().is_zero());
    }
}

TEST_CASE("shape_inertia by name, and its errors", "[inertia]") {
    const symbol M("M"), R("R"), h("h");
    CHECK(same(eomgen::shape_inertia("solid_cone", M, {R, h}), eomgen::solid_cone_inertia(M, R, h)));
    CHECK(eomgen::shape_dimensions("box") == std::vector<std::string>{"a", "b", "c"});
    CHECK(eomgen::shape_names().size() == 10);
    CHECK_THROWS_WITH(eomgen::shape_inertia("blob", M, {}), Catch::Contains("unknown shape 'blob'"));
    CHECK_THROWS_WITH(eomgen::shape_inertia("box", M, {R}), Catch::Contains("takes 3 dimension(s), not 1"));
}

TEST_CASE("parallel axis: rod about its end, triangle about its corner, and back", "[inertia]") {
    const symbol M("M"), l("l"), a("a"), dx("dx"), dy("dy"), dz("dz");
    CHECK(same(eomgen::parallel_axis(eomgen::thin_rod_inertia(M, l), M, column(0, 0, l / 2)),
               matrix{{M * l * l / 3, 0, 0}, {0, M * l * l / 3, 0}, {0, 0, 0}}));
    const ex k = M * a * a / 12;
    CHECK(
        same(eomgen::parallel_axis(eomgen::right_triangle_plate_inertia(M, a, a), M, column(a / 3, a / 3, 0)),
             matrix{{2 * k, -k, 0}, {-k, 2 * k, 0}, {0, 0, 4 * k}}));
    const matrix d = column(dx, dy, dz);
    const matrix Ic = eomgen::box_inertia(M, a, l, 2 * a);
    CHECK(same(eomgen::shift_to_centre(eomgen::parallel_axis(Ic, M, d), M, d), Ic));
}

TEST_CASE("principal axes: a double moment exactly, an irrational spectrum numerically", "[inertia]") {
    const symbol M("M"), R("R");
    const eomgen::PrincipalAxes disk = eomgen::principal_axes(eomgen::thin_disk_inertia(M, R));
    REQUIRE(disk.exact);
    CHECK((disk.moments[0] - M * R * R / 4).normal().is_zero());
    CHECK((disk.moments[1] - M * R * R / 4).normal().is_zero());
    CHECK((disk.moments[2] - M * R * R / 2).normal().is_zero());
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) {
            ex dot = 0;
            for (unsigned c = 0; c < 3; ++c) dot += disk.axes[i](c, 0) * disk.axes[j](c, 0);
            CHECK((dot - (i == j ? 1 : 0)).normal().is_zero());
        }

    // det(λ − I) = (λ − M)(λ² − 3Mλ + M²): no rational roots for the quadratic.
    const matrix I{{2 * M, M, 0}, {M, M, 0}, {0, 0, M}};
    CHECK_THROWS_WITH(eomgen::principal_axes(I), Catch::Contains("does not factor"));
    const eomgen::PrincipalAxes n = eomgen::principal_axes(I, {{M, 2}});
    REQUIRE_FALSE(n.exact);
    const double golden = (3 - std::sqrt(5.0)) / 2;
    CHECK(GiNaC::ex_to<numeric>(n.moments[0]).to_double() == Approx(2 * golden).epsilon(1e-12));
    CHECK(GiNaC::ex_to<numeric>(n.moments[1]).to_double() == Approx(2.0).epsilon(1e-12));
    CHECK(GiNaC::ex_to<numeric>(n.moments[2]).to_double() == Approx(2 * (3 - golden)).epsilon(1e-12));
    for (unsigned i = 0; i < 3; ++i) {
        const matrix Iv = GiNaC::ex_to<matrix>(I.subs(GiNaC::exmap{{M, 2}})).mul(n.axes[i]);  // I v = λ v
        for (unsigned c = 0; c < 3; ++c)
            CHECK(
                GiNaC::ex_to<numeric>(GiNaC::evalf(Iv(c, 0) - n.moments[i] * n.axes[i](c, 0))).to_double() ==
                Approx(0.0).margin(1e-12));
    }
}
