/** @file exam_lu_factor.cpp  LuFactor (lu_factor.hpp), the LU of Radau5's and the variational integrator's Newton
 * systems: solutions against Eigen's PartialPivLU (dynamic sizes, as a reference) for real and complex matrices of
 * fixed and dynamic size, the row interchanges a zero leading entry needs, and singular or non-finite matrices. */
#include "eomgen/lu_factor.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <catch2/catch.hpp>

#include <complex>
#include <limits>
#include <random>

namespace {

template <class S>
S random_entry(std::mt19937& rng) {
    std::normal_distribution<double> normal;
    if constexpr (std::is_same_v<S, std::complex<double>>)
        return {normal(rng), normal(rng)};
    else
        return S(normal(rng));
}

/// LuFactor<Matrix> of random n×n matrices against Eigen's PartialPivLU of the same in dynamic size: the solution
/// of A x = b to round-off (the residual and the reference), and the pivots' product as the determinant's modulus.
template <class S, int N>
void check_against_eigen(int n) {
    using Matrix = Eigen::Matrix<S, N, N>;
    using Dynamic = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
    using DynamicVector = Eigen::Matrix<S, Eigen::Dynamic, 1>;
    std::mt19937 rng(20261128u + unsigned(n));
    for (int trial = 0; trial < 10; ++trial) {
        Matrix A(n, n);
        Eigen::Matrix<S, N, 1> b(n);
        for (int i = 0; i < n; ++i) {
            b(i) = random_entry<S>(rng);
            for (int j = 0; j < n; ++j) A(i, j) = random_entry<S>(rng);
        }
        eomgen::LuFactor<Matrix> lu;
        REQUIRE(lu.compute(A));
        const Eigen::PartialPivLU<Dynamic> reference{Dynamic(A)};
        const DynamicVector expected = reference.solve(DynamicVector(b));
        const DynamicVector x = lu.solve(b);
        const double scale = expected.cwiseAbs().maxCoeff();
        INFO("n = " << n << ", trial " << trial);
        CHECK((x - expected).cwiseAbs().maxCoeff() <= 1e-10 * scale);
        CHECK((Dynamic(A) * x - DynamicVector(b)).cwiseAbs().maxCoeff() <= 1e-12 * (1 + A.cwiseAbs().maxCoeff() * scale) * n);
        std::complex<double> det = 1;
        for (int i = 0; i < n; ++i) det *= std::complex<double>(lu.pivot(i));
        CHECK(std::abs(det) == Approx(std::abs(std::complex<double>(reference.determinant()))).epsilon(1e-10));
    }
}

}  // namespace

TEST_CASE("LuFactor: real and complex, fixed and dynamic sizes, equals Eigen's PartialPivLU", "[runtime]") {
    check_against_eigen<double, 1>(1);
    check_against_eigen<double, 4>(4);
    check_against_eigen<double, 9>(9);
    check_against_eigen<std::complex<double>, 4>(4);
    for (int n : {1, 2, 6, 30}) {
        check_against_eigen<double, Eigen::Dynamic>(n);
        check_against_eigen<std::complex<double>, Eigen::Dynamic>(n);
    }
}

TEST_CASE("LuFactor: a zero leading entry needs the row interchange, and solve_in_place equals solve", "[runtime]") {
    Eigen::Matrix3d A;
    A << 0, 2, 1,  //
        1, 1, 0,   //
        3, 0, 4;
    const Eigen::Vector3d x_true(1, -2, 0.5);
    const Eigen::Vector3d b = A * x_true;
    eomgen::LuFactor<Eigen::Matrix3d> lu;
    REQUIRE(lu.compute(A));
    Eigen::Vector3d x = b;
    lu.solve_in_place(x);
    CHECK((x - x_true).cwiseAbs().maxCoeff() < 1e-14);
    CHECK((lu.solve(b) - x).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("LuFactor: a singular or non-finite matrix is refused, and the next regular one is factored", "[runtime][errors]") {
    eomgen::LuFactor<Eigen::MatrixXd> lu;
    Eigen::MatrixXd singular(3, 3);
    singular << 1, 2, 3,  //
        2, 4, 6,          //
        0, 1, 1;
    CHECK_FALSE(lu.compute(singular));
    CHECK_FALSE(lu.compute(Eigen::MatrixXd::Zero(2, 2)));
    Eigen::MatrixXd nan = Eigen::MatrixXd::Identity(2, 2);
    nan(1, 1) = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(lu.compute(nan));
    Eigen::MatrixXd inf = Eigen::MatrixXd::Identity(2, 2);
    inf(0, 0) = std::numeric_limits<double>::infinity();
    CHECK_FALSE(lu.compute(inf));
    const Eigen::MatrixXd regular = 2 * Eigen::MatrixXd::Identity(4, 4);
    REQUIRE(lu.compute(regular));
    CHECK(lu.size() == 4);
    CHECK((lu.solve(Eigen::VectorXd::Ones(4)) - Eigen::VectorXd::Constant(4, 0.5)).cwiseAbs().maxCoeff() == 0.0);

    eomgen::LuFactor<Eigen::Matrix<std::complex<double>, 2, 2>> c;
    Eigen::Matrix<std::complex<double>, 2, 2> z;
    z << std::complex<double>(1, 1), std::complex<double>(2, 2),  //
        std::complex<double>(1, 0), std::complex<double>(2, 0);  // the second column twice the first
    CHECK_FALSE(c.compute(z));
}
