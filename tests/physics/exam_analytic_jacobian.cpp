/**
 * @file exam_analytic_jacobian.cpp  The generated analytic Jacobians ∂ẋ/∂x (state_jacobian()) and ∂ẋ/∂p
 * (parameter_jacobian()) of unconstrained models, against forward automatic differentiation through rhs
 * (linearization()) and against central differences of rhs in x and in p.
 */
#include "differences_support.hpp"

#include "eomgen/model_jacobian.hpp"
#include "eomgen/model_traits.hpp"
#include "eomgen/models/damped_pendulum.hpp"
#include "eomgen/models/driven_chain4.hpp"
#include "eomgen/models/heavy_symmetric_top.hpp"
#include "eomgen/models/pendulum_5_20.hpp"
#include "eomgen/models/pendulum_cartesian.hpp"
#include "eomgen/models/triangle_plate_5_15.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace {

using differences_support::parameter_differences;
using differences_support::state_differences;

/// At random states about the default one and random times: the analytic ∂ẋ/∂x equal to the automatic-
/// differentiation one to round-off and to central differences to their truncation error; likewise ∂ẋ/∂p against
/// linearization()'s B and central differences in p. model_jacobian picks the analytic one.
template <class M>
void check_analytic_jacobians(double spread) {
    static_assert(eomgen::has_analytic_jacobian<M>::value);
    const typename M::Params p{};
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> u(-spread, spread), time(0.0, 3.0);
    for (int trial = 0; trial < 8; ++trial) {
        typename M::State x = M::default_state();
        for (int i = 0; i < M::nx; ++i) x(i) += u(rng);
        const double t = time(rng);
        Eigen::Matrix<double, M::nx, M::nx> J, J_used, J_ad;
        Eigen::Matrix<double, M::nx, M::n_params> Jp, B;
        M::state_jacobian(t, x, p, J);
        M::parameter_jacobian(t, x, p, Jp);
        // linearization() differentiates rhs() forward in the states and parameters at once (one AD type a model:
        // eomgen::state_jacobian's states-only one would compile each model's rhs over AD a second time).
        M::linearization(t, x, p, J_ad, B);
        eomgen::model_jacobian<M>(t, x, p, J_used);
        const double scale = 1 + J_ad.cwiseAbs().maxCoeff(), scale_p = 1 + B.cwiseAbs().maxCoeff();
        INFO(M::name << " at t = " << t << ", x = " << x.transpose());
        CHECK((J - J_ad).cwiseAbs().maxCoeff() <= 1e-12 * scale);
        CHECK((J - state_differences<M>(t, x, p)).cwiseAbs().maxCoeff() <= 1e-6 * scale);
        CHECK((J_used - J).cwiseAbs().maxCoeff() == 0.0);
        CHECK((Jp - B).cwiseAbs().maxCoeff() <= 1e-12 * scale_p);
        CHECK((Jp - parameter_differences<M>(t, x, p)).cwiseAbs().maxCoeff() <= 1e-6 * scale_p);
    }
}

}  // namespace

TEST_CASE("analytic jacobian: state and parameter Jacobians of unconstrained models against AD and differences",
          "[physics][jacobian]") {
    check_analytic_jacobians<eomgen::models::pendulum_5_20::Model<double>>(0.5);
    check_analytic_jacobians<eomgen::models::heavy_symmetric_top::Model<double>>(0.3);
    check_analytic_jacobians<eomgen::models::damped_pendulum::Model<double>>(0.5);
    check_analytic_jacobians<eomgen::models::triangle_plate_5_15::Model<double>>(0.3);
    // Rheonomic (driven pivot), dissipative (joint damping), a time-dependent applied torque, four coordinates.
    check_analytic_jacobians<eomgen::models::driven_chain4::Model<double>>(0.4);
}

TEST_CASE("analytic jacobian: constrained models have none and keep forward differentiation",
          "[physics][jacobian]") {
    STATIC_REQUIRE_FALSE(eomgen::has_analytic_jacobian<eomgen::models::pendulum_cartesian::Model<double>>::value);
}

TEST_CASE("analytic jacobian: a singular mass matrix throws as rhs does, never a NaN", "[physics][jacobian]") {
    using M = eomgen::models::heavy_symmetric_top::Model<double>;
    M::State x = M::default_state();
    x(1) = 0.0;  // theta = 0: the Euler angles are singular, det M = 0
    Eigen::Matrix<double, M::nx, M::nx> J;
    Eigen::Matrix<double, M::nx, M::n_params> Jp;
    M::State xdot;
    CHECK_THROWS_AS(M::rhs(0.0, x, M::Params{}, xdot), eomgen::SingularMassMatrix);
    CHECK_THROWS_AS(M::state_jacobian(0.0, x, M::Params{}, J), eomgen::SingularMassMatrix);
    CHECK_THROWS_AS(M::parameter_jacobian(0.0, x, M::Params{}, Jp), eomgen::SingularMassMatrix);
}
