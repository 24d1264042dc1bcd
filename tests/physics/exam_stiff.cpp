/** @file exam_stiff.cpp  The stiff example under radau5 against a tight dopri5; the models' exact Jacobians. */
#include "../approx.hpp"
#include "differences_support.hpp"

#include "eomgen/constraints.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/model_jacobian.hpp"
#include "eomgen/models/pendulum_5_20.hpp"
#include "eomgen/models/pendulum_cartesian.hpp"
#include "eomgen/models/stiff_spring_pendulum.hpp"
#include "eomgen/radau5.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace {

/// model_jacobian at random states near the default one: equal to linearization()'s A to round-off and to
/// central differences to their truncation error.
template <class M>
void check_jacobian(const typename M::Params& p, double spread, bool project) {
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> u(-spread, spread);
    for (int trial = 0; trial < 5; ++trial) {
        typename M::State x = M::default_state();
        for (int i = 0; i < M::nx; ++i) x(i) += u(rng);
        if constexpr (eomgen::is_constrained<M>::value)
            if (project) eomgen::project_onto_constraints<M>(0.0, x, p);
        Eigen::Matrix<double, M::nx, M::nx> J, A;
        Eigen::Matrix<double, M::nx, M::n_params> B;
        eomgen::model_jacobian<M>(0.3, x, p, J);
        M::linearization(0.3, x, p, A, B);
        const double scale = 1 + J.cwiseAbs().maxCoeff();
        INFO(M::name << " at x = " << x.transpose());
        CHECK((J - A).cwiseAbs().maxCoeff() <= 1e-13 * scale);
        CHECK((J - differences_support::state_differences<M>(0.3, x, p)).cwiseAbs().maxCoeff() <= 1e-6 * scale);
    }
}

}  // namespace

TEST_CASE("stiff: the exact Jacobian of three generated models, one constrained, against finite differences",
          "[physics][stiff][jacobian]") {
    check_jacobian<eomgen::models::stiff_spring_pendulum::Model<double>>({}, 0.1, false);
    check_jacobian<eomgen::models::pendulum_5_20::Model<double>>({}, 0.5, false);
    check_jacobian<eomgen::models::pendulum_cartesian::Model<double>>({}, 0.2, true);
}

TEST_CASE("stiff: the spring pendulum by radau5 matches a tight dopri5 at the end, in far fewer right-hand sides",
          "[physics][stiff]") {
    using M = eomgen::models::stiff_spring_pendulum::Model<double>;
    using State = M::State;
    const M::Params p{};
    const State x0 = M::default_state();
    const auto f = [&p](const double& t, const State& x, State& xdot) { M::rhs(t, x, p, xdot); };
    const auto jac = [&p](const double& t, const State& x, Eigen::Matrix<double, M::nx, M::nx>& J) {
        eomgen::model_jacobian<M>(t, x, p, J);
    };
    eomgen::Dopri5Options<double> tight;
    tight.rtol = 1e-12;
    tight.atol = 1e-14;
    tight.max_steps = 1000000;
    const auto ref = eomgen::integrate(f, 0.0, x0, 10.0, tight);
    for (const double rtol : {1e-6, 1e-8}) {
        eomgen::Radau5Options<double> o;
        o.rtol = rtol;
        o.atol = rtol * 1e-2;
        const auto r = eomgen::integrate_radau5(f, jac, 0.0, x0, 10.0, o);
        eomgen::Dopri5Options<double> od;
        od.rtol = rtol;
        od.atol = rtol * 1e-2;
        od.max_steps = 1000000;
        const auto d = eomgen::integrate(f, 0.0, x0, 10.0, od);
        const double err = (r.x - ref.x).cwiseAbs().maxCoeff(), err_d = (d.x - ref.x).cwiseAbs().maxCoeff();
        INFO("rtol " << rtol << ": radau5 error " << err << " in " << r.rhs_evaluations << " rhs, "
                     << r.jacobian_evaluations << " Jacobians; dopri5 error " << err_d << " in " << d.rhs_evaluations
                     << " rhs");
        CHECK(err < 10 * rtol);
        CHECK(err < 100 * err_d + 10 * rtol);  // as accurate as dopri5 at the same tolerance, give or take
        CHECK(d.rhs_evaluations > 20 * (r.rhs_evaluations + M::nx * r.jacobian_evaluations));
    }
}
