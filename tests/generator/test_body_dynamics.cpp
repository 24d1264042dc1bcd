/** @file test_body_dynamics.cpp  Euler's equations, angular momentum, applied loads and springs of body-based
 * models, cross-checked against the Euler–Lagrange equations and against hand-written T and V. */
#include "test_paths.hpp"
#include "mechanics/bodies.hpp"
#include "mechanics/kinematics.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <string>

namespace {

using GiNaC::ex;

double value(const ex& e, const GiNaC::exmap& at) {
    const ex v = GiNaC::evalf(e.subs(at));
    REQUIRE(GiNaC::is_a<GiNaC::numeric>(v));
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

ex parameter(const eomgen::Model& m, const std::string& name) {
    for (const auto& p : m.parameters)
        if (p.name == name) return p.symbol;
    throw std::logic_error("no parameter " + name);
}

/// A random point of every symbol with q̈ replaced by the solution of M q̈ = f: a state on a trajectory.
GiNaC::exmap on_trajectory(const eomgen::Model& md, const eomgen::Equations& eq, unsigned seed) {
    GiNaC::exmap at = eomgen::random_point(md, seed);
    const Eigen::Index n = Eigen::Index(md.dof());
    Eigen::MatrixXd M(n, n);
    Eigen::VectorXd f(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        f(i) = value(eq.f[std::size_t(i)], at);
        for (Eigen::Index j = 0; j < n; ++j) M(i, j) = value(eq.M(unsigned(i), unsigned(j)), at);
    }
    const Eigen::VectorXd qdd = M.ldlt().solve(f);
    for (Eigen::Index i = 0; i < n; ++i) at[md.coordinates[std::size_t(i)].qdd] = qdd(i);
    return at;
}

const char* top_text = R"T(name = "top"
[[coordinates]]
name = "phi"
[[coordinates]]
name = "theta"
[[coordinates]]
name = "psi"
[[parameters]]
name = "I1"
value = 1
[[parameters]]
name = "I2"
value = 2
[[parameters]]
name = "I3"
value = 3
[[parameters]]
name = "N1"
value = 1
[[parameters]]
name = "N2"
value = 1
[[parameters]]
name = "N3"
value = 1
[[bodies]]
name = "body"
mass = "1"
inertia = ["I1", "I2", "I3"]
position = ["0", "0", "0"]
orientation = ["phi", "theta", "psi"]
)T";

}  // namespace

TEST_CASE("Euler's equations: zero along the Euler-Lagrange motion of a free asymmetric body", "[bodies][euler]") {
    const eomgen::Model md = eomgen::parse_model(top_text, "top.toml");
    const eomgen::Equations eq = eomgen::derive_equations(md);
    const eomgen::BodyDynamics d = eomgen::body_dynamics(md, md.bodies[0]);
    for (unsigned seed = 1; seed <= 5; ++seed) {
        const GiNaC::exmap at = on_trajectory(md, eq, seed);
        for (unsigned k = 0; k < 3; ++k) CHECK(value(d.euler_torque(k, 0), at) == Approx(0).margin(1e-12));
        // Off the trajectory (q̈ random) they are not zero: the check can fail.
        const GiNaC::exmap off = eomgen::random_point(md, seed);
        CHECK(std::abs(value(d.euler_torque(0, 0), off)) + std::abs(value(d.euler_torque(1, 0), off)) > 1e-3);
    }
    // Goldstein (5.39), principal axes: I1 ω̇1 − ω2 ω3 (I2 − I3) = N1.
    const ex I1 = parameter(md, "I1"), I2 = parameter(md, "I2"), I3 = parameter(md, "I3");
    const GiNaC::matrix& w = d.omega_body;
    const ex N1 = eomgen::time_derivative(w(0, 0), md) * I1 - w(1, 0) * w(2, 0) * (I2 - I3);
    CHECK(eomgen::is_zero(N1 - d.euler_torque(0, 0), md));
}

TEST_CASE("Euler's equations with an applied torque: N' of the motion equals the torque applied",
          "[bodies][euler]") {
    const eomgen::Model md =
        eomgen::parse_model(std::string(top_text) + "torque = [\"N1\", \"N2*cos(theta)\", \"N3*psi'\"]\n", "top.toml");
    const eomgen::Equations eq = eomgen::derive_equations(md);
    const eomgen::BodyDynamics d = eomgen::body_dynamics(md, md.bodies[0]);
    for (unsigned seed = 1; seed <= 5; ++seed) {
        const GiNaC::exmap at = on_trajectory(md, eq, seed);
        for (unsigned k = 0; k < 3; ++k)
            CHECK(value(d.euler_torque(k, 0) - md.bodies[0].torque[k], at) == Approx(0).margin(1e-12));
    }
    // ψ's generalized force is the torque's component along the body z axis (ω' ∂/∂ψ̇ = e3).
    CHECK(eomgen::is_zero(eq.generalized_forces[2] - md.bodies[0].torque[2], md));
}

TEST_CASE("a force at the centre of mass: m r'' = F, and its generalized force by virtual work", "[bodies]") {
    const eomgen::Model md = eomgen::parse_model(R"T(name = "puck"
[[coordinates]]
name = "r"
[[coordinates]]
name = "a"
[[parameters]]
name = "m"
value = 1
[[parameters]]
name = "F"
value = 1
[[bodies]]
name = "disc"
mass = "m"
inertia = ["0", "0", "0"]
position = ["r*cos(a)", "r*sin(a)", "0"]
force = ["F", "0", "0"]
)T",
                                                 "puck.toml");
    const eomgen::Equations eq = eomgen::derive_equations(md);
    const ex r = md.coordinates[0].q, a = md.coordinates[1].q, F = parameter(md, "F");
    // Q_r = F·∂r/∂r = F cos a, Q_a = F·∂r/∂a = −F r sin a.
    CHECK(eomgen::is_zero(eq.generalized_forces[0] - F * cos(a), md));
    CHECK(eomgen::is_zero(eq.generalized_forces[1] + F * r * sin(a), md));
}

TEST_CASE("5-18 dumbbell as a body: Euler's torque and dL/dt in space agree with the seed", "[bodies][dumbbell]") {
    const eomgen::Model md = eomgen::load_model(eomgen_test::source_dir() + "/models/dumbbell_5_18_bodies.toml");
    const eomgen::BodyDynamics d = eomgen::body_dynamics(md, md.bodies[0]);
    const ex m = parameter(md, "m"), l = parameter(md, "l"), th = parameter(md, "theta"),
             w = parameter(md, "omega");
    const auto& alpha = md.coordinates[0];
    const auto& beta = md.coordinates[1];
    // The drive: alpha = theta, beta = omega t.
    const GiNaC::exmap drive{{alpha.q, th}, {alpha.qd, 0}, {alpha.qdd, 0}, {beta.q, w * md.t}, {beta.qd, w}, {beta.qdd, 0}};
    const ex N = 2 * m * l * l * w * w * sin(th) * cos(th);
    // Body axes (x' across the bar and across ω here; the seed's y'): N' = (−N, 0, 0).
    CHECK(eomgen::is_zero(d.euler_torque(0, 0).subs(drive) + N, md));
    CHECK(eomgen::is_zero(d.euler_torque(1, 0).subs(drive), md));
    CHECK(eomgen::is_zero(d.euler_torque(2, 0).subs(drive), md));
    // Inertial frame: the seed's dL/dt = N (sin ωt, −cos ωt, 0) for its bar along r1 = l (sin θ cos ωt,
    // sin θ sin ωt, cos θ). Here the bar points along (sin α sin β, −sin α cos β, cos α), the seed's r1 turned
    // by −90° about z, so every vector is turned the same way, (v_x, v_y) → (v_y, −v_x): dL/dt = −N (cos ωt,
    // sin ωt, 0), and Aᵀ N' is the same rotating vector.
    const GiNaC::matrix dL = eomgen::time_derivative(d.angular_momentum_space, md);
    const GiNaC::matrix space = d.rotation.transpose().mul(d.euler_torque);
    const ex expected[3] = {-N * cos(w * md.t), -N * sin(w * md.t), 0};
    for (unsigned k = 0; k < 3; ++k) {
        CHECK(eomgen::is_zero(dL(k, 0).subs(drive) - expected[k], md));
        CHECK(eomgen::is_zero(space(k, 0).subs(drive) - expected[k], md));
    }
    // The seed's L = −2 m l² ω sin θ (cos θ cos ωt, cos θ sin ωt, −sin θ).
    const ex L[3] = {-2 * m * l * l * w * sin(th) * cos(th) * cos(w * md.t),
                     -2 * m * l * l * w * sin(th) * cos(th) * sin(w * md.t), 2 * m * l * l * w * sin(th) * sin(th)};
    // Turned the same way, (L_x, L_y) → (L_y, −L_x).
    CHECK(eomgen::is_zero(d.angular_momentum_space(0, 0).subs(drive) - L[1], md));
    CHECK(eomgen::is_zero(d.angular_momentum_space(1, 0).subs(drive) + L[0], md));
    CHECK(eomgen::is_zero(d.angular_momentum_space(2, 0).subs(drive) - L[2], md));
}

TEST_CASE("springs: the same equations as V written by hand, ends in space and on a body", "[bodies][springs]") {
    const std::string head = R"T(name = "s"
[[coordinates]]
name = "th"
[[coordinates]]
name = "r"
[[parameters]]
name = "m"
value = 1
[[parameters]]
name = "k"
value = 10
[[parameters]]
name = "l0"
value = 1
[[parameters]]
name = "d"
value = 0.5
[[bodies]]
name = "rod"
mass = "m"
shape = "thin_rod"
dimensions = ["r"]
position = ["r/2*sin(th)", "-r/2*cos(th)", "0"]
orientation = ["th", "pi/2", "0"]
)T";
    // The rod's body z axis is along (sin th, −cos th, 0) (z-x-z angles (th, π/2, 0)): its far end is at
    // ρ = (0, 0, r/2) from its centre. Spring from (d, 0, 0) to that end, rest length l0; and a zero-length
    // one from the origin to the centre.
    const eomgen::Model md = eomgen::parse_model(
        head + R"T([[springs]]
name = "s1"
stiffness = "k"
length = "l0"
from = ["d", "0", "0"]
to = { body = "rod", point = ["0", "0", "r/2"] }
[[springs]]
name = "s2"
stiffness = "2*k"
from = ["0", "0", "0"]
to = { body = "rod" }
)T",
        "s.toml");
    const eomgen::Equations eq = eomgen::derive_equations(md);
    REQUIRE(eq.springs.size() == 2);
    const ex th = md.coordinates[0].q, r = md.coordinates[1].q;
    const ex k = parameter(md, "k"), l0 = parameter(md, "l0"), d = parameter(md, "d");
    const ex len2 = pow(r * sin(th) - d, 2) + pow(r * cos(th), 2);
    const ex V1 = k / 2 * pow(sqrt(len2) - l0, 2), V2 = k * r * r / 4;
    CHECK(eomgen::is_zero(eq.springs[0].V - V1, md));
    CHECK(eomgen::is_zero(eq.springs[1].V - V2, md));
    CHECK(eomgen::is_zero(eq.springs[0].length - sqrt(len2), md));
    CHECK(eomgen::is_zero(eq.V - V1 - V2, md));
    // The potential part of f is −∂V/∂q.
    CHECK(eomgen::is_zero(eq.dLdq[0] - GiNaC::diff(eq.T, md.coordinates[0].q) + GiNaC::diff(V1 + V2, md.coordinates[0].q), md));

    auto error = [&](const std::string& springs) {
        try {
            eomgen::derive_equations(eomgen::parse_model(head + springs, "s.toml"));
        } catch (const eomgen::ModelError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK_THAT(error("[[springs]]\nname = \"x\"\nfrom = [0, 0, 0]\nto = [\"r\", 0, 0]\n"),
               Catch::Contains("missing key 'stiffness'") && Catch::StartsWith("s.toml:"));
    CHECK_THAT(error("[[springs]]\nname = \"x\"\nstiffness = \"k\"\nfrom = [0, 0, 0]\nto = { body = \"bar\" }\n"),
               Catch::Contains("no body named 'bar'") && Catch::StartsWith("s.toml:29:"));
    CHECK_THAT(error("[[springs]]\nname = \"x\"\nstiffness = \"k*th'\"\nfrom = [0, 0, 0]\nto = [0, 0, 1]\n"),
               Catch::Contains("must not depend on velocities"));
    CHECK_THAT(error("[[springs]]\nname = \"x\"\nstiffness = \"k\"\nfrom = [0, 0, 0]\n"),
               Catch::Contains("missing key 'to'"));
    CHECK_THAT(error("[[springs]]\nname = \"th\"\nstiffness = \"k\"\nfrom = [0, 0, 0]\nto = [0, 0, 1]\n"),
               Catch::Contains("'th'"));
}
