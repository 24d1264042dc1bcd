/** @file exam_modes.cpp  Small oscillations (mechanics/small_oscillations.hpp) against closed forms derived here
 * by hand, finite differences of generated right-hand sides, and simulations at small amplitude. */
#include "eomgen/events.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/models/bead_on_hoop.hpp"
#include "eomgen/models/pendulum_5_20.hpp"
#include "eomgen/models/pendulum_cartesian.hpp"
#include "mechanics/lagrangian.hpp"
#include "mechanics/small_oscillations.hpp"
#include "model/model_file.hpp"
#include "modes_support.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <random>

namespace {

using modes_support::at;
using modes_support::derive;
using modes_support::Derived;
using modes_support::load;

GiNaC::symbol param(const eomgen::Model& m, const std::string& name) {
    for (const auto& p : m.parameters)
        if (p.name == name) return p.symbol;
    FAIL("no parameter " << name);
    return GiNaC::symbol();
}

double eval(const GiNaC::ex& e, const GiNaC::exmap& at) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
}

const std::string kDoublePendulum = R"toml(name = "double_pendulum"
[[coordinates]]
name = "a"
[[coordinates]]
name = "b"
[[parameters]]
name = "m1"
value = 1.3
[[parameters]]
name = "m2"
value = 0.7
[[parameters]]
name = "l1"
value = 0.9
[[parameters]]
name = "l2"
value = 1.4
[[parameters]]
name = "g"
value = 9.81
[lagrangian]
T = "(m1+m2)/2*l1^2*a'^2 + m2/2*l2^2*b'^2 + m2*l1*l2*a'*b'*cos(a-b)"
V = "-(m1+m2)*g*l1*cos(a) - m2*g*l2*cos(b)"
)toml";

}  // namespace

TEST_CASE("modes: double pendulum, both frequencies and shapes in closed form for any masses and lengths",
          "[physics][modes]") {
    // By hand about θ1 = θ2 = 0: M0 = [[(m1+m2) l1², m2 l1 l2], [m2 l1 l2, m2 l2²]], K0 = diag((m1+m2) g l1, m2 g l2);
    // det(K0 − ω² M0) = m1 m2 l1² l2² ω⁴ − (m1+m2) m2 g l1 l2 (l1+l2) ω² + (m1+m2) m2 g² l1 l2 = 0, so
    //   ω² = (m1+m2) g [(l1+l2) ∓ √((l1+l2)² − 4 m1 l1 l2/(m1+m2))] / (2 m1 l1 l2),
    // and from the first row the shape has b/a = (m1+m2)(g − ω² l1)/(m2 l2 ω²).
    const Derived d = derive(kDoublePendulum);
    const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, {});
    const eomgen::Equilibrium& e = at(r, {0, 0});
    CHECK(e.stability == eomgen::Stability::Stable);
    REQUIRE(e.modes.size() == 2);
    const auto m1 = param(d.model, "m1"), m2 = param(d.model, "m2"), l1 = param(d.model, "l1"),
               l2 = param(d.model, "l2"), g = param(d.model, "g");
    auto hand = [](double M1, double M2, double L1, double L2, double G, int sign) {
        const double s = L1 + L2, root = std::sqrt(s * s - 4 * M1 * L1 * L2 / (M1 + M2));
        return (M1 + M2) * G * (s + sign * root) / (2 * M1 * L1 * L2);
    };
    for (int k = 0; k < 2; ++k) {
        const eomgen::NormalMode& mode = e.modes[std::size_t(k)];
        CHECK(mode.omega2 == Approx(hand(1.3, 0.7, 0.9, 1.4, 9.81, k == 0 ? -1 : 1)).epsilon(1e-12));
        const double ratio = (2.0) * (9.81 - mode.omega2 * 0.9) / (0.7 * 1.4 * mode.omega2);
        CHECK(mode.shape[1] / mode.shape[0] == Approx(ratio).epsilon(1e-9));
        // The exact ω² is the hand formula for any parameters, not only the model's.
        REQUIRE(mode.omega2_exact);
        std::mt19937 rng(5 + unsigned(k));
        std::uniform_real_distribution<double> u(0.3, 3);
        for (int trial = 0; trial < 5; ++trial) {
            const double M1 = u(rng), M2 = u(rng), L1 = u(rng), L2 = u(rng), G = 9.81 * u(rng);
            const GiNaC::exmap values{{m1, M1}, {m2, M2}, {l1, L1}, {l2, L2}, {g, G}};
            CHECK(eval(*mode.omega2_exact, values) == Approx(hand(M1, M2, L1, L2, G, k == 0 ? -1 : 1)).epsilon(1e-10));
        }
    }
    // Equal masses and lengths: ω² = (g/l)(2 ∓ √2).
    eomgen::ModesOptions equal;
    equal.set = {{"m1", 1}, {"m2", 1}, {"l1", 2}, {"l2", 2}};
    const eomgen::ModesResult r2 = eomgen::small_oscillations(d.model, d.eq, equal);
    const eomgen::Equilibrium& e2 = at(r2, {0, 0});
    CHECK(e2.modes[0].omega2 == Approx(9.81 / 2 * (2 - std::sqrt(2.0))).epsilon(1e-12));
    CHECK(e2.modes[1].omega2 == Approx(9.81 / 2 * (2 + std::sqrt(2.0))).epsilon(1e-12));
    // The other three equilibria (one or both rods up) are unstable.
    REQUIRE(r.equilibria.size() == 4);
    for (const auto& other : r.equilibria)
        if (other.q != std::vector<double>{0, 0}) CHECK(other.stability == eomgen::Stability::Unstable);
}

TEST_CASE("modes: the linear symmetric triatomic molecule (Goldstein 6.4)", "[physics][modes]") {
    const Derived d = derive(R"toml(name = "triatomic"
[[coordinates]]
name = "x1"
[[coordinates]]
name = "x2"
initial = 1.1
[[coordinates]]
name = "x3"
initial = 2.2
[[parameters]]
name = "m"
value = 1.7
[[parameters]]
name = "M"
value = 2.9
[[parameters]]
name = "k"
value = 3.1
[[parameters]]
name = "b"
value = 1.1
[lagrangian]
T = "m/2*(x1'^2 + x3'^2) + M/2*x2'^2"
V = "k/2*(x2 - x1 - b)^2 + k/2*(x3 - x2 - b)^2"
)toml");
    const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, {});
    // One family of equilibria (a free translation), reported once, with its zero mode.
    REQUIRE(r.equilibria.size() == 1);
    const eomgen::Equilibrium& e = r.equilibria[0];
    CHECK(e.q[1] - e.q[0] == Approx(1.1));
    CHECK(e.q[2] - e.q[1] == Approx(1.1));
    CHECK(e.stability == eomgen::Stability::Marginal);
    const double m = 1.7, M = 2.9, k = 3.1;
    REQUIRE(e.modes.size() == 3);
    CHECK(e.modes[0].omega2 == 0);
    CHECK(e.modes[1].omega2 == Approx(k / m).epsilon(1e-12));
    CHECK(e.modes[2].omega2 == Approx(k / m * (1 + 2 * m / M)).epsilon(1e-12));
    for (const double c : e.modes[0].shape) CHECK(c == Approx(1).epsilon(1e-12));
    CHECK(e.modes[1].shape[1] == 0);
    CHECK(e.modes[1].shape[0] == Approx(-e.modes[1].shape[2]));
    CHECK(e.modes[2].shape[1] / e.modes[2].shape[0] == Approx(-2 * m / M).epsilon(1e-10));
    // Exact: k/m and (k/m)(1 + 2m/M).
    const GiNaC::exmap values{{param(d.model, "m"), 0.37}, {param(d.model, "M"), 1.9}, {param(d.model, "k"), 5.0}};
    REQUIRE(e.modes[2].omega2_exact);
    CHECK(eval(*e.modes[1].omega2_exact, values) == Approx(5.0 / 0.37));
    CHECK(eval(*e.modes[2].omega2_exact, values) == Approx(5.0 / 0.37 * (1 + 2 * 0.37 / 1.9)));
    CHECK_FALSE(r.notes.empty());  // the zero mode is explained
}

TEST_CASE("modes: the triatomic molecule in SI units of atoms is marginally stable, its eigenvalues ±iω",
          "[physics][modes]") {
    // M⁻¹K ~ 1e29 beside the 1s of the first-order system: unscaled, the eigen-solver gave the zero mode as ±8e20
    // and called carbon dioxide unstable.
    const Derived d = derive(R"toml(name = "co2"
[[coordinates]]
name = "x1"
[[coordinates]]
name = "x2"
[[coordinates]]
name = "x3"
[[parameters]]
name = "M"
value = 2.66e-26
[[parameters]]
name = "m"
value = 1.993e-26
[[parameters]]
name = "k"
value = 3628
[lagrangian]
T = "M/2*x1'^2 + m/2*x2'^2 + M/2*x3'^2"
V = "k/2*(x2 - x1)^2 + k/2*(x3 - x2)^2"
)toml");
    const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, {});
    REQUIRE(r.equilibria.size() == 1);
    const eomgen::Equilibrium& e = r.equilibria[0];
    CHECK(e.stability == eomgen::Stability::Marginal);
    const double M = 2.66e-26, m = 1.993e-26, k = 3628;
    REQUIRE(e.modes.size() == 3);
    CHECK(e.modes[1].omega2 == Approx(k / M).epsilon(1e-9));
    CHECK(e.modes[2].omega2 == Approx(k / M * (1 + 2 * M / m)).epsilon(1e-9));
    REQUIRE(e.eigenvalues.size() == 6);
    for (const std::complex<double>& z : e.eigenvalues) CHECK(std::abs(z.real()) <= 1e-6 * std::sqrt(k / m));
    CHECK(std::abs(e.eigenvalues.front()) == Approx(std::sqrt(e.modes[2].omega2)).epsilon(1e-9));
}

TEST_CASE("modes: bead on a spinning hoop, stable at the bottom below w^2 = g/R, off axis above",
          "[physics][modes]") {
    // L = ½ m R² (ȧ² + w² sin² a) + m g R cos a: V_eff = −m g R cos a − ½ m R² w² sin² a, M = m R².
    // V_eff'' = m g R cos a − m R² w² cos 2a: at a = 0 ω² = g/R − w²; where cos a0 = g/(R w²), ω² = w² sin² a0.
    const Derived d = load("examples/bead_on_hoop.toml");
    const double R = 0.5, g = 9.81;
    {
        eomgen::ModesOptions slow;
        slow.set["w"] = 3;
        const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, slow);
        REQUIRE(r.equilibria.size() == 2);
        const auto& bottom = at(r, {0});
        CHECK(bottom.stability == eomgen::Stability::Stable);
        CHECK(bottom.modes[0].omega2 == Approx(g / R - 9).epsilon(1e-12));
        CHECK(at(r, {3.141592653589793}).stability == eomgen::Stability::Unstable);
    }
    eomgen::ModesOptions fast;
    fast.set["w"] = 6;
    const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, fast);
    REQUIRE(r.equilibria.size() == 4);
    const auto& bottom = at(r, {0});
    CHECK(bottom.stability == eomgen::Stability::Unstable);
    CHECK(bottom.growth_rate == Approx(std::sqrt(36 - g / R)).epsilon(1e-10));
    const double a0 = std::acos(g / (R * 36));
    for (const double side : {-1.0, 1.0}) {
        const auto& off = at(r, {side * a0});
        CHECK(off.stability == eomgen::Stability::Stable);
        CHECK(off.modes[0].omega2 == Approx(36 * std::sin(a0) * std::sin(a0)).epsilon(1e-10));
        REQUIRE(off.exact[0]);
        REQUIRE(off.modes[0].omega2_exact);
        const GiNaC::exmap values{{param(d.model, "w"), 6}, {param(d.model, "R"), R}, {param(d.model, "g"), g},
                                  {param(d.model, "m"), 0.1}};
        CHECK(eval(*off.exact[0], values) == Approx(side * a0));
        CHECK(eval(*off.modes[0].omega2_exact, values) == Approx(36 * std::sin(a0) * std::sin(a0)).epsilon(1e-12));
    }
}

TEST_CASE("modes: the sleeping top is stable exactly when I3^2 w3^2 > 4 I M g l (Routh, p_phi = p_psi)",
          "[physics][modes]") {
    // With p_φ = p_ψ = b = I3 ω3 the amended potential near θ = 0 is M g l (1 − θ²/2) + b² θ²/(8 I) + O(θ⁴),
    // I = I1 + M l² about the pivot: K0 = b²/(4 I) − M g l, M0 = I.
    const Derived d = load("models/heavy_symmetric_top.toml");
    const double M = 0.5, l = 0.05, I1 = 0.0004, g = 9.81, I = I1 + M * l * l;
    const double critical = std::sqrt(4 * I * M * g * l);
    for (const double factor : {1.2, 0.8}) {
        const double b = factor * critical;
        eomgen::ModesOptions o;
        o.momentum = {{"p_phi", b}, {"p_psi", b}};
        const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, o);
        REQUIRE(r.coordinates == std::vector<std::string>{"theta"});
        const auto& sleeping = at(r, {0});
        const double K = b * b / (4 * I) - M * g * l;
        CHECK(sleeping.M[0][0] == Approx(I).epsilon(1e-12));
        CHECK(sleeping.K[0][0] == Approx(K).epsilon(1e-9));
        if (factor > 1) {
            CHECK(sleeping.stability == eomgen::Stability::Stable);
            CHECK(sleeping.modes[0].omega2 == Approx(K / I).epsilon(1e-9));
        } else {
            CHECK(sleeping.stability == eomgen::Stability::Unstable);
            CHECK(sleeping.growth_rate == Approx(std::sqrt(-K / I)).epsilon(1e-9));
        }
    }
    eomgen::ModesOptions wrong;
    wrong.momentum = {{"p_theta", 1}};
    CHECK_THROWS_AS(eomgen::small_oscillations(d.model, d.eq, wrong), eomgen::ModesError);
}

TEST_CASE("modes: the linearization equals finite differences of the generated rhs, and a small motion "
          "oscillates at the predicted frequency",
          "[physics][modes]") {
    using P = eomgen::models::pendulum_5_20::Model<double>;
    const Derived d = load("models/pendulum_5_20.toml");
    const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, {});
    const eomgen::Equilibrium& e = at(r, {0, 0});
    REQUIRE(e.stability == eomgen::Stability::Stable);
    Eigen::Matrix2d M, K, D;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            M(i, j) = e.M[std::size_t(i)][std::size_t(j)];
            K(i, j) = e.K[std::size_t(i)][std::size_t(j)];
            D(i, j) = e.C[std::size_t(i)][std::size_t(j)] + e.G[std::size_t(i)][std::size_t(j)];
        }
    Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
    A.topRightCorner<2, 2>().setIdentity();
    A.bottomLeftCorner<2, 2>() = -M.inverse() * K;
    A.bottomRightCorner<2, 2>() = -M.inverse() * D;
    // Central differences of the generated rhs at the equilibrium (error O(h²) ~ 1e-10).
    const P::Params p;
    Eigen::Matrix4d fd;
    const double h = 1e-5;
    for (int j = 0; j < 4; ++j) {
        P::State xp = P::State::Zero(), xm = P::State::Zero(), fp, fm;
        xp(j) = h;
        xm(j) = -h;
        P::rhs(0.0, xp, p, fp);
        P::rhs(0.0, xm, p, fm);
        fd.col(j) = (fp - fm) / (2 * h);
    }
    CHECK((fd - A).cwiseAbs().maxCoeff() <= 1e-7 * A.cwiseAbs().maxCoeff());

    // Start in each mode's shape at amplitude 1e-5 and time the zero crossings of theta.
    for (const eomgen::NormalMode& mode : e.modes) {
        const double omega = std::sqrt(mode.omega2);
        P::State x0 = P::State::Zero();
        x0(0) = 1e-5 * mode.shape[0];
        x0(1) = 1e-5 * mode.shape[1];
        std::vector<double> crossings;
        eomgen::Event<P::State> up{"theta up", [](const double&, const P::State& x) { return x(0); },
                                   eomgen::EventDirection::Rising, eomgen::EventAction::Record};
        auto f = [&p](const double& t, const P::State& x, P::State& xdot) { P::rhs(t, x, p, xdot); };
        eomgen::Dopri5Options<double> opt;
        opt.rtol = 1e-13;
        opt.atol = 1e-19;
        const double periods = 6, t_end = periods * 2 * M_PI / omega + 0.5 * M_PI / omega;
        const auto result = eomgen::integrate(f, 0.0, x0, t_end, opt, std::vector<eomgen::Event<P::State>>{up});
        for (const auto& ev : result.events) crossings.push_back(ev.t);
        REQUIRE(crossings.size() >= 5);
        const double period = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
        CHECK(2 * M_PI / period == Approx(omega).epsilon(1e-6));
    }
}

TEST_CASE("modes: an unstable equilibrium's growth in a simulation matches its eigenvalue", "[physics][modes]") {
    using B = eomgen::models::bead_on_hoop::Model<double>;
    const Derived d = load("examples/bead_on_hoop.toml");
    const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, {});  // w = 6: a = 0 unstable
    const eomgen::Equilibrium& bottom = at(r, {0});
    REQUIRE(bottom.stability == eomgen::Stability::Unstable);
    const double rate = bottom.growth_rate;
    // Along the growing mode: a = ε e^{λt}, ȧ = λ a; at a = 1e-4 the nonlinear part is ~1e-8 relative.
    const B::Params p;
    B::State x0;
    x0 << 1e-9, rate * 1e-9;
    auto f = [&p](const double& t, const B::State& x, B::State& xdot) { B::rhs(t, x, p, xdot); };
    eomgen::Dopri5Options<double> opt;
    opt.rtol = 1e-13;
    opt.atol = 1e-22;
    const double t_end = std::log(1e5) / rate;  // a grows by 1e5
    const auto result = eomgen::integrate(f, 0.0, x0, t_end, opt);
    CHECK(std::log(result.x(0) / 1e-9) / t_end == Approx(rate).epsilon(1e-6));
}

TEST_CASE("modes: the inverted pendulum on a cart, A and B of the control textbooks", "[physics][modes]") {
    // Linearized about the upright rod (θ = 0): (M + m) ẍ + m l θ̈ = F, m l ẍ + m l² θ̈ − m g l θ = 0, so
    // ẍ = (F − m g θ)/M and θ̈ = ((M + m) g θ − F)/(M l).
    const Derived d = load("tests/physics/cart_pendulum.toml");
    eomgen::ModesOptions o;
    o.inputs = {"F"};
    const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, o);
    const eomgen::Equilibrium& up = at(r, {0, 0});
    const double M = 1.0, m = 0.2, l = 0.5, g = 9.81;
    const std::vector<std::vector<double>> A = {{0, 0, 1, 0}, {0, 0, 0, 1}, {0, -m * g / M, 0, 0},
                                                {0, (M + m) * g / (M * l), 0, 0}};
    const std::vector<std::vector<double>> B = {{0}, {0}, {1 / M}, {-1 / (M * l)}};
    for (std::size_t i = 0; i < 4; ++i) {
        for (std::size_t j = 0; j < 4; ++j) CHECK(up.A[i][j] == Approx(A[i][j]).margin(1e-12));
        CHECK(up.B[i][0] == Approx(B[i][0]).margin(1e-12));
    }
    CHECK(up.stability == eomgen::Stability::Unstable);
    CHECK(up.growth_rate == Approx(std::sqrt((M + m) * g / (M * l))).epsilon(1e-10));
}

namespace {

/// Central differences of M's rhs in x and in the parameters (set_param by name), step h.
template <class M>
void finite_differences(const typename M::State& x, const typename M::Params& p, Eigen::MatrixXd& A, Eigen::MatrixXd& B) {
    const double h = 1e-6;
    A.resize(M::nx, M::nx);
    B.resize(M::nx, M::n_params);
    typename M::State fp, fm;
    for (int j = 0; j < M::nx; ++j) {
        typename M::State xp = x, xm = x;
        xp(j) += h;
        xm(j) -= h;
        M::rhs(0.0, xp, p, fp);
        M::rhs(0.0, xm, p, fm);
        A.col(j) = (fp - fm) / (2 * h);
    }
    const auto values = M::param_values(p);
    for (int k = 0; k < M::n_params; ++k) {
        typename M::Params pp = p, pm = p;
        M::set_param(pp, M::param_names[std::size_t(k)], values[std::size_t(k)] + h);
        M::set_param(pm, M::param_names[std::size_t(k)], values[std::size_t(k)] - h);
        M::rhs(0.0, x, pp, fp);
        M::rhs(0.0, x, pm, fm);
        B.col(k) = (fp - fm) / (2 * h);
    }
}

}  // namespace

TEST_CASE("linearization(): the generated header's A and B by forward differentiation, at any state, with and "
          "without constraints",
          "[physics][modes][linearize]") {
    using P = eomgen::models::pendulum_5_20::Model<double>;
    const P::Params p;
    // At the equilibrium: the A of eomgen modes.
    P::StateJacobian A;
    P::ParameterJacobian B;
    P::linearization(0.0, P::State::Zero(), p, A, B);
    const Derived d = load("models/pendulum_5_20.toml");
    const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, {});
    const eomgen::Equilibrium& e = at(r, {0, 0});
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) CHECK(A(i, j) == Approx(e.A[std::size_t(i)][std::size_t(j)]).margin(1e-12));
    // At states away from rest: finite differences (error O(h²) ~ 1e-9 of the entries).
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    for (int trial = 0; trial < 3; ++trial) {
        P::State x;
        for (int i = 0; i < 4; ++i) x(i) = u(rng);
        P::linearization(0.0, x, p, A, B);
        Eigen::MatrixXd fa, fb;
        finite_differences<P>(x, p, fa, fb);
        CHECK((fa - A).cwiseAbs().maxCoeff() <= 1e-6 * (1 + A.cwiseAbs().maxCoeff()));
        CHECK((fb - B).cwiseAbs().maxCoeff() <= 1e-6 * (1 + B.cwiseAbs().maxCoeff()));
    }
    // Through the constrained solve (the multipliers depend on x and p too).
    using C = eomgen::models::pendulum_cartesian::Model<double>;
    const C::Params pc;
    const C::State xc = C::default_state();
    C::StateJacobian Ac;
    C::ParameterJacobian Bc;
    C::linearization(0.0, xc, pc, Ac, Bc);
    Eigen::MatrixXd fa, fb;
    finite_differences<C>(xc, pc, fa, fb);
    CHECK((fa - Ac).cwiseAbs().maxCoeff() <= 1e-6 * (1 + Ac.cwiseAbs().maxCoeff()));
    CHECK((fb - Bc).cwiseAbs().maxCoeff() <= 1e-6 * (1 + Bc.cwiseAbs().maxCoeff()));
}
