/**
 * @file exam_constrained_sticking.cpp  Sticking on a constraint manifold: a driven pendulum with dry friction at its
 * pivot, written in Cartesian coordinates on a rod (friction_pendulum_cartesian.toml, its friction's switching
 * surface x y' − y x' = 0), against the same pendulum in its angle (friction_pendulum.toml, unconstrained, whose
 * sticking integrate_sliding follows). Two derivations that share nothing but the physics: the Cartesian one slides
 * with Filippov's combination of two constrained fields (integrate_constrained), and its sensitivities with the
 * sliding variational equations of the constrained solve.
 */
#include "eomgen/constraints.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/models/friction_pendulum.hpp"
#include "eomgen/models/friction_pendulum_cartesian.hpp"
#include "eomgen/sensitivities.hpp"
#include "eomgen/simulation_options.hpp"
#include "eomgen/sliding.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace {

using Angle = eomgen::models::friction_pendulum::Model<double>;
using Cartesian = eomgen::models::friction_pendulum_cartesian::Model<double>;

constexpr double kTEnd = 8.0;

eomgen::Dop853Options<double> tight() {
    eomgen::Dop853Options<double> o;
    o.rtol = 1e-12;
    o.atol = 1e-14;
    o.max_steps = 2000000;
    return o;
}

/// The bob's start at angle theta0, at rest, in each model.
Angle::State angle_start(double theta0) { return Angle::State(theta0, 0.0); }

Cartesian::State cartesian_start(double theta0, double l) {
    Cartesian::State x;
    x << l * std::sin(theta0), -l * std::cos(theta0), 0.0, 0.0;
    return x;
}

/// Where sliding began and ended: ("slides" or "leaves to s > 0" …, t), the switching surface's name dropped.
template <class State>
std::vector<std::pair<std::string, double>> sliding_events(const std::vector<eomgen::EventHit<State>>& hits) {
    std::vector<std::pair<std::string, double>> out;
    for (const auto& e : hits) out.emplace_back(e.name.substr(e.name.find(": ") + 2), e.t);
    return out;
}

}  // namespace

TEST_CASE("a constrained model follows its motion's sticking as the same motion in its angle does", "[sticking]") {
    const Angle::Params pa;
    const Cartesian::Params pc;
    const double l = pc.l;
    std::vector<double> times;
    for (int k = 0; k <= 160; ++k) times.push_back(kTEnd * k / 160);

    auto fa = [&pa](const double& t, const Angle::State& x, Angle::State& xd) { Angle::rhs(t, x, pa, xd); };
    const auto angle = eomgen::integrate_sliding<eomgen::Dop853>(
        fa, 0.0, angle_start(0.2), kTEnd, tight(), eomgen::sim::switch_events<Angle>(eomgen::sim::Options{}, pa),
        times);
    const auto cartesian = eomgen::integrate_constrained<Cartesian, eomgen::Dop853>(
        pc, 0.0, cartesian_start(0.2, l), times, tight(), false,
        eomgen::sim::switch_events<Cartesian>(eomgen::sim::Options{}, pc));
    REQUIRE(angle.t == Approx(kTEnd));
    REQUIRE(cartesian.run.t == Approx(kTEnd));

    // The same stick-slip: each sliding interval begins and ends at the same times (located by each run's events).
    const auto ea = sliding_events(angle.events), ec = sliding_events(cartesian.run.events);
    INFO("angle model's events: " << ea.size() << ", Cartesian model's: " << ec.size());
    REQUIRE(ea.size() == ec.size());
    int stuck = 0;
    for (std::size_t k = 0; k < ea.size(); ++k) {
        INFO(ea[k].first << " at t = " << ea[k].second << " against " << ec[k].first << " at t = " << ec[k].second);
        CHECK(ea[k].first == ec[k].first);
        CHECK(std::abs(ea[k].second - ec[k].second) < 1e-8);
        stuck += ea[k].first == "slides" ? 1 : 0;
    }
    CHECK(stuck >= 2);  // held, let go and held again by the pivot's friction

    // θ = atan2(x, −y) and θ̇ = (x ẏ − y ẋ)/l² at every sample, through every sticking and slip.
    REQUIRE(angle.samples.size() == cartesian.run.samples.size());
    double worst = 0, worst_rate = 0;
    for (std::size_t k = 0; k < angle.samples.size(); ++k) {
        const Angle::State& a = angle.samples[k].x;
        const Cartesian::State& c = cartesian.run.samples[k].x;
        REQUIRE(cartesian.run.samples[k].t == Approx(angle.samples[k].t));
        worst = std::max(worst, std::abs(std::atan2(c(0), -c(1)) - a(0)));
        worst_rate = std::max(worst_rate, std::abs((c(0) * c(3) - c(1) * c(2)) / (l * l) - a(1)));
    }
    INFO("largest difference of theta " << worst << " rad, of theta_dot " << worst_rate << " rad/s");
    CHECK(worst < 1e-8);
    CHECK(worst_rate < 1e-7);
    // The rod held to round-off by the projection after each sample, sliding included.
    CHECK(cartesian.max_position_residual < 1e-9);
}

TEST_CASE("the sensitivities of a constrained motion that sticks agree with those of its angle", "[sticking]") {
    const Angle::Params pa;
    const Cartesian::Params pc;
    const double l = pc.l;
    const std::vector<std::string> names = {"m", "l", "g", "tau_f", "A", "Omega"};
    std::vector<eomgen::SensitivityColumn> ca, cc;
    for (const std::string& n : names) {
        ca.push_back(eomgen::parameter_column(Angle::param_names, n));
        cc.push_back(eomgen::parameter_column(Cartesian::param_names, n));
    }
    const double t_end = 6.0;
    const auto a = eomgen::integrate_sensitivities<Angle, eomgen::Dop853>(pa, 0.0, angle_start(0.2), t_end, ca, tight());
    const auto c = eomgen::integrate_sensitivities<Cartesian, eomgen::Dop853>(pc, 0.0, cartesian_start(0.2, l), t_end,
                                                                            cc, tight());
    REQUIRE(c.t == Approx(t_end));
    int slides = 0;
    for (const auto& s : c.switches) slides += s.first.find(": slides") != std::string::npos ? 1 : 0;
    CHECK(slides >= 2);

    // θ = atan2(x, −y): δθ = (x δy − y δx)/l²; θ̇ = (x ẏ − y ẋ)/l², differentiated likewise (l's column adds
    // −2 θ̇ δl/l).
    const double x = c.x(0), y = c.x(1), xd = c.x(2), yd = c.x(3);
    const double rate = (x * yd - y * xd) / (l * l);
    for (std::size_t k = 0; k < names.size(); ++k) {
        const Eigen::VectorXd s = c.S.col(Eigen::Index(k));
        const double dl = names[k] == "l" ? 1.0 : 0.0;
        const double dtheta = (x * s(1) - y * s(0)) / (l * l);
        const double drate = (s(0) * yd + x * s(3) - s(1) * xd - y * s(2)) / (l * l) - 2 * rate * dl / l;
        const double scale = std::max({std::abs(a.S(0, Eigen::Index(k))), std::abs(a.S(1, Eigen::Index(k))), 1e-3});
        const double off = std::max(std::abs(dtheta - a.S(0, Eigen::Index(k))), std::abs(drate - a.S(1, Eigen::Index(k))));
        INFO("d/d" << names[k] << ": theta " << dtheta << " against " << a.S(0, Eigen::Index(k)) << ", theta_dot "
                   << drate << " against " << a.S(1, Eigen::Index(k)) << ": relative difference " << off / scale);
        CHECK(off / scale < 1e-7);
        // S stays on the rod's tangent: x δx + y δy = l δl.
        CHECK(std::abs(x * s(0) + y * s(1) - l * dl) < 1e-8);
    }
}
