/**
 * @file lu_factor.hpp  LU with partial pivoting of a small square matrix, as plain loops: the Newton systems of
 * Radau5 (real and complex) and of the variational integrator.
 *
 * Why not Eigen's PartialPivLU: for the sizes these systems have (a model's 2n, up to about a hundred) its algorithm
 * is this one (unblocked, row interchanges, a rank-one update per column), but instantiating it costs every file
 * that includes an implicit method about 2.5 s of compile time for the real and complex pair of each size, and a
 * fixed-size model is a size of its own (exam_radau5.cpp: 41 s at -O3 with it, 22 s with these loops; a file that
 * integrates one model by Radau5, front end only: 5.6 s with it, 2.9 s with these; docs/benchmarks.md, "Build time").
 */
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <complex>
#include <utility>

namespace eomgen {

namespace detail {

/// The size a pivot is chosen by: |a| for a real entry, |a|² for a complex one (no square root, same order).
template <class S>
S pivot_magnitude(const S& a) {
    using std::abs;
    return abs(a);
}
template <class S>
S pivot_magnitude(const std::complex<S>& a) {
    return std::norm(a);
}

template <class S>
bool finite_entry(const S& a) {
    return std::isfinite(a);
}
template <class S>
bool finite_entry(const std::complex<S>& a) {
    return std::isfinite(a.real()) && std::isfinite(a.imag());
}

/// a·b by the textbook formula: for complex numbers without the checks for infinite parts that C++'s operator*
/// makes (a library call per product, __muldc3, most of the elimination's time); the pivots are finite here.
template <class S>
S product(const S& a, const S& b) {
    return a * b;
}
template <class S>
std::complex<S> product(const std::complex<S>& a, const std::complex<S>& b) {
    return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

}  // namespace detail

/**
 * P A = L U of a square `Matrix` (an Eigen matrix type, fixed or dynamic size, real or complex Scalar) by Gaussian
 * elimination with row interchanges (LAPACK's getf2): L unit lower triangular and U upper triangular, both kept in
 * one matrix, P as the row swapped with row k at each step k.
 *
 *     LuFactor<Eigen::Matrix4d> lu;
 *     if (!lu.compute(A)) ...;   // a zero or non-finite pivot: A is singular (or not finite)
 *     lu.solve_in_place(b);      // b := A⁻¹ b
 */
template <class Matrix>
class LuFactor {
  public:
    using Scalar = typename Matrix::Scalar;
    static constexpr int N = Matrix::RowsAtCompileTime;
    using Vector = Eigen::Matrix<Scalar, N, 1>;

    /// Factors A; false when a pivot is zero or not finite, and then solve() must not be called until a compute()
    /// that returns true.
    template <class MatA>
    bool compute(const MatA& A) {
        lu_ = A;
        n_ = lu_.rows();
        const Eigen::Index n = size();
        swaps_.resize(n);
        for (Eigen::Index k = 0; k < n; ++k) {
            Eigen::Index p = k;
            auto best = detail::pivot_magnitude(lu_(k, k));
            for (Eigen::Index i = k + 1; i < n; ++i) {
                const auto m = detail::pivot_magnitude(lu_(i, k));
                if (m > best) {
                    best = m;
                    p = i;
                }
            }
            swaps_(k) = p;
            if (p != k)
                for (Eigen::Index j = 0; j < n; ++j) std::swap(lu_(k, j), lu_(p, j));
            const Scalar pivot = lu_(k, k);
            if (pivot == Scalar(0) || !detail::finite_entry(pivot)) return false;
            const Scalar inverse = Scalar(1) / pivot;
            for (Eigen::Index i = k + 1; i < n; ++i) lu_(i, k) = detail::product(lu_(i, k), inverse);
            for (Eigen::Index j = k + 1; j < n; ++j) {
                const Scalar u = lu_(k, j);
                if (u == Scalar(0)) continue;  // a sparse Jacobian's zeros cost nothing
                for (Eigen::Index i = k + 1; i < n; ++i) lu_(i, j) -= detail::product(lu_(i, k), u);
            }
        }
        return true;
    }

    /// U's k-th diagonal entry.
    const Scalar& pivot(Eigen::Index k) const { return lu_(k, k); }
    /// The order of the matrix: a constant for a fixed size, so that the loops over it can be unrolled.
    Eigen::Index size() const { return N == Eigen::Dynamic ? n_ : Eigen::Index(N); }

    /// b := A⁻¹ b, for a vector b of A's size.
    template <class Vec>
    void solve_in_place(Vec& b) const {
        const Eigen::Index n = size();
        for (Eigen::Index k = 0; k < n; ++k)
            if (swaps_(k) != k) std::swap(b(k), b(swaps_(k)));
        for (Eigen::Index k = 0; k < n; ++k) {  // L y = P b, column by column
            const Scalar y = b(k);
            if (y == Scalar(0)) continue;
            for (Eigen::Index i = k + 1; i < n; ++i) b(i) -= detail::product(lu_(i, k), y);
        }
        for (Eigen::Index k = n - 1; k >= 0; --k) {  // U x = y
            b(k) /= lu_(k, k);
            const Scalar x = b(k);
            for (Eigen::Index i = 0; i < k; ++i) b(i) -= detail::product(lu_(i, k), x);
        }
    }

    /// A⁻¹ b.
    template <class Vec>
    Vector solve(const Vec& b) const {
        Vector x = b;
        solve_in_place(x);
        return x;
    }

  private:
    Matrix lu_;
    Eigen::Matrix<Eigen::Index, N, 1> swaps_;
    Eigen::Index n_ = 0;
};

}  // namespace eomgen
