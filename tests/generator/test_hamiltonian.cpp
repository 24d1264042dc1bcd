/** @file test_hamiltonian.cpp  The Legendre transform: H(q, p) against closed forms, and cross-checked through
 * p = p(q, q̇): H ∘ p = h, ∂H/∂p = q̇, −∂H/∂q + Q = ∂L/∂q + Q (= ṗ on the Euler–Lagrange equations). */
#include "test_paths.hpp"
#include "mechanics/hamiltonian.hpp"
#include "model/families.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace {

const std::string kSource = eomgen_test::source_dir();

struct Derived {
    eomgen::Model model;
    eomgen::Equations eq;
    eomgen::Hamiltonian h;
};

Derived derive(eomgen::Model m) {
    eomgen::Equations e = eomgen::derive_equations(m);
    eomgen::Hamiltonian h = eomgen::derive_hamiltonian(m, e);
    return {std::move(m), std::move(e), std::move(h)};
}

Derived load(const std::string& path) {
    return derive(eomgen::load_model(kSource + "/" + path));
}

GiNaC::ex sym(const Derived& d, const std::string& name) {
    for (const eomgen::Parameter& p : d.model.parameters)
        if (p.name == name) return p.symbol;
    for (const eomgen::Coordinate& c : d.model.coordinates)
        if (c.name == name) return c.q;
    FAIL("no symbol " << name);
    return 0;
}

/// The identities that hold for every Legendre transform, through p = p(q, q̇).
void require_canonical(const Derived& d) {
    REQUIRE(d.h.symbolic);
    const eomgen::Model& m = d.model;
    CHECK(eomgen::is_zero(eomgen::in_velocities(d.h.H, d.h) - d.eq.energy, m));
    for (std::size_t i = 0; i < m.dof(); ++i) {
        INFO("coordinate " << m.coordinates[i].name);
        CHECK(eomgen::is_zero(eomgen::in_velocities(d.h.velocities[i], d.h) - m.coordinates[i].qd, m));
        CHECK(eomgen::is_zero(eomgen::in_velocities(d.h.qdot[i], d.h) - m.coordinates[i].qd, m));
        // ṗ = d/dt ∂L/∂q̇ = ∂L/∂q + Q on the Euler–Lagrange equations.
        CHECK(eomgen::is_zero(eomgen::in_velocities(d.h.pdot[i], d.h) - d.eq.dLdq[i] - d.eq.generalized_forces[i], m));
    }
}

}  // namespace

TEST_CASE("hamiltonian: the plane pendulum's H = p^2/(2 m l^2) - m g l cos(theta)", "[hamiltonian]") {
    const Derived d = load("tests/checker/models/plane_pendulum.toml");
    require_canonical(d);
    const GiNaC::ex m = sym(d, "m"), l = sym(d, "l"), g = sym(d, "g"), th = sym(d, "theta");
    const GiNaC::ex p = d.h.p[0];
    CHECK((d.h.H - (p * p / (2 * m * l * l) - m * g * l * GiNaC::cos(th))).expand().is_zero());
    CHECK((d.h.pdot[0] + m * g * l * GiNaC::sin(th)).expand().is_zero());
}

TEST_CASE("hamiltonian: the spherical pendulum, diagonal M", "[hamiltonian]") {
    const Derived d = load("tests/checker/models/spherical_pendulum.toml");
    require_canonical(d);
    const GiNaC::ex m = sym(d, "m"), l = sym(d, "l"), g = sym(d, "g"), th = sym(d, "theta");
    const GiNaC::ex pt = d.h.p[0], pp = d.h.p[1];
    const GiNaC::ex closed = pt * pt / (2 * m * l * l) + pp * pp / (2 * m * l * l * GiNaC::pow(GiNaC::sin(th), 2)) -
                             m * g * l * GiNaC::cos(th);
    CHECK(GiNaC::normal(d.h.H - closed).is_zero());
    // ṗ_θ = p_φ² cos θ / (m l² sin³ θ) − m g l sin θ (Goldstein §8.1 exercise form).
    const GiNaC::ex pdot_theta = pp * pp * GiNaC::cos(th) / (m * l * l * GiNaC::pow(GiNaC::sin(th), 3)) -
                                 m * g * l * GiNaC::sin(th);
    CHECK(GiNaC::normal(d.h.pdot[0] - pdot_theta).is_zero());
    CHECK(d.h.pdot[1].is_zero());  // φ is cyclic
}

TEST_CASE("hamiltonian: the heavy symmetric top, a 3x3 block with a coupled phi-psi pair", "[hamiltonian]") {
    const Derived d = load("models/heavy_symmetric_top.toml");
    require_canonical(d);
    // H = p_θ²/(2I) + (p_φ − p_ψ cos θ)²/(2I sin²θ) + p_ψ²/(2 I3) + M g l cos θ, I = I1 + M l² about the pivot
    // (Goldstein §5.7, in momenta).
    GiNaC::ex ph, th, ps;
    for (std::size_t i = 0; i < 3; ++i) {
        const std::string& n = d.model.coordinates[i].name;
        (n == "phi" ? ph : n == "theta" ? th : ps) = d.h.p[i];
    }
    const GiNaC::ex I1 = sym(d, "I1"), I3 = sym(d, "I3"), M = sym(d, "M"), g = sym(d, "g"), l = sym(d, "l"),
                    t = sym(d, "theta");
    const GiNaC::ex I = I1 + M * l * l;  // about the pivot
    const GiNaC::ex closed = th * th / (2 * I) +
                             GiNaC::pow(ph - ps * GiNaC::cos(t), 2) / (2 * I * GiNaC::pow(GiNaC::sin(t), 2)) +
                             ps * ps / (2 * I3) + M * g * l * GiNaC::cos(t);
    CHECK(eomgen::is_zero(eomgen::in_velocities(d.h.H - closed, d.h), d.model));
}

TEST_CASE("hamiltonian: four coupled coordinates are not inverted symbolically", "[hamiltonian]") {
    const Derived d = derive(eomgen::parse_model(
        eomgen::family_model_text(eomgen::parse_family_spec("pendulum:n=4")), "--family pendulum:n=4"));
    CHECK_FALSE(d.h.symbolic);
    CHECK(d.h.why_not_symbolic.find("couples 4 coordinates") != std::string::npos);
    // The momenta and the split of L are there: L = ½ q̇ᵀ M q̇ + bᵀ q̇ + L₀.
    GiNaC::ex L = d.h.L0;
    for (std::size_t i = 0; i < 4; ++i) {
        L += d.h.b[i] * d.model.coordinates[i].qd;
        for (std::size_t j = 0; j < 4; ++j)
            L += d.h.M(unsigned(i), unsigned(j)) * d.model.coordinates[i].qd * d.model.coordinates[j].qd / 2;
    }
    CHECK(eomgen::is_zero(L - d.eq.L, d.model));
}

TEST_CASE("hamiltonian: a term linear in the velocities, a charge in a magnetic field", "[hamiltonian]") {
    // L = m/2 (x'² + y'²) + (e B/2)(x y' − y x') + k cos(w t) x: b = (e B/2)(−y, x), explicit time in L₀.
    const Derived d = load("tests/checker/models/charge_in_field.toml");
    require_canonical(d);
    const GiNaC::ex m = sym(d, "m"), eB = sym(d, "b"), x = sym(d, "x"), y = sym(d, "y");
    CHECK((d.h.b[0] + eB * y / 2).expand().is_zero());
    CHECK((d.h.b[1] - eB * x / 2).expand().is_zero());
    // H = ((p_x + eB y/2)² + (p_y − eB x/2)²)/(2m) − k cos(w t) x
    const GiNaC::ex px = d.h.p[0], py = d.h.p[1];
    const GiNaC::ex closed = (GiNaC::pow(px + eB * y / 2, 2) + GiNaC::pow(py - eB * x / 2, 2)) / (2 * m) -
                             sym(d, "k") * GiNaC::cos(sym(d, "w") * d.model.t) * x;
    CHECK(GiNaC::normal(d.h.H - closed).is_zero());
}
