/** @file check_mass_solve.cpp  The generated headers' unrolled L D L^T (solve_for_accelerations) against the
 * runtime's loop and Eigen's LU at random states, on models whose M has zeros and on dense ones. */
#include "../approx.hpp"

#include "eomgen/models/door.hpp"
#include "eomgen/models/heavy_symmetric_top.hpp"
#include "eomgen/models/pendulum_5_20.hpp"
#include "eomgen/models/torque_free_top.hpp"
#include "eomgen/models/triangle_plate_5_15.hpp"

#include <Eigen/LU>
#include <catch2/catch.hpp>

#include <limits>
#include <random>

namespace {

using eomgen::test::AllClose;

/// At 50 random states (coordinates in (0.2, 1.4), away from the tops' sin θ = 0, rates in (−2, 2)): the unrolled
/// solve equals the runtime's solve_mass_matrix and Eigen's partial-pivoting LU of the same M and f.
template <class Model>
void check_model() {
    std::mt19937 rng(7u + Model::nq);
    std::uniform_real_distribution<double> angle(0.2, 1.4), rate(-2.0, 2.0);
    const typename Model::Params p;
    for (int trial = 0; trial < 50; ++trial) {
        typename Model::State x;
        for (int i = 0; i < Model::nq; ++i) x(i) = angle(rng);
        for (int i = 0; i < Model::nq; ++i) x(Model::nq + i) = rate(rng);
        typename Model::MassMatrix M;
        typename Model::Config f, unrolled, loop;
        Model::dynamics(0.0, x.template head<Model::nq>().eval(), x.template tail<Model::nq>().eval(), p, M, f);
        Model::solve_for_accelerations(0.0, x, M, f, unrolled);
        eomgen::solve_mass_matrix(M, f, loop, 0.0, x);
        const typename Model::Config lu = M.partialPivLu().solve(f);
        const double scale = lu.cwiseAbs().maxCoeff();
        REQUIRE_THAT(Eigen::MatrixXd(unrolled), AllClose(loop, 1e-13, 1e-13 * scale));
        REQUIRE_THAT(Eigen::MatrixXd(unrolled), AllClose(lu, 1e-10, 1e-10 * scale));
        typename Model::State xdot;
        Model::rhs(0.0, x, p, xdot);
        REQUIRE(xdot.template tail<Model::nq>() == unrolled);
    }
}

}  // namespace

TEST_CASE("unrolled L D L^T equals the runtime's solve and LU: M with zeros (tops, plate)", "[generated]") {
    check_model<eomgen::models::torque_free_top::Model<double>>();
    check_model<eomgen::models::heavy_symmetric_top::Model<double>>();
    check_model<eomgen::models::triangle_plate_5_15::Model<double>>();
}

TEST_CASE("unrolled L D L^T equals the runtime's solve and LU: dense M (pendulum 5-20, door)", "[generated]") {
    check_model<eomgen::models::pendulum_5_20::Model<double>>();
    check_model<eomgen::models::door::Model<double>>();
}

TEST_CASE("unrolled L D L^T: a non-finite state throws NonFiniteState, a singular M SingularMassMatrix", "[generated]") {
    using P = eomgen::models::pendulum_5_20::Model<double>;
    P::State x = P::default_state(), xdot;
    x(0) = std::numeric_limits<double>::quiet_NaN();  // NaN in M and f
    CHECK_THROWS_AS(P::rhs(0.0, x, P::Params{}, xdot), eomgen::NonFiniteState);
    x = P::default_state();
    x(3) = std::numeric_limits<double>::infinity();  // M finite, f not: the result's finite check
    CHECK_THROWS_AS(P::rhs(0.0, x, P::Params{}, xdot), eomgen::NonFiniteState);
    using T = eomgen::models::torque_free_top::Model<double>;
    T::State y = T::default_state(), ydot;
    y(1) = 0;  // theta = 0: the Euler angles' singular point, det M = 0
    CHECK_THROWS_AS(T::rhs(0.0, y, T::Params{}, ydot), eomgen::SingularMassMatrix);
}
