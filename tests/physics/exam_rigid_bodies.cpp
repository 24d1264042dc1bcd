/** @file exam_rigid_bodies.cpp  Rigid bodies of the seed from their body descriptions: the torque-free top
 *  (Derivation 5-6) from simulated trajectories, the rolling cone (5-17) simulated with its constraints, and a
 *  trajectory that runs into the singular configuration of its coordinates. */
#include "eomgen/constraints.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/models/damped_spherical_pendulum.hpp"
#include "eomgen/models/rolling_cone.hpp"
#include "eomgen/models/torque_free_top.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace {

using Top = eomgen::models::torque_free_top::Model<double>;
using Cone = eomgen::models::rolling_cone::Model<double>;
using Spherical = eomgen::models::damped_spherical_pendulum::Model<double>;

eomgen::Dopri5Options<double> tight() {
    eomgen::Dopri5Options<double> o;
    o.rtol = 1e-13;
    o.atol = 1e-15;
    o.max_steps = 10000000;
    return o;
}

std::vector<double> grid(double t_end, int n) {
    std::vector<double> t;
    for (int k = 1; k <= n; ++k) t.push_back(t_end * k / n);
    return t;
}

/// Angular velocity in body axes from z-x-z Euler angles, Goldstein (4.87), written out here rather than
/// taken from the generator, so that the test does not check the generator against itself.
Eigen::Vector3d omega_body(const Top::State& x) {
    const double th = x(1), ps = x(2), phd = x(3), thd = x(4), psd = x(5);
    return {phd * std::sin(th) * std::sin(ps) + thd * std::cos(ps),
            phd * std::sin(th) * std::cos(ps) - thd * std::sin(ps), phd * std::cos(th) + psd};
}

/// A (space → body) of z-x-z Euler angles, Goldstein (4.46): A = R_z(ψ) R_x(θ) R_z(φ), passive rotations.
Eigen::Matrix3d rotation(const Top::State& x) {
    using Eigen::AngleAxisd;
    const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Z = Eigen::Vector3d::UnitZ();
    const Eigen::Matrix3d active = (AngleAxisd(x(0), Z) * AngleAxisd(x(1), X) * AngleAxisd(x(2), Z)).toRotationMatrix();
    return active.transpose();
}

/// Unwrapped angle of successive planar vectors: the running sum of the angles between neighbours.
class Unwrap {
public:
    double add(double a) {
        if (!started_) {
            started_ = true;
            first_ = last_ = a;
            return 0;
        }
        double d = a - last_;
        while (d > M_PI) d -= 2 * M_PI;
        while (d < -M_PI) d += 2 * M_PI;
        total_ += d;
        last_ = a;
        return total_;
    }

private:
    bool started_ = false;
    double first_ = 0, last_ = 0, total_ = 0;
};

auto top_rhs(const Top::Params& p) {
    return [p](const double& t, const Top::State& x, Top::State& xdot) { Top::rhs(t, x, p, xdot); };
}

}  // namespace

TEST_CASE("5-6 torque-free top with L along z: theta constant, phi' = I3 w3/(I cos theta), psi' = -Omega",
          "[physics][bodies][top]") {
    Top::Params p;
    const Top::State x0 = Top::default_state();
    const double th0 = x0(1), w3 = x0(5) + x0(3) * std::cos(th0);
    const double Omega = w3 * (p.I3 - p.I1) / p.I1;
    // The default state is the one of the model's description: L along the space z axis.
    const Eigen::Vector3d L0 = rotation(x0).transpose() * (Eigen::Vector3d(p.I1, p.I1, p.I3).asDiagonal() * omega_body(x0));
    REQUIRE(std::hypot(L0(0), L0(1)) <= 1e-14 * L0.norm());

    const double t_end = 40;
    const auto r = eomgen::integrate(top_rhs(p), 0.0, x0, t_end, tight(), {}, grid(t_end, 400));
    REQUIRE(r.samples.size() == 400);
    double worst_theta = 0;
    for (const auto& s : r.samples) worst_theta = std::max(worst_theta, std::abs(s.x(1) - th0));
    INFO("max |theta - theta0| = " << worst_theta);
    CHECK(worst_theta <= 1e-11);
    // Rates measured from the trajectory, against the closed forms of the seed.
    const double phi_rate = (r.x(0) - x0(0)) / t_end, psi_rate = (r.x(2) - x0(2)) / t_end;
    const double phi_expected = p.I3 * w3 / (p.I1 * std::cos(th0));
    INFO("phi' " << phi_rate << " vs " << phi_expected << " (relative error " << std::abs(phi_rate / phi_expected - 1)
                 << "); psi' " << psi_rate << " vs " << -Omega << " (" << std::abs(psi_rate / -Omega - 1) << ")");
    CHECK(std::abs(phi_rate - phi_expected) <= 1e-8 * std::abs(phi_expected));
    CHECK(std::abs(psi_rate + Omega) <= 1e-8 * std::abs(Omega));
}

TEST_CASE("5-6 torque-free top from a general state: Omega in the body, |L|/I about L, sin theta' relation",
          "[physics][bodies][top]") {
    Top::Params p;
    p.I1 = 0.8;
    p.I3 = 1.3;
    Top::State x0;
    x0 << 0.4, 1.1, -0.3, 0.7, 0.45, 2.1;  // L is not along any space axis
    const Eigen::Vector3d I(p.I1, p.I1, p.I3);
    const double t_end = 30;
    const auto r = eomgen::integrate(top_rhs(p), 0.0, x0, t_end, tight(), {}, grid(t_end, 3000));
    REQUIRE(r.samples.size() == 3000);

    const Eigen::Vector3d w0 = omega_body(x0);
    const double w3 = w0(2), Omega = w3 * (p.I3 - p.I1) / p.I1;
    const Eigen::Vector3d L = rotation(x0).transpose() * (I.asDiagonal() * w0);
    const Eigen::Vector3d Lhat = L.normalized();
    const Eigen::Vector3d b1 = Lhat.unitOrthogonal(), b2 = Lhat.cross(b1);
    const double cos_theta = (rotation(x0).row(2).dot(Lhat));  // body z axis in space: row 3 of A

    Unwrap body_angle, axis_angle;
    body_angle.add(std::atan2(w0(1), w0(0)));
    const Eigen::Vector3d e30 = rotation(x0).row(2).transpose();
    axis_angle.add(std::atan2(e30.dot(b2), e30.dot(b1)));
    double worst_L = 0, worst_w3 = 0, worst_cos = 0, worst_sine = 0, turned_body = 0, turned_axis = 0;
    for (const auto& s : r.samples) {
        const Eigen::Matrix3d A = rotation(s.x);
        const Eigen::Vector3d w = omega_body(s.x);
        const Eigen::Vector3d Ls = A.transpose() * (I.asDiagonal() * w);
        const Eigen::Vector3d e3 = A.row(2).transpose();
        worst_L = std::max(worst_L, (Ls - L).norm() / L.norm());
        worst_w3 = std::max(worst_w3, std::abs(w(2) - w3) / std::abs(w3));
        worst_cos = std::max(worst_cos, std::abs(e3.dot(Lhat) - cos_theta));
        turned_body = body_angle.add(std::atan2(w(1), w(0)));
        turned_axis = axis_angle.add(std::atan2(e3.dot(b2), e3.dot(b1)));
        // θ′ between ω and L, θ″ between ω and the symmetry axis: sin θ′ = ((I3 − I)/I3) cos θ sin θ″.
        const Eigen::Vector3d ws = A.transpose() * w;
        const double sin1 = ws.cross(Lhat).norm() / ws.norm(), sin2 = std::hypot(w(0), w(1)) / w.norm();
        worst_sine = std::max(worst_sine, std::abs(sin1 - std::abs((p.I3 - p.I1) / p.I3 * cos_theta) * sin2));
    }
    INFO("L drift " << worst_L << ", w3 drift " << worst_w3 << ", cos theta drift " << worst_cos
                    << ", sin theta' relation " << worst_sine);
    CHECK(worst_L <= 1e-11);
    CHECK(worst_w3 <= 1e-11);
    CHECK(worst_cos <= 1e-11);
    CHECK(worst_sine <= 1e-11);
    // ω seen from the body turns about the symmetry axis at Ω; the axis goes round L at |L|/I.
    const double body_rate = turned_body / t_end, axis_rate = turned_axis / t_end;
    INFO("body-frame rate " << body_rate << " vs Omega " << Omega << " (relative error "
                            << std::abs(body_rate / Omega - 1) << "); precession " << axis_rate << " vs |L|/I "
                            << L.norm() / p.I1 << " (" << std::abs(axis_rate / (L.norm() / p.I1) - 1) << ")");
    CHECK(std::abs(body_rate - Omega) <= 1e-8 * std::abs(Omega));
    CHECK(std::abs(axis_rate - L.norm() / p.I1) <= 1e-8 * L.norm() / p.I1);
    // The same precession rate in the seed's form, I3 w3 / (I cos θ): L cos θ = I3 w3.
    CHECK(std::abs(axis_rate - p.I3 * w3 / (p.I1 * cos_theta)) <= 1e-8 * std::abs(axis_rate));
}

TEST_CASE("5-17 rolling cone: rolls at constant phi' with T = 3 M h^2 phi'^2 (1 + 5 cos^2 alpha)/40",
          "[physics][bodies][cone][constraints]") {
    Cone::Params p;
    Cone::State x0 = Cone::default_state();
    const double t_end = 20;
    const auto r = eomgen::integrate_constrained<Cone>(p, 0.0, x0, grid(t_end, 200), tight());
    REQUIRE(r.run.samples.size() >= 200);
    const double phid0 = x0(3);
    double worst_T = 0, worst_rate = 0;
    for (const auto& s : r.run.samples) {
        const double phid = s.x(3);
        const double closed = 3 * p.M * p.h * p.h * phid * phid * (1 + 5 * std::pow(std::cos(p.alpha), 2)) / 40;
        const double T = Cone::kinetic_energy(s.t, s.x.head<3>(), s.x.tail<3>(), p);
        worst_T = std::max(worst_T, std::abs(T - closed) / closed);
        worst_rate = std::max(worst_rate, std::abs(phid - phid0) / phid0);
    }
    INFO("T vs closed form " << worst_T << ", phi' drift " << worst_rate << ", residuals "
                             << r.max_position_residual << " " << r.max_velocity_residual);
    CHECK(worst_T <= 1e-10);
    CHECK(worst_rate <= 1e-10);
    CHECK(r.max_velocity_residual <= 1e-10);
    // It went round: the line of contact turned by phi' t_end.
    CHECK(r.run.x(0) == Approx(phid0 * t_end).epsilon(1e-9));
}

TEST_CASE("a trajectory that settles at its coordinates' singular point stops with a message, not NaN",
          "[physics][errors]") {
    // The damped spherical pendulum comes to rest at theta = 0, where M = diag(m l², m l² sin²θ) is singular.
    Spherical::Params p;
    const Spherical::State x0 = Spherical::default_state();
    auto f = [&p](const double& t, const Spherical::State& x, Spherical::State& xdot) { Spherical::rhs(t, x, p, xdot); };
    eomgen::Dopri5Options<double> o;
    o.rtol = 1e-10;
    o.atol = 1e-12;
    o.max_steps = 1000000;
    try {
        const auto r = eomgen::integrate(f, 0.0, x0, 200.0, o);
        FAIL("reached t = " << r.t << " at theta = " << r.x(0));
    } catch (const eomgen::SimulationError& e) {
        const std::string what = e.what();
        INFO(what);
        CHECK(what.find("singular") != std::string::npos);
        CHECK(what.find("with state [") != std::string::npos);
        CHECK(e.t() > 1.0);
    }
}
