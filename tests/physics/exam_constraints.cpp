/** @file exam_constraints.cpp  Constrained systems: rolling sphere (Ex. 25), Cartesian pendulum, rolling disc,
 *  the driven dumbbell (5-18) and a damped pendulum, against invariants, closed forms and other formulations. */
#include "test_paths.hpp"
#include "approx.hpp"

#include "eomgen/constraints.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/models/damped_pendulum.hpp"
#include "eomgen/models/dumbbell_5_18.hpp"
#include "eomgen/models/pendulum.hpp"
#include "eomgen/models/pendulum_cartesian.hpp"
#include "eomgen/models/rolling_disc.hpp"
#include "eomgen/models/rolling_sphere.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace {

using Sphere = eomgen::models::rolling_sphere::Model<double>;
using Pendulum = eomgen::models::pendulum::Model<double>;
using Cartesian = eomgen::models::pendulum_cartesian::Model<double>;
using Disc = eomgen::models::rolling_disc::Model<double>;
using Dumbbell = eomgen::models::dumbbell_5_18::Model<double>;
using Damped = eomgen::models::damped_pendulum::Model<double>;

std::vector<double> grid(double t_end, int n) {
    std::vector<double> t;
    for (int k = 1; k <= n; ++k) t.push_back(t_end * k / n);
    return t;
}

eomgen::Dopri5Options<double> tight() {
    eomgen::Dopri5Options<double> o;
    o.rtol = 1e-12;
    o.atol = 1e-14;
    o.max_steps = 10000000;
    return o;
}

/// A sphere state with the given angles and rates, x' and y' from the no-slip constraints.
Sphere::State sphere_state(double th, double ph, double ps, double thd, double phd, double psd, double R) {
    Sphere::State x;
    x << 0.3, -0.2, th, ph, ps, R * (thd * std::sin(ph) - psd * std::sin(th) * std::cos(ph)),
        -R * (thd * std::cos(ph) + psd * std::sin(th) * std::sin(ph)), thd, phd, psd;
    return x;
}

}  // namespace

TEST_CASE("rolling sphere: spin, speed and both kinetic energies are conserved, no drift", "[physics][constraints]") {
    Sphere::Params p;
    const Sphere::State x0 = Sphere::default_state();
    const auto r = eomgen::integrate_constrained<Sphere>(p, 0.0, x0, grid(200.0, 400), tight());
    auto invariants = [&p](const Sphere::State& x) {
        const double th = x(2), phd = x(8), psd = x(9), thd = x(7), ph = x(3);
        const double wz = phd + psd * std::cos(th);  // ω_z = φ̇ + ψ̇ cos θ (Goldstein 4.87)
        const double wx = thd * std::cos(ph) + psd * std::sin(th) * std::sin(ph);
        const double wy = thd * std::sin(ph) - psd * std::sin(th) * std::cos(ph);
        const double v = std::hypot(x(5), x(6));
        return std::array<double, 4>{wz, v, 0.5 * p.m * v * v, 0.5 * p.I * (wx * wx + wy * wy + wz * wz)};
    };
    const auto start = invariants(x0);
    for (const auto& s : r.run.samples) {
        const auto now = invariants(s.x);
        for (int k = 0; k < 4; ++k) REQUIRE(now[std::size_t(k)] == Approx(start[std::size_t(k)]).epsilon(1e-9));
    }
    INFO("residuals before projection: " << r.max_position_residual << ", " << r.max_velocity_residual);
    REQUIRE(r.max_velocity_residual <= 1e-10);
    // The sphere has moved: the test is not of a state at rest.
    REQUIRE(std::hypot(r.run.x(0) - x0(0), r.run.x(1) - x0(1)) > 1.0);
}

TEST_CASE("rolling sphere: the multipliers are the friction forces m x'' = -lambda_x, m y'' = lambda_y",
          "[physics][constraints]") {
    // For a uniform sphere on a plane the friction vanishes (m a = F and I ω̇ = r × F with no slip give
    // F (1 + m R²/I) = 0), so both sides are zero to round-off, at every consistent state.
    Sphere::Params p;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-2, 2), th(0.3, 2.8);
    for (int trial = 0; trial < 20; ++trial) {
        const Sphere::State x = sphere_state(th(rng), u(rng), u(rng), u(rng), u(rng), u(rng), p.R);
        Sphere::Config qdd;
        Sphere::ConstraintVector lambda;
        Sphere::accelerations(0.0, x, p, 0.0, 0.0, qdd, lambda);
        REQUIRE(p.m * qdd(0) == Approx(-lambda(0)).margin(1e-12));
        REQUIRE(p.m * qdd(1) == Approx(lambda(1)).margin(1e-12));
        REQUIRE(std::abs(lambda(0)) < 1e-12);
        REQUIRE(std::abs(lambda(1)) < 1e-12);
    }
}

TEST_CASE("rolling sphere: the Euler-angle singularity sin(theta) = 0 stops with a clear message",
          "[physics][constraints][errors]") {
    Sphere::Params p;
    const Sphere::State x = sphere_state(0.0, 0.3, 0.1, 0.5, 0.2, 0.4, p.R);  // sin θ = 0
    Sphere::State xdot;
    try {
        Sphere::rhs(0.0, x, p, xdot);
        FAIL("no error at sin(theta) = 0");
    } catch (const eomgen::SimulationError& e) {
        INFO(e.what());
        REQUIRE(std::string(e.what()).find("singular") != std::string::npos);
        REQUIRE(std::string(e.what()).find("t = 0") != std::string::npos);
    }
}

TEST_CASE("Cartesian pendulum: same trajectory as the angle formulation, lambda = -F/(2l)",
          "[physics][constraints]") {
    Cartesian::Params pc;
    Pendulum::Params pa;
    const double phi0 = 0.5, rate0 = 1.3;
    Pendulum::State a0;
    a0 << phi0, rate0;
    Cartesian::State c0;
    c0 << pc.l * std::sin(phi0), -pc.l * std::cos(phi0), pc.l * rate0 * std::cos(phi0), pc.l * rate0 * std::sin(phi0);
    const std::vector<double> times = grid(20.0, 200);
    const auto rc = eomgen::integrate_constrained<Cartesian>(pc, 0.0, c0, times, tight());
    auto fa = [&pa](const double& t, const Pendulum::State& x, Pendulum::State& xdot) { Pendulum::rhs(t, x, pa, xdot); };
    const auto ra = eomgen::integrate(fa, 0.0, a0, 20.0, tight(), {}, times);
    REQUIRE(ra.samples.size() == times.size());
    for (std::size_t k = 0; k < times.size(); ++k) {
        const auto& c = rc.run.samples[k + 1];  // sample 0 is t = 0
        const auto& a = ra.samples[k];
        REQUIRE(c.t == a.t);
        const double phi = a.x(0), phid = a.x(1);
        REQUIRE(c.x(0) == Approx(pc.l * std::sin(phi)).margin(1e-8));
        REQUIRE(c.x(1) == Approx(-pc.l * std::cos(phi)).margin(1e-8));
        Cartesian::ConstraintVector lambda;
        Cartesian::multipliers(c.t, c.x, pc, lambda);
        const double tension = pc.m * (pc.g * std::cos(phi) + pc.l * phid * phid);
        REQUIRE(lambda(0) == Approx(-tension / (2 * pc.l)).epsilon(1e-7));
    }
    REQUIRE(rc.max_position_residual <= 1e-10);
}

TEST_CASE("rolling disc: energy is conserved, fast rolling stays upright, slow rolling falls", "[physics][constraints]") {
    Disc::Params p;
    auto run = [&p](double spin, double t_end) {
        Disc::State x0 = Disc::State::Zero();
        x0(Disc::nq + 3) = 0.01;                   // θ̇: a small push sideways
        x0(Disc::nq + 4) = spin;                   // ψ̇
        x0(Disc::nq + 0) = -p.R * spin;            // ẋ = −R ψ̇ cos φ
        return eomgen::integrate_constrained<Disc>(p, 0.0, x0, grid(t_end, 500), tight());
    };
    const auto fast = run(20.0, 10.0);
    const double h0 = Disc::energy(0, fast.run.samples[0].x.head<Disc::nq>(), fast.run.samples[0].x.tail<Disc::nq>(), p);
    double max_lean_fast = 0;
    for (const auto& s : fast.run.samples) {
        REQUIRE(Disc::energy(s.t, s.x.head<Disc::nq>(), s.x.tail<Disc::nq>(), p) == Approx(h0).epsilon(1e-9));
        max_lean_fast = std::max(max_lean_fast, std::abs(s.x(3)));
    }
    const auto slow = run(2.0, 3.0);
    double max_lean_slow = 0;
    for (const auto& s : slow.run.samples) max_lean_slow = std::max(max_lean_slow, std::abs(s.x(3)));
    INFO("largest lean: fast " << max_lean_fast << ", slow " << max_lean_slow);
    REQUIRE(max_lean_fast < 0.01);
    REQUIRE(max_lean_slow > 0.3);
}

TEST_CASE("dumbbell 5-18: the drive's torque is 2 m l^2 w^2 sin(theta) cos(theta), perpendicular to bar and axis",
          "[physics][constraints]") {
    Dumbbell::Params p;
    const auto r = eomgen::integrate_constrained<Dumbbell>(p, 0.0, Dumbbell::default_state(), grid(5.0, 50), tight());
    for (const auto& s : r.run.samples) {
        Dumbbell::ConstraintVector lambda;
        Dumbbell::multipliers(s.t, s.x, p, lambda);
        const double alpha = s.x(0), beta = s.x(1);
        // λ_tilt is the torque about the axis (−sin β, cos β, 0) that turns α; λ_drive the torque about z.
        const Eigen::Vector3d N(-lambda(0) * std::sin(beta), lambda(0) * std::cos(beta), lambda(1));
        const double wt = p.omega * s.t;
        const Eigen::Vector3d seed = 2 * p.m * p.l * p.l * p.omega * p.omega * std::sin(p.theta) * std::cos(p.theta) *
                                     Eigen::Vector3d(std::sin(wt), -std::cos(wt), 0);
        REQUIRE_THAT(Eigen::MatrixXd(N), eomgen::test::AllClose(seed, 1e-8, 1e-10));
        const Eigen::Vector3d bar(std::sin(alpha) * std::cos(beta), std::sin(alpha) * std::sin(beta), std::cos(alpha));
        REQUIRE(std::abs(N.dot(bar)) < 1e-10);
        REQUIRE(std::abs(N.z()) < 1e-10);
    }
}

TEST_CASE("damped pendulum: dh/dt = -2R along the trajectory", "[physics][forces]") {
    Damped::Params p;
    auto f = [&p](const double& t, const Damped::State& x, Damped::State& xdot) { Damped::rhs(t, x, p, xdot); };
    // Trapezoid-free check: h(t) − h(0) against ∫ −c φ̇² dt by Simpson's rule on a fine grid.
    const int n = 4000;
    const double t_end = 10.0;
    const auto r = eomgen::integrate(f, 0.0, Damped::default_state(), t_end, tight(), {}, grid(t_end, n));
    auto h = [&p](const Damped::State& x) { return Damped::energy(0, x.head<1>(), x.tail<1>(), p); };
    auto two_R = [&p](const Damped::State& x) { return p.c * x(1) * x(1); };
    std::vector<Damped::State> xs{Damped::default_state()};
    for (const auto& s : r.samples) xs.push_back(s.x);
    double integral = 0;
    const double dt = t_end / n;
    for (int k = 0; k + 2 <= n; k += 2)
        integral += dt / 3 * (two_R(xs[std::size_t(k)]) + 4 * two_R(xs[std::size_t(k + 1)]) + two_R(xs[std::size_t(k + 2)]));
    const double dh = h(xs.back()) - h(xs.front());
    INFO("h lost " << dh << ", integral of -2R " << -integral);
    REQUIRE(dh < -0.1);  // it does lose energy
    REQUIRE(dh == Approx(-integral).epsilon(1e-8));
    REQUIRE_FALSE(Damped::n_conserved > 0);
}

TEST_CASE("inconsistent initial conditions are refused with the constraint's name, or projected", "[constraints][errors]") {
    Sphere::Params p;
    Sphere::State x = Sphere::default_state();
    x(7) += 0.5;  // θ̇ changed, ẋ and ẏ not
    try {
        eomgen::check_consistent<Sphere>(0.0, x, p);
        FAIL("accepted");
    } catch (const eomgen::InconsistentInitialConditions& e) {
        REQUIRE(std::string(e.what()).find("'roll_x'") != std::string::npos);
    }
    eomgen::project_onto_constraints<Sphere>(0.0, x, p);
    REQUIRE_NOTHROW(eomgen::check_consistent<Sphere>(0.0, x, p, 1e-12));
    Cartesian::Params pc;
    Cartesian::State c;
    c << 0.8, -0.7, 0.3, 0.1;  // off the circle, velocity not tangent
    REQUIRE_THROWS_AS(eomgen::check_consistent<Cartesian>(0.0, c, pc), eomgen::InconsistentInitialConditions);
    eomgen::project_onto_constraints<Cartesian>(0.0, c, pc);
    REQUIRE(std::hypot(c(0), c(1)) == Approx(pc.l).epsilon(1e-13));
    REQUIRE(std::abs(c(0) * c(2) + c(1) * c(3)) < 1e-13);
}

TEST_CASE("generated constraint code equals the symbolic Jacobians and gamma", "[generated][constraints]") {
    const eomgen::Model md = eomgen::load_model(eomgen_test::source_dir() + "/models/rolling_disc.toml");
    const eomgen::Equations eq = eomgen::derive_equations(md);
    Disc::Params p;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    for (int trial = 0; trial < 10; ++trial) {
        Disc::Config q, qd;
        GiNaC::exmap at;
        for (int i = 0; i < Disc::nq; ++i) {
            q(i) = u(rng);
            qd(i) = u(rng);
            at[md.coordinates[std::size_t(i)].q] = q(i);
            at[md.coordinates[std::size_t(i)].qd] = qd(i);
        }
        for (const auto& par : md.parameters) {
            double v = 0;
            for (std::size_t k = 0; k < Disc::param_names.size(); ++k)
                if (par.name == Disc::param_names[k]) v = Disc::param_values(p)[k];
            at[par.symbol] = v;
        }
        Disc::ConstraintJacobian A;
        Disc::ConstraintVector gamma;
        Disc::constraints(0.0, q, qd, p, A, gamma);
        for (int k = 0; k < Disc::n_constraints; ++k) {
            const auto& c = eq.constraints[std::size_t(k)];
            for (int i = 0; i < Disc::nq; ++i)
                REQUIRE(A(k, i) == Approx(GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(c.jacobian[std::size_t(i)].subs(at)))
                                              .to_double()).margin(1e-13));
            REQUIRE(gamma(k) == Approx(GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(c.gamma.subs(at))).to_double())
                                    .epsilon(1e-12).margin(1e-13));
        }
    }
}
