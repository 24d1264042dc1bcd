/** @file exam_pendulum_5_20.cpp  Goldstein ch. 5 Ex. 20, the rod with a free disk: equations and invariants. */
#include "test_paths.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/models/pendulum_5_20.hpp"
#include "eomgen/symplectic.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace {

using Pendulum = eomgen::models::pendulum_5_20::Model<double>;

const eomgen::Model& model() {
    static const eomgen::Model m = eomgen::load_model(eomgen_test::source_dir() + "/models/pendulum_5_20.toml");
    return m;
}

GiNaC::ex sym(const std::string& name) {
    for (const auto& p : model().parameters)
        if (p.name == name) return p.symbol;
    FAIL("no parameter " << name);
    return 0;
}

}  // namespace

TEST_CASE("pendulum 5-20: derived equations equal a hand derivation", "[physics][pendulum][mechanics]") {
    // By hand (θ rod angle, φ disk angle, both from the downward vertical):
    //   T = (m + 3M) l² θ̇²/6 + M a l θ̇ φ̇ cos(φ−θ) + (3/4) M a² φ̇²
    //   V = −(m + 2M) g l cos θ / 2 − M g a cos φ
    //   θ: (m+3M) l² θ̈/3 + M a l φ̈ cos(φ−θ) − M a l φ̇² sin(φ−θ) + (m+2M) g l sin θ / 2 = 0
    //   φ: (3/2) M a² φ̈ + M a l θ̈ cos(φ−θ) + M a l θ̇² sin(φ−θ) + M g a sin φ = 0
    // (the seed writes M l² for the θ̈ coefficient, cos for the last sin, and m for M in the φ equation).
    const eomgen::Model& md = model();
    const GiNaC::ex m = sym("m"), M = sym("M"), l = sym("l"), a = sym("a"), g = sym("g");
    const auto& th = md.coordinates[0];
    const auto& ph = md.coordinates[1];
    const GiNaC::ex c = GiNaC::cos(ph.q - th.q), s = GiNaC::sin(ph.q - th.q);
    const GiNaC::ex T = (m + 3 * M) * l * l * th.qd * th.qd / 6 + M * a * l * th.qd * ph.qd * c +
                        GiNaC::numeric(3, 4) * M * a * a * ph.qd * ph.qd;
    const GiNaC::ex V = -(m + 2 * M) * g * l * GiNaC::cos(th.q) / 2 - M * g * a * GiNaC::cos(ph.q);
    const GiNaC::ex eq_theta = (m + 3 * M) * l * l * th.qdd / 3 + M * a * l * ph.qdd * c -
                               M * a * l * ph.qd * ph.qd * s + (m + 2 * M) * g * l * GiNaC::sin(th.q) / 2;
    const GiNaC::ex eq_phi = GiNaC::numeric(3, 2) * M * a * a * ph.qdd + M * a * l * th.qdd * c +
                             M * a * l * th.qd * th.qd * s + M * g * a * GiNaC::sin(ph.q);

    const eomgen::Equations eq = eomgen::derive_equations(md);
    REQUIRE((eq.T - T).expand().is_zero());
    REQUIRE((eq.V - V).expand().is_zero());
    REQUIRE((eq.euler_lagrange[0] - eq_theta).expand().is_zero());
    REQUIRE((eq.euler_lagrange[1] - eq_phi).expand().is_zero());
    // The seed's φ equation (cos instead of sin, m instead of M) is not an equation of this system.
    const GiNaC::ex seed_phi = GiNaC::numeric(3, 2) * M * a * a * ph.qdd + M * a * l * th.qdd * c +
                               M * a * l * th.qd * th.qd * c + m * g * a * GiNaC::sin(ph.q);
    REQUIRE_FALSE(eomgen::is_zero(eq.euler_lagrange[1] - seed_phi, md));
    // Mass-matrix form: M q̈ − f reproduces the equations.
    for (unsigned i = 0; i < 2; ++i) {
        GiNaC::ex lhs = -eq.f[i];
        for (unsigned j = 0; j < 2; ++j) lhs += eq.M(i, j) * md.coordinates[j].qdd;
        REQUIRE((lhs - eq.euler_lagrange[i]).expand().is_zero());
    }
    REQUIRE_FALSE(eq.explicit_time);
    REQUIRE(eq.cyclic == std::vector<bool>{false, false});
    REQUIRE(eq.conserved.size() == 1);
    REQUIRE(eq.conserved[0].name == "h");
    REQUIRE((eq.energy - (T + V)).expand().is_zero());  // h = T + V for a natural system
}

TEST_CASE("pendulum 5-20: h is conserved to 1e-9 over 100 s", "[physics][pendulum]") {
    Pendulum::Params p;
    Pendulum::State x0;
    x0 << 1.2, -0.7, 0.5, 2.0;  // a lively, chaotic-looking motion
    auto f = [&p](const double& t, const Pendulum::State& x, Pendulum::State& xdot) { Pendulum::rhs(t, x, p, xdot); };
    eomgen::Dopri5Options<double> opt;
    opt.rtol = 1e-12;
    opt.atol = 1e-14;
    opt.max_steps = 1000000;
    std::vector<double> times;
    for (int k = 0; k <= 1000; ++k) times.push_back(0.1 * k);
    const auto r = eomgen::integrate(f, 0.0, x0, 100.0, opt, {}, times);
    REQUIRE(r.t == 100.0);
    const double h0 = Pendulum::energy(0, x0.head<2>(), x0.tail<2>(), p);
    double worst = 0;
    for (const auto& s : r.samples)
        worst = std::max(worst, std::abs(Pendulum::energy(s.t, s.x.head<2>(), s.x.tail<2>(), p) - h0) / std::abs(h0));
    INFO("max relative energy error " << worst);
    REQUIRE(worst <= 1e-9);
}

TEST_CASE("pendulum 5-20: the variational integrator's energy error stays bounded over 1e5 steps",
          "[physics][pendulum][symplectic]") {
    // The largest relative energy error over the first tenth, the last tenth and the whole of 10^5 steps.
    auto errors = [](const Pendulum::State& x0) {
        Pendulum::Params p;
        eomgen::VariationalIntegrator<Pendulum> vi(p, 0.01);
        vi.set_state(0.0, x0.head<2>(), x0.tail<2>());
        const double e0 = Pendulum::energy(0, x0.head<2>(), x0.tail<2>(), p);
        const std::size_t n = 100000, tenth = n / 10;
        std::array<double, 3> e{0, 0, 0};
        for (std::size_t k = 1; k <= n; ++k) {
            vi.step();
            const double err = std::abs(Pendulum::energy(vi.t(), vi.q(), vi.velocity(), p) - e0) / std::abs(e0);
            e[2] = std::max(e[2], err);
            if (k <= tenth) e[0] = std::max(e[0], err);
            if (k > n - tenth) e[1] = std::max(e[1], err);
        }
        return e;
    };
    // Bounded and oscillating (backward error analysis: a nearby Hamiltonian is conserved), no secular growth.
    SECTION("a large swing, theta = 1.2, phi = -0.7") {
        Pendulum::State x0;
        x0 << 1.2, -0.7, 0.5, 2.0;
        const std::array<double, 3> e = errors(x0);
        INFO("max relative energy error: first tenth " << e[0] << ", last tenth " << e[1] << ", all " << e[2]);
        REQUIRE(e[2] < 1e-2);
        REQUIRE(e[1] < 2 * e[0]);
    }
    SECTION("README's run (scripts/run.sh): theta = 0.5, phi = -0.3, theta' = 0.5, phi' = 2, within 5.2e-5") {
        Pendulum::State x0;
        x0 << 0.5, -0.3, 0.5, 2.0;
        const std::array<double, 3> e = errors(x0);
        INFO("max relative energy error: first tenth " << e[0] << ", last tenth " << e[1] << ", all " << e[2]);
        REQUIRE(e[2] < 5.5e-5);
        REQUIRE(e[1] < 2 * e[0]);
    }

}
