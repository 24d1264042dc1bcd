/** @file exam_linear_solve.cpp  eomgen::solve_mass_matrix (LDL^T, pivots tested, finite check on the result only)
 * against Eigen's LLT, and its failures: which error for which broken input. */
#include "../approx.hpp"

#include "eomgen/analytic_jacobian.hpp"
#include "eomgen/linear_solve.hpp"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace {

using eomgen::test::AllClose;

/// A random symmetric positive definite matrix with condition number about `cond` (Q diag Qᵀ, Q orthogonal).
template <int N>
Eigen::Matrix<double, N, N> random_spd(int n, double cond, std::mt19937& rng) {
    std::normal_distribution<double> normal;
    Eigen::MatrixXd A(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) A(i, j) = normal(rng);
    const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(A).householderQ();
    Eigen::VectorXd lambda(n);
    for (int i = 0; i < n; ++i) lambda(i) = std::pow(cond, -double(i) / std::max(1, n - 1));
    return Q * lambda.asDiagonal() * Q.transpose();
}

template <int N>
void check_against_llt(int n) {
    std::mt19937 rng(20261124u + unsigned(n));
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 20; ++trial) {
        const Eigen::Matrix<double, N, N> M = random_spd<N>(n, 1e6, rng);
        Eigen::Matrix<double, N, 1> f(n), qdd(n);
        for (int i = 0; i < n; ++i) f(i) = normal(rng);
        eomgen::solve_mass_matrix(M, f, qdd, 0.0, f);
        // The reference in dynamic sizes: Eigen's LLT compiled once, not once for each N.
        const Eigen::VectorXd expected = Eigen::LLT<Eigen::MatrixXd>(M).solve(Eigen::VectorXd(f));
        // cond 1e6: both solves carry errors of about cond·eps relative to |q̈|.
        REQUIRE_THAT(Eigen::MatrixXd(qdd), AllClose(expected, 1e-8, 1e-8 * expected.cwiseAbs().maxCoeff()));
        REQUIRE((M * qdd - f).cwiseAbs().maxCoeff() <= 1e-10 * (M.cwiseAbs().maxCoeff() * qdd.cwiseAbs().maxCoeff() + 1));
    }
}

}  // namespace

TEST_CASE("solve_mass_matrix: L D L^T equals Eigen's LLT on random SPD matrices, fixed and dynamic sizes", "[runtime]") {
    check_against_llt<1>(1);
    check_against_llt<2>(2);
    check_against_llt<3>(3);
    check_against_llt<7>(7);
    check_against_llt<13>(13);
    check_against_llt<30>(30);
    for (int n : {1, 2, 5, 16}) check_against_llt<Eigen::Dynamic>(n);
}

TEST_CASE("solve_mass_matrix: a singular or indefinite M throws SingularMassMatrix, never NaN", "[runtime][errors]") {
    Eigen::Matrix3d M;
    M << 1, 2, 3, 2, 4, 6, 3, 6, 10;  // rank 2: the second pivot is 0
    const Eigen::Vector3d f(1, 2, 3);
    Eigen::Vector3d qdd;
    CHECK_THROWS_AS(eomgen::solve_mass_matrix(M, f, qdd, 0.5, f), eomgen::SingularMassMatrix);
    M << 1, 0, 0, 0, -1, 0, 0, 0, 1;  // indefinite
    CHECK_THROWS_AS(eomgen::solve_mass_matrix(M, f, qdd, 0.5, f), eomgen::SingularMassMatrix);
    M << 1, 0, 0, 0, 1e-17, 0, 0, 0, 1;  // singular to working precision: pivot ratio below n eps
    CHECK_THROWS_AS(eomgen::solve_mass_matrix(M, f, qdd, 0.5, f), eomgen::SingularMassMatrix);
    M << 1, 0, 0, 0, 1e-14, 0, 0, 0, 1;  // ill-conditioned but regular: solved
    eomgen::solve_mass_matrix(M, f, qdd, 0.5, f);
    CHECK(qdd(1) == Approx(2e14));
    try {
        M.setZero();
        eomgen::solve_mass_matrix(M, f, qdd, 0.5, f);
        FAIL("no exception");
    } catch (const eomgen::SingularMassMatrix& e) {
        CHECK(e.t() == 0.5);
        CHECK(std::string(e.what()).find("mass matrix is singular or not positive definite at t = 0.5") == 0);
    }
}

TEST_CASE("solve_mass_matrix: a non-finite M, f or result throws NonFiniteState", "[runtime][errors]") {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    Eigen::Matrix2d M;
    Eigen::Vector2d f(1, 1), qdd;
    M << 2, nan, nan, 2;  // a NaN pivot is reported as what it comes from
    CHECK_THROWS_AS(eomgen::solve_mass_matrix(M, f, qdd, 0.0, f), eomgen::NonFiniteState);
    M << 2, 1, 1, 2;
    f << nan, 1;  // finite pivots, NaN result: the finite check on the result
    CHECK_THROWS_AS(eomgen::solve_mass_matrix(M, f, qdd, 0.0, f), eomgen::NonFiniteState);
    f << inf, 1;
    CHECK_THROWS_AS(eomgen::solve_mass_matrix(M, f, qdd, 0.0, f), eomgen::NonFiniteState);
    M << 1e-300, 0, 0, 1e-300;  // regular, finite inputs, q̈ overflows
    f << 1e300, 1;
    try {
        eomgen::solve_mass_matrix(M, f, qdd, 0.0, f);
        FAIL("no exception");
    } catch (const eomgen::NonFiniteState& e) {
        CHECK(std::string(e.what()).find("accelerations are not finite") == 0);
    }
}

TEST_CASE("solve_mass_matrix above kLoopSolveMaxN (Eigen's LLT): the same errors", "[runtime][errors]") {
    constexpr int n = int(eomgen::kLoopSolveMaxN) + 5;
    Eigen::Matrix<double, n, n> M = Eigen::Matrix<double, n, n>::Identity();
    Eigen::Matrix<double, n, 1> f = Eigen::Matrix<double, n, 1>::Ones(), qdd;
    M(n - 1, n - 1) = 0;
    CHECK_THROWS_AS(eomgen::solve_mass_matrix(M, f, qdd, 0.0, f), eomgen::SingularMassMatrix);
    M(n - 1, n - 1) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(eomgen::solve_mass_matrix(M, f, qdd, 0.0, f), eomgen::NonFiniteState);
    M(n - 1, n - 1) = 1;
    f(0) = std::numeric_limits<double>::infinity();
    CHECK_THROWS_AS(eomgen::solve_mass_matrix(M, f, qdd, 0.0, f), eomgen::NonFiniteState);
}

namespace {

/// solve_jacobian_columns (analytic_jacobian.hpp) on random SPD M: q̈ = M⁻¹ f, and the columns R(q̈) the callback
/// fills solved with the same factorization, M X = R, on both sides of kLoopSolveMaxN.
template <int N>
void check_jacobian_columns(int n) {
    std::mt19937 rng(15u + unsigned(n));
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 10; ++trial) {
        const Eigen::Matrix<double, N, N> M = random_spd<N>(n, 1e4, rng);
        Eigen::Matrix<double, N, 1> f(n), qdd(n);
        for (int i = 0; i < n; ++i) f(i) = normal(rng);
        Eigen::Matrix<double, N, Eigen::Dynamic> B(n, 3), R(n, 3);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < 3; ++j) B(i, j) = normal(rng);
        Eigen::Matrix<double, N, Eigen::Dynamic> filled;  // R as the callback wrote it: B + q̈ in each column
        eomgen::solve_jacobian_columns(M, f, qdd, R, 0.0, f, [&](const auto& a, auto& r) {
            r = B.colwise() + a;
            filled = r;
        });
        const Eigen::VectorXd ref = Eigen::LLT<Eigen::MatrixXd>(M).solve(Eigen::VectorXd(f));
        CHECK_THAT(Eigen::MatrixXd(qdd), AllClose(ref, 1e-8, 1e-8));
        CHECK_THAT(Eigen::MatrixXd(M * R), AllClose(filled, 1e-8, 1e-8));
        CHECK_THAT(Eigen::MatrixXd(filled.col(0)), AllClose((B.col(0) + ref).eval(), 1e-8, 1e-8));
    }
}

}  // namespace

TEST_CASE("solve_jacobian_columns: q'' and M^-1 R(q'') by one factorization, below and above kLoopSolveMaxN",
          "[runtime]") {
    check_jacobian_columns<4>(4);
    check_jacobian_columns<Eigen::Dynamic>(7);
    check_jacobian_columns<Eigen::Dynamic>(int(eomgen::kLoopSolveMaxN) + 5);
    using S = Eigen::Matrix<double, 2, 2>;
    S M;
    M << 1, 1, 1, 1;  // singular
    Eigen::Vector2d f(1, 2), qdd;
    Eigen::Matrix<double, 2, 3> R;
    CHECK_THROWS_AS(eomgen::solve_jacobian_columns(M, f, qdd, R, 0.0, f, [](const auto&, auto& r) { r.setOnes(); }),
                    eomgen::SingularMassMatrix);
}
