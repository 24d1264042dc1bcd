/** @file check_tree_rhs.cpp  A header whose rhs() is the O(n) recursion of a tree of point masses (the 14-link
 * chain, codegen/tree_emitter.hpp) against the same header's dense M and f, in double and long double; its
 * Jacobians (forward differentiation through that rhs) against central differences of it; and its failures. */
#include "../approx.hpp"

#include "eomgen/models/pendulum_14.hpp"

#include <Eigen/LU>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace {

using eomgen::test::AllClose;

template <class Scalar>
using Chain = eomgen::models::pendulum_14::Model<Scalar>;

/// A state with angles in (−1.5, 1.5) and rates in (−2, 2), and parameters in (0.5, 1.5).
template <class Scalar>
void random_state(std::mt19937& rng, typename Chain<Scalar>::State& x, typename Chain<Scalar>::Params& p) {
    std::uniform_real_distribution<double> angle(-1.5, 1.5), rate(-2, 2), value(0.5, 1.5);
    for (int i = 0; i < Chain<Scalar>::nq; ++i) x(i) = Scalar(angle(rng));
    for (int i = 0; i < Chain<Scalar>::nq; ++i) x(Chain<Scalar>::nq + i) = Scalar(rate(rng));
    for (const char* name : Chain<Scalar>::param_names) REQUIRE(Chain<Scalar>::set_param(p, name, Scalar(value(rng))));
}

template <class Scalar>
void check_against_dense(double tolerance) {
    using M = Chain<Scalar>;
    std::mt19937 rng(14);
    for (int trial = 0; trial < 50; ++trial) {
        typename M::State x, xdot;
        typename M::Params p;
        random_state<Scalar>(rng, x, p);
        M::rhs(Scalar(0), x, p, xdot);
        typename M::MassMatrix mass;
        typename M::Config f;
        M::dynamics(Scalar(0), x.template head<M::nq>().eval(), x.template tail<M::nq>().eval(), p, mass, f);
        const typename M::Config lu = mass.partialPivLu().solve(f);
        const double scale = double(lu.cwiseAbs().maxCoeff());
        REQUIRE_THAT(Eigen::MatrixXd(xdot.template tail<M::nq>().template cast<double>()),
                     AllClose(Eigen::MatrixXd(lu.template cast<double>()), tolerance, tolerance * scale));
        REQUIRE(xdot.template head<M::nq>() == x.template tail<M::nq>());
    }
}

}  // namespace

TEST_CASE("tree rhs: the 14-link chain's recursion equals its dense M^-1 f, in double and long double", "[generated]") {
    STATIC_REQUIRE(Chain<double>::tree_components == 2);
    check_against_dense<double>(1e-12);
    check_against_dense<long double>(1e-15);
}

TEST_CASE("tree rhs: state_jacobian() and parameter_jacobian() through the recursion equal central differences of rhs",
          "[generated]") {
    // The tree's Jacobians are forward differentiation through its O(n) recursion (codegen/jacobian_emitter.hpp):
    // checked against central differences of the same rhs in x and in p, which share no code with the AD.
    using M = Chain<double>;
    std::mt19937 rng(3);
    for (int trial = 0; trial < 5; ++trial) {
        M::State x;
        M::Params p;
        random_state<double>(rng, x, p);
        M::StateJacobian J;
        M::ParameterJacobian Jp;
        M::state_jacobian(0.0, x, p, J);
        M::parameter_jacobian(0.0, x, p, Jp);
        M::StateJacobian J_fd;
        M::ParameterJacobian Jp_fd;
        for (int k = 0; k < M::nx; ++k) {
            const double h = 1e-6 * std::max(1.0, std::abs(x(k)));
            M::State up = x, down = x, f_up, f_down;
            up(k) += h;
            down(k) -= h;
            M::rhs(0.0, up, p, f_up);
            M::rhs(0.0, down, p, f_down);
            J_fd.col(k) = (f_up - f_down) / (2 * h);
        }
        const auto values = M::param_values(p);
        for (int j = 0; j < M::n_params; ++j) {
            const double h = 1e-6 * std::max(1.0, std::abs(values[std::size_t(j)]));
            M::Params up = p, down = p;
            REQUIRE(M::set_param(up, M::param_names[std::size_t(j)], values[std::size_t(j)] + h));
            REQUIRE(M::set_param(down, M::param_names[std::size_t(j)], values[std::size_t(j)] - h));
            M::State f_up, f_down;
            M::rhs(0.0, x, up, f_up);
            M::rhs(0.0, x, down, f_down);
            Jp_fd.col(j) = (f_up - f_down) / (2 * h);
        }
        REQUIRE_THAT(Eigen::MatrixXd(J), AllClose(Eigen::MatrixXd(J_fd), 1e-5, 1e-6 * J_fd.cwiseAbs().maxCoeff()));
        REQUIRE_THAT(Eigen::MatrixXd(Jp), AllClose(Eigen::MatrixXd(Jp_fd), 1e-5, 1e-6 * Jp_fd.cwiseAbs().maxCoeff()));
        // And linearization(), the same differentiation seeded with x and p together.
        M::StateJacobian A;
        M::ParameterJacobian B;
        M::linearization(0.0, x, p, A, B);
        REQUIRE_THAT(Eigen::MatrixXd(A), AllClose(Eigen::MatrixXd(J), 1e-13, 1e-13 * J.cwiseAbs().maxCoeff()));
        REQUIRE_THAT(Eigen::MatrixXd(B), AllClose(Eigen::MatrixXd(Jp), 1e-13, 1e-13 * Jp.cwiseAbs().maxCoeff()));
    }
}

TEST_CASE("tree rhs: a massless last bob is a singular M, a NaN in the state is reported", "[generated]") {
    using M = Chain<double>;
    M::State x = M::default_state(), xdot;
    M::Params p;
    p.m14 = 0;
    CHECK_THROWS_AS(M::rhs(0.0, x, p, xdot), eomgen::SingularMassMatrix);
    p = M::Params();
    x(3) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(M::rhs(0.0, x, p, xdot), eomgen::NonFiniteState);
}
