/** @file exam_radau5.cpp  Radau IIA order 5: its constants, order, stiff accuracy, dense output, events, errors. */
#include "eomgen/dopri5.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/radau5.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using V2 = Eigen::Vector2d;
using M2 = Eigen::Matrix2d;

/// x'' + x = sin 2t as [x, v] from x = 1, v = 0: x = cos t + (2/3) sin t − (1/3) sin 2t. Smooth, not stiff, and
/// time-dependent; linear, so that Newton's iteration is exact and only the method's own error is measured.
struct Forced {
    void operator()(const double& t, const V2& x, V2& xdot) const {
        xdot(0) = x(1);
        xdot(1) = -x(0) + std::sin(2 * t);
    }
    static void jacobian(const double&, const V2&, M2& J) { J << 0, 1, -1, 0; }
    static V2 exact(double t) {
        return {std::cos(t) + 2.0 / 3 * std::sin(t) - std::sin(2 * t) / 3,
                -std::sin(t) + 2.0 / 3 * std::cos(t) - 2.0 / 3 * std::cos(2 * t)};
    }
};

/// y' = L y with L = S diag(−1, −1e6) S⁻¹: a slow mode and one a million times faster.
struct StiffLinear {
    M2 S = (M2() << 1, 1, 1, -1).finished(), L;
    StiffLinear() { L = S * Eigen::Vector2d(-1, -1e6).asDiagonal() * S.inverse(); }
    void operator()(const double&, const V2& y, V2& ydot) const { ydot = L * y; }
    V2 exact(double t, const V2& y0) const {
        return S * Eigen::Vector2d(std::exp(-t), std::exp(-1e6 * t)).asDiagonal() * S.inverse() * y0;
    }
};

eomgen::Radau5Options<double> fixed_step(double h) {
    eomgen::Radau5Options<double> o;
    o.rtol = o.atol = 1;  // the error test never rejects: every step has size h
    o.h0 = o.hmax = h;
    return o;
}

}  // namespace

TEST_CASE("radau5: the Butcher matrix is collocation at Radau points, T block-diagonalizes its inverse, and d is the "
          "embedded formula's", "[runtime][radau5]") {
    using K = eomgen::Radau5<V2>;
    const auto& k = K::constants();
    const Eigen::Vector3d c(k.c1, k.c2, 1);
    for (int q = 1; q <= 3; ++q)  // C(3): Σ_j a_ij c_j^(q−1) = c_i^q / q
        CHECK((k.A * c.array().pow(q - 1).matrix() - c.array().pow(q).matrix() / q).norm() < 1e-15);
    // Radau points: roots of d²/dx² (x²(x − 1)³)... the nodes c1, c2 are the roots of 10 c² − 8 c + 1.
    CHECK(std::abs(10 * k.c1 * k.c1 - 8 * k.c1 + 1) < 1e-15);
    CHECK(std::abs(10 * k.c2 * k.c2 - 8 * k.c2 + 1) < 1e-15);
    Eigen::Matrix3d lambda = Eigen::Matrix3d::Zero();
    lambda(0, 0) = k.gamma;
    lambda.bottomRightCorner<2, 2>() << k.alpha, k.beta, -k.beta, k.alpha;
    CHECK((k.TI * k.A.inverse() * k.T - lambda).norm() < 1e-13);
    CHECK((k.TI * k.T - Eigen::Matrix3d::Identity()).norm() < 1e-14);
    // The embedded formula x̂ = x0 + h (γ0 f0 + Σ b̂_i f_i), γ0 = 1/γ, is of order 3: with d = b̂ − b,
    // γ0 + Σ d_i = 0 and Σ d_i c_i^(q−1) = 0 for q = 2, 3; and x̂ − x = γ0 h f0 + e·Z, e = dᵀ A⁻¹.
    Eigen::Matrix3d Vdm;
    Vdm.row(0).setOnes();
    Vdm.row(1) = c.transpose();
    Vdm.row(2) = c.array().square().matrix().transpose();
    const Eigen::Vector3d d = Vdm.lu().solve(Eigen::Vector3d(-1 / k.gamma, 0, 0));
    const Eigen::RowVector3d e = d.transpose() * k.A.inverse();
    CHECK((k.gamma * e - Eigen::RowVector3d(k.d1, k.d2, k.d3)).norm() < 1e-12);
}

TEST_CASE("radau5: order 5 at fixed step sizes on a smooth problem with known solution", "[runtime][radau5]") {
    const Forced f;
    const V2 x0 = Forced::exact(0);
    const double t_end = 10;
    std::vector<double> errors;
    for (const double h : {0.4, 0.2, 0.1, 0.05}) {
        const auto r = eomgen::integrate_radau5(f, Forced::jacobian, 0.0, x0, t_end, fixed_step(h));
        CHECK(r.rejected_steps == 0);
        CHECK(r.accepted_steps == std::size_t(std::llround(t_end / h)));
        errors.push_back((r.x - Forced::exact(t_end)).norm());
    }
    for (std::size_t i = 1; i < errors.size(); ++i) {
        const double order = std::log2(errors[i - 1] / errors[i]);
        INFO("h = " << 0.4 / std::pow(2, i) << ": error " << errors[i] << ", observed order " << order);
        CHECK(order > 4.7);
        CHECK(order < 5.5);
    }
}

TEST_CASE("radau5: a nonlinear orbit to its tolerance, the Jacobian reused across steps", "[runtime][radau5]") {
    // Kepler, e = 0.5, one period; the exact state after a full period is the start again.
    using V4 = Eigen::Vector4d;
    using M4 = Eigen::Matrix4d;
    const auto f = [](const double&, const V4& x, V4& xdot) {
        const double r3 = std::pow(x(0) * x(0) + x(1) * x(1), 1.5);
        xdot << x(2), x(3), -x(0) / r3, -x(1) / r3;
    };
    const auto jac = [](const double&, const V4& x, M4& J) {
        const double r2 = x(0) * x(0) + x(1) * x(1), r3 = r2 * std::sqrt(r2), r5 = r3 * r2;
        J.setZero();
        J(0, 2) = J(1, 3) = 1;
        J(2, 0) = -1 / r3 + 3 * x(0) * x(0) / r5;
        J(2, 1) = J(3, 0) = 3 * x(0) * x(1) / r5;
        J(3, 1) = -1 / r3 + 3 * x(1) * x(1) / r5;
    };
    const double e = 0.5, pi = 3.14159265358979323846;
    const V4 x0(1 - e, 0, 0, std::sqrt((1 + e) / (1 - e)));
    for (const double rtol : {1e-6, 1e-9}) {
        eomgen::Radau5Options<double> o;
        o.rtol = rtol;
        o.atol = rtol;
        const auto r = eomgen::integrate_radau5(f, jac, 0.0, x0, 2 * pi, o);
        INFO("rtol " << rtol << ": error " << (r.x - x0).norm() << ", " << r.accepted_steps << " steps, "
                     << r.jacobian_evaluations << " Jacobians, " << r.lu_decompositions << " LU");
        CHECK((r.x - x0).norm() < 300 * rtol);
        CHECK((r.x - x0).norm() > 1e-3 * rtol);  // the tolerance is what limits it
        CHECK(r.jacobian_evaluations < r.accepted_steps);
        CHECK(r.lu_decompositions <= r.accepted_steps + r.rejected_steps);
    }
}

TEST_CASE("radau5: eigenvalues -1 and -1e6, accurate in far fewer steps than dopri5", "[runtime][radau5][stiff]") {
    const StiffLinear f;
    const auto jac = [&f](const double&, const V2&, M2& J) { J = f.L; };
    const V2 y0(2, 0);  // both modes excited
    std::vector<double> times;
    for (int k = 0; k <= 20; ++k) times.push_back(0.05 * k);
    eomgen::Radau5Options<double> o;
    o.rtol = 1e-8;
    o.atol = 1e-10;
    const auto r = eomgen::integrate_radau5(f, jac, 0.0, y0, 1.0, o, {}, times);
    double worst = 0;
    for (const auto& s : r.samples) worst = std::max(worst, (s.x - f.exact(s.t, y0)).norm());
    INFO("radau5: " << r.accepted_steps << " steps, " << r.rhs_evaluations << " rhs, worst sample error " << worst);
    CHECK((r.x - f.exact(1.0, y0)).norm() < 1e-8);
    CHECK(worst < 1e-7);
    CHECK(r.accepted_steps < 200);
    // dopri5 is held to |h λ| ≲ 3.3 by stability, whatever its tolerance: ~3e5 steps for t in [0, 1].
    eomgen::Dopri5Options<double> od;
    od.rtol = 1e-8;
    od.atol = 1e-10;
    od.max_steps = 2000000;
    const auto d = eomgen::integrate(f, 0.0, y0, 1.0, od);
    INFO("dopri5: " << d.accepted_steps << " steps, " << d.rhs_evaluations << " rhs");
    CHECK(d.accepted_steps > 1000 * r.accepted_steps);
    CHECK(d.rhs_evaluations > 100 * r.rhs_evaluations);
}

TEST_CASE("radau5: samples and events on the collocation polynomial, backwards too", "[runtime][radau5]") {
    const Forced f;
    const V2 x0 = Forced::exact(0);
    eomgen::Radau5Options<double> o;
    o.rtol = 1e-10;
    o.atol = 1e-12;
    // x falls through 0 first near t = 1.9 (found on the closed form by bisection).
    double lo = 1, hi = 2.5;
    for (int i = 0; i < 200; ++i) (Forced::exact(0.5 * (lo + hi))(0) > 0 ? lo : hi) = 0.5 * (lo + hi);
    const std::vector<eomgen::Event<V2>> events{
        {"x=0", [](const double&, const V2& x) { return x(0); }, eomgen::EventDirection::Falling,
         eomgen::EventAction::Stop}};
    std::vector<double> times;
    for (int k = 0; k <= 50; ++k) times.push_back(0.1 * k);
    const auto r = eomgen::integrate_radau5(f, Forced::jacobian, 0.0, x0, 5.0, o, events, times);
    REQUIRE(r.stop_reason == eomgen::StopReason::TerminalEvent);
    REQUIRE(r.events.size() == 1);
    CHECK(std::abs(r.events[0].t - lo) < 1e-8);
    CHECK(std::abs(r.x(0)) < 1e-8);
    REQUIRE(!r.samples.empty());
    CHECK(r.samples.back().t <= r.t);
    double worst = 0;
    for (const auto& s : r.samples) worst = std::max(worst, (s.x - Forced::exact(s.t)).norm());
    CHECK(worst < 1e-8);
    // Backwards from t = 3 to 0 lands on the start.
    const auto b = eomgen::integrate_radau5(f, Forced::jacobian, 3.0, Forced::exact(3.0), 0.0, o);
    CHECK(b.t == 0.0);
    CHECK((b.x - x0).norm() < 1e-8);
}

TEST_CASE("radau5: a clear error when Newton fails down to hmin, on non-finite values and too many steps",
          "[runtime][radau5][errors]") {
    // A Jacobian of the wrong sign: for h above ~1e-4 the simplified Newton iteration diverges.
    const auto f = [](const double&, const V2& x, V2& xdot) { xdot = -1e4 * x; };
    const auto wrong = [](const double&, const V2&, M2& J) { J = 1e4 * M2::Identity(); };
    eomgen::Radau5Options<double> o;
    o.hmin = 1e-3;
    o.h0 = 0.01;
    try {
        eomgen::integrate_radau5(f, wrong, 0.0, V2(1, 1), 1.0, o);
        FAIL("no error");
    } catch (const eomgen::StepSizeUnderflow& e) {
        CHECK_THAT(e.what(), Catch::Contains("Newton's iteration") && Catch::Contains("did not converge") &&
                                 Catch::Contains("at t = 0 with state [1, 1]"));
    }
    // f blows up at t = 0.5: the steps shrink onto it and the error names a non-finite value.
    const auto blows = [](const double& t, const V2& x, V2& xdot) {
        xdot = t < 0.5 ? V2(-x) : V2(std::numeric_limits<double>::quiet_NaN(), 0);
    };
    const auto jac = [](const double&, const V2&, M2& J) { J = -M2::Identity(); };
    CHECK_THROWS_AS(eomgen::integrate_radau5(blows, jac, 0.0, V2(1, 1), 1.0), eomgen::NonFiniteState);
    const auto nan_jac = [](const double&, const V2&, M2& J) { J.setConstant(std::nan("")); };
    CHECK_THROWS_WITH(eomgen::integrate_radau5(f, nan_jac, 0.0, V2(1, 1), 1.0),
                      Catch::Contains("Jacobian of the right-hand side is not finite"));
    eomgen::Radau5Options<double> few;
    few.max_steps = 5;
    CHECK_THROWS_AS(eomgen::integrate_radau5(Forced(), Forced::jacobian, 0.0, V2(1, 0), 100.0, few),
                    eomgen::TooManySteps);
}

TEST_CASE("radau5: long double and a dynamic-size state", "[runtime][radau5]") {
    using VL = Eigen::Matrix<long double, 2, 1>;
    using ML = Eigen::Matrix<long double, 2, 2>;
    const auto f = [](const long double&, const VL& x, VL& xdot) { xdot << x(1), -x(0); };
    const auto jac = [](const long double&, const VL&, ML& J) { J << 0, 1, -1, 0; };
    eomgen::Radau5Options<long double> o;
    o.rtol = 1e-14L;
    o.atol = 1e-16L;
    const auto r = eomgen::integrate_radau5(f, jac, 0.0L, VL(1, 0), 1.0L, o);
    CHECK(std::abs(double(r.x(0) - std::cos(1.0L))) < 1e-13);
    using VX = Eigen::VectorXd;
    const auto g = [](const double&, const VX& x, VX& xdot) { xdot = -x; };
    const auto gj = [](const double&, const VX& x, Eigen::MatrixXd& J) {
        J = -Eigen::MatrixXd::Identity(x.size(), x.size());
    };
    const auto d = eomgen::integrate_radau5(g, gj, 0.0, VX(VX::Ones(3)), 2.0);
    CHECK((d.x - VX::Constant(3, std::exp(-2.0))).norm() < 1e-5);
}
