/** @file check_symplectic.cpp  Midpoint variational integrator: bounded energy, order 2, reversibility. */
#include "../approx.hpp"
#include "test_models.hpp"

#include "eomgen/integrate.hpp"
#include "eomgen/symplectic.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using eomgen::test::AllClose;
using eomgen::test::DoublePendulum;
using eomgen::test::VariableMass;

/// Max |E − E0| over the first and the last 10% of n steps of size h, and Newton iterations per step.
template <class Model>
std::tuple<double, double, double> energy_error_head_tail(const typename Model::Config& q0,
                                                          const typename Model::Config& qd0, double h,
                                                          std::size_t n) {
    eomgen::VariationalIntegrator<Model> vi({}, h);
    vi.set_state(0.0, q0, qd0);
    const double e0 = vi.energy();
    double head = 0, tail = 0;
    for (std::size_t k = 1; k <= n; ++k) {
        vi.step();
        if (k <= n / 10) head = std::max(head, std::abs(vi.energy() - e0));
        if (k > n - n / 10) tail = std::max(tail, std::abs(vi.energy() - e0));
    }
    return {head, tail, double(vi.newton_iterations()) / double(n)};
}

/// A reference solution of the model's own equations of motion M q̈ = f by DOPRI5 at tight tolerance.
template <class Model>
typename Model::State reference(const typename Model::State& x0, double t_end) {
    eomgen::Dopri5Options<double> opts;
    opts.rtol = 1e-13;
    opts.atol = 1e-15;
    const typename Model::Params params{};
    const auto f = [&](const double& t, const typename Model::State& x, typename Model::State& xdot) {
        Model::rhs(t, x, params, xdot);
    };
    return eomgen::integrate(f, 0.0, x0, t_end, opts).x;
}

}  // namespace

TEST_CASE("test models: hand-written momenta and dL/dq match finite differences of L",
          "[runtime][symplectic]") {
    // Cross-check the hand differentiation the other tests rely on.
    using M1 = VariableMass<double>;
    using M2 = DoublePendulum<double>;
    const double d = 1e-6;
    {
        const M1::Config q(0.7), qd(-1.3);
        M1::Config p, g;
        M1::momenta(0, q, qd, {}, p);
        M1::lagrangian_gradient(0, q, qd, {}, g);
        const double dp =
            (M1::lagrangian(0, q, qd + M1::Config(d), {}) - M1::lagrangian(0, q, qd - M1::Config(d), {})) /
            (2 * d);
        const double dg =
            (M1::lagrangian(0, q + M1::Config(d), qd, {}) - M1::lagrangian(0, q - M1::Config(d), qd, {})) /
            (2 * d);
        CHECK(p(0) == Approx(dp).epsilon(1e-8));
        CHECK(g(0) == Approx(dg).epsilon(1e-8));
    }
    const M2::Config q(0.4, -1.1), qd(0.8, 1.9);
    M2::Config p, g;
    M2::momenta(0, q, qd, {}, p);
    M2::lagrangian_gradient(0, q, qd, {}, g);
    for (int i = 0; i < 2; ++i) {
        const M2::Config e = M2::Config::Unit(i) * d;
        CHECK(p(i) == Approx((M2::lagrangian(0, q, qd + e, {}) - M2::lagrangian(0, q, qd - e, {})) / (2 * d))
                          .epsilon(1e-8));
        CHECK(g(i) == Approx((M2::lagrangian(0, q + e, qd, {}) - M2::lagrangian(0, q - e, qd, {})) / (2 * d))
                          .epsilon(1e-8));
    }
}

TEST_CASE("variational integrator: energy error bounded, no secular growth over 1e5 steps",
          "[runtime][symplectic]") {
    using Model = VariableMass<double>;
    const Model::Config q0(1.2), qd0(0.3);
    const double h = 0.05;
    const std::size_t n = 100000;
    const auto [head, tail, iterations] = energy_error_head_tail<Model>(q0, qd0, h, n);
    INFO("variational, h = " << h << ", " << n << " steps: max |dE| first 10% " << head << ", last 10% "
                             << tail << ", " << iterations << " Newton iterations per step");
    CHECK(tail < 1.5 * head);
    CHECK(tail < 1e-2 * h * h * 100);  // O(h²) with a modest constant

    // The same measure catches drift: RK4 on the same equations, same h, loses energy steadily.
    const Model::Params params{};
    const auto f = [&](const double& t, const Model::State& x, Model::State& xdot) {
        Model::rhs(t, x, params, xdot);
    };
    const Model::State x0 = Model::state(q0, qd0);
    const double e0 = Model::energy(0, q0, qd0, params);
    double rk_head = 0, rk_tail = 0;
    std::size_t k = 0;
    eomgen::integrate_rk4(f, 0.0, x0, h * n, h, {}, {}, [&](const double&, const Model::State& x) {
        const double de = std::abs(Model::energy(0, x.head<1>(), x.tail<1>(), params) - e0);
        if (k <= n / 10) rk_head = std::max(rk_head, de);
        if (k > n - n / 10) rk_tail = std::max(rk_tail, de);
        ++k;
    });
    INFO("RK4 same h: first 10% " << rk_head << ", last 10% " << rk_tail);
    CHECK(rk_tail > 5 * rk_head);
}

TEST_CASE("variational integrator converges with order 2 to the DOPRI5 solution", "[runtime][symplectic]") {
    using Model = VariableMass<double>;
    const Model::Config q0(1.2), qd0(0.3);
    const Model::State x0 = Model::state(q0, qd0);
    const double t_end = 5.0;
    const Model::State ref = reference<Model>(x0, t_end);
    double errors[3];
    const double hs[3] = {0.1, 0.05, 0.025};
    for (int i = 0; i < 3; ++i) {
        eomgen::VariationalIntegrator<Model> vi({}, hs[i]);
        vi.set_state(0.0, q0, qd0);
        vi.step(std::size_t(std::lround(t_end / hs[i])));
        CHECK(vi.t() == Approx(t_end).epsilon(1e-15));
        const Model::State x = Model::state(vi.q(), vi.velocity());
        errors[i] = (x - ref).lpNorm<Eigen::Infinity>();
    }
    const double o1 = std::log2(errors[0] / errors[1]), o2 = std::log2(errors[1] / errors[2]);
    INFO("errors " << errors[0] << " " << errors[1] << " " << errors[2] << ", orders " << o1 << " " << o2);
    CHECK(o1 == Approx(2.0).margin(0.1));
    CHECK(o2 == Approx(2.0).margin(0.1));
}

TEST_CASE("variational integrator is time-reversible: stepping back with -h returns to the start",
          "[runtime][symplectic]") {
    using Model = VariableMass<double>;
    const Model::Config q0(1.2), qd0(0.3);
    const double h = 0.05;
    eomgen::VariationalIntegrator<Model> fwd({}, h);
    fwd.set_state(0.0, q0, qd0);
    fwd.step(2000);
    eomgen::VariationalIntegrator<Model> back({}, -h);
    back.set_phase_state(fwd.t(), fwd.q(), fwd.p());
    back.step(2000);
    Model::Config p0;
    Model::momenta(0, q0, qd0, {}, p0);
    INFO("after 2000 steps there and back: dq = " << (back.q() - q0)(0) << ", dp = " << (back.p() - p0)(0));
    CHECK(std::abs(back.t()) < 1e-12);
    REQUIRE_THAT(Eigen::MatrixXd(back.q()), AllClose(q0, 0, 1e-11));
    REQUIRE_THAT(Eigen::MatrixXd(back.p()), AllClose(p0, 0, 1e-11));
    // One step there and back agrees to rounding.
    Model::Config q1, p1, q2, p2;
    eomgen::variational_midpoint_step<Model>(0.0, q0, p0, h, {}, {}, q1, p1);
    eomgen::variational_midpoint_step<Model>(h, q1, p1, -h, {}, {}, q2, p2);
    REQUIRE_THAT(Eigen::MatrixXd(q2), AllClose(q0, 1e-14, 1e-15));
    REQUIRE_THAT(Eigen::MatrixXd(p2), AllClose(p0, 1e-14, 1e-15));
}

TEST_CASE("double pendulum (2 DOF, fixed and dynamic size): order 2 and bounded energy",
          "[runtime][symplectic]") {
    using Model = DoublePendulum<double>;
    using ModelDyn = DoublePendulum<double, Eigen::Dynamic>;
    const Model::Config q0(0.5, -0.3), qd0(0.0, 0.4);
    const Model::State x0 = Model::state(q0, qd0);
    const double t_end = 2.0;
    const Model::State ref = reference<Model>(x0, t_end);
    double errors[2];
    const double hs[2] = {0.02, 0.01};
    for (int i = 0; i < 2; ++i) {
        eomgen::VariationalIntegrator<Model> vi({}, hs[i]);
        vi.set_state(0.0, q0, qd0);
        vi.step(std::size_t(std::lround(t_end / hs[i])));
        const Model::State x = Model::state(vi.q(), vi.velocity());
        errors[i] = (x - ref).lpNorm<Eigen::Infinity>();

        eomgen::VariationalIntegrator<ModelDyn> vd({}, hs[i]);
        vd.set_state(0.0, Eigen::VectorXd(q0), Eigen::VectorXd(qd0));
        vd.step(std::size_t(std::lround(t_end / hs[i])));
        REQUIRE_THAT(Eigen::MatrixXd(vd.q()), AllClose(vi.q(), 1e-12, 1e-13));
    }
    const double order = std::log2(errors[0] / errors[1]);
    INFO("errors " << errors[0] << " " << errors[1] << ", order " << order);
    CHECK(order == Approx(2.0).margin(0.15));

    const auto [head, tail, iterations] = energy_error_head_tail<Model>(q0, qd0, 0.01, 20000);
    INFO("double pendulum, h = 0.01, 2e4 steps: max |dE| first 10% "
         << head << ", last 10% " << tail << ", " << iterations << " Newton iterations per step");
    CHECK(tail < 2 * head);
}

TEST_CASE("variational integrator in long double, Newton failure is a SimulationError",
          "[runtime][symplectic][long double]") {
    using Model = VariableMass<long double>;
    const Model::Config q0(1.2L), qd0(0.3L);
    eomgen::VariationalIntegrator<Model> fwd({}, 0.05L);
    fwd.set_state(0.0L, q0, qd0);
    const long double e0 = fwd.energy();
    fwd.step(200);
    CHECK(std::abs(double(fwd.energy() - e0)) < 1e-3);
    eomgen::VariationalIntegrator<Model> back({}, -0.05L);
    back.set_phase_state(fwd.t(), fwd.q(), fwd.p());
    back.step(200);
    INFO("long double there and back: dq = " << double((back.q() - q0)(0)));
    CHECK(std::abs(double((back.q() - q0)(0))) < 1e-15);

    eomgen::VariationalOptions<double> strict;
    strict.tolerance = 0;
    strict.max_iterations = 1;
    eomgen::VariationalIntegrator<VariableMass<double>> vi({}, 0.3, strict);
    vi.set_state(0.0, VariableMass<double>::Config(1.0), VariableMass<double>::Config(1.0));
    CHECK_THROWS_AS(vi.step(), eomgen::SimulationError);
}
