/** @file linear_solve.hpp  Solving M(q) q̈ = f for the generated right-hand sides, with failures reported. */
#pragma once

#include "eomgen/device.hpp"
#include "eomgen/errors.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <type_traits>

namespace eomgen {

/**
 * The singularity test of every mass-matrix solve, on the pivots d_i of M = L D Lᵀ (d_i = L_ii² of the Cholesky
 * factor): regular when the smallest is above n·eps times the largest (which also requires them all positive;
 * a NaN pivot fails). The pivots are Schur complements of M's leading blocks, so λ_min(M) ≤ d_i ≤ λ_max(M)
 * (interlacing): the ratio is never below 1/cond₂(M), and a collapsing pivot is how a singular M shows in its
 * factor. It costs n comparisons, where LLT::rcond() costs several triangular solves. For an automatic-
 * differentiation Scalar the comparisons are on the value parts. `margin` > 1 asks for that much more room
 * (the constraints' Schur complement, whose entries carry M's rounding already).
 */
template <class Pivots>
bool pivots_regular(const Pivots& d, double margin = 1) {
    using S = std::decay_t<decltype(d[0])>;
    const int n = int(d.size());
    S lo = d[0], hi = d[0];
    for (int i = 1; i < n; ++i) {
        if (d[i] < lo) lo = d[i];
        if (d[i] > hi) hi = d[i];
    }
    return lo > S(margin) * S(n) * S(Eigen::NumTraits<S>::epsilon()) * hi;
}

/**
 * What a failed solve of M q̈ = f throws, found only once it has failed (no pass over M or f on the way):
 * NonFiniteState when M or f is not finite (a NaN pivot or result usually comes from there), else
 * SingularMassMatrix when the pivots were not regular, else NonFiniteState (q̈ overflowed). `t` and `x` (the full
 * state) only go into the message.
 */
template <class MatM, class VecF, class Scalar, class VecX>
[[noreturn]] void throw_solve_failure(const MatM& M, const VecF& f, bool singular, const Scalar& t, const VecX& x) {
    if (!M.allFinite() || !f.allFinite())
        throw NonFiniteState(describe_state("mass matrix or forcing is not finite", t, x), value_of(t));
    if (singular)
        throw SingularMassMatrix(describe_state("mass matrix is singular or not positive definite", t, x),
                                 value_of(t));
    throw NonFiniteState(describe_state("accelerations are not finite", t, x), value_of(t));
}

/// M = L D Lᵀ row by row (the factorization of solve_mass_matrix, below): L's strict lower triangle in L (row i
/// holds u_ik = L_ik d_k while it is built), the pivots in d, their inverses in inv_d; n the order of M.
template <class MatM, class MatL, class VecD>
EOMGEN_HD void factor_ldlt(const MatM& M, Eigen::Index n, MatL& L, VecD& d, VecD& inv_d) {
    using S = typename MatM::Scalar;
    for (Eigen::Index i = 0; i < n; ++i) {
        S di = M(i, i);
        for (Eigen::Index j = 0; j < i; ++j) {
            S u = M(i, j);
            for (Eigen::Index k = 0; k < j; ++k) u -= L(i, k) * L(j, k);
            L(i, j) = u;  // u_ij = L_ij d_j, kept until the row is done: the sums above need it
        }
        for (Eigen::Index j = 0; j < i; ++j) {
            const S l = L(i, j) * inv_d(j);
            di -= L(i, j) * l;
            L(i, j) = l;
        }
        d(i) = di;
        inv_d(i) = S(1) / di;
    }
}

/// Overwrites every column b of B (n rows) with M⁻¹ b, M = L D Lᵀ as factor_ldlt left it: L y = b, Lᵀ z = D⁻¹ y.
template <class MatL, class VecD, class MatB>
EOMGEN_HD void substitute_ldlt(const MatL& L, const VecD& inv_d, Eigen::Index n, MatB& B) {
    using S = typename MatB::Scalar;
    for (Eigen::Index c = 0; c < B.cols(); ++c) {
        for (Eigen::Index i = 0; i < n; ++i) {
            S y = B(i, c);
            for (Eigen::Index k = 0; k < i; ++k) y -= L(i, k) * B(k, c);
            B(i, c) = y;
        }
        for (Eigen::Index i = n; i-- > 0;) {
            S z = B(i, c) * inv_d(i);
            for (Eigen::Index k = i + 1; k < n; ++k) z -= L(k, i) * B(k, c);
            B(i, c) = z;
        }
    }
}

/**
 * Solves M qdd = f for symmetric positive definite M (n×n, fixed or dynamic size; only its lower triangle is read)
 * by M = L D Lᵀ, row by row (Golub & Van Loan, "Matrix Computations", §4.1): with u_ik = L_ik d_k,
 *   L_ij = (M_ij − Σ_{k<j} u_ik L_jk) / d_j,   d_i = M_ii − Σ_{k<i} u_ik L_ik,
 * then L y = f, z = D⁻¹ y, Lᵀ qdd = z. Throws SingularMassMatrix when the pivots d_i are not regular
 * (pivots_regular) and NonFiniteState when M or f is not finite or q̈ is not (throw_solve_failure); the finite test
 * is on the result only. `t` and `x` (the full state) only go into the error message. Generated headers emit the
 * same factorization unrolled for small n (generator/codegen/mass_solve_emitter.cpp) and call this above.
 * Above kLoopSolveMaxN the factorization is Eigen's LLT (d_i = L_ii²), whose vectorized kernels win there
 * (bench/run.sh --peers-only, section 8: at n = 30 the loop made rhs 1.15× slower than LLT, at n = 20 1.4× faster).
 */
constexpr Eigen::Index kLoopSolveMaxN = 20;

/**
 * The factorization of a symmetric positive definite matrix that solve_mass_matrix and the constrained solve
 * (constraints.hpp) use: M = L D Lᵀ by factor_ldlt up to kLoopSolveMaxN rows, Eigen's LLT above (d_i = L_ii²);
 * only M's lower triangle is read. compute() says whether the pivots are regular (pivots_regular); nothing else
 * passes over M. N is M's compile-time size (or Eigen::Dynamic). A fixed size up to kLoopSolveMaxN never builds the
 * LLT path: instantiating Eigen's LLT and its solves for each fixed size was most of the compile time of a
 * constrained model's shared object (two factors, M's and the Schur complement's; with Eigen's products,
 * constraints.hpp, solve_constrained alone for rolling_disc's sizes took 8.4 s at -O2, 1.5 s without both).
 */
template <class S, int N>
class MassFactor {
    static constexpr bool kLoopsOnly = N != Eigen::Dynamic && N <= kLoopSolveMaxN;

  public:
    template <class MatM>
    bool compute(const MatM& M, double margin = 1) {
        n_ = N == Eigen::Dynamic ? M.rows() : N;  // a constant where M's size is: loops the compiler can unroll
                                                  // and schedule (Eigen's dot products on segments measured slower
                                                  // up to n = 30)
        loops_ = n_ <= kLoopSolveMaxN;
        if (n_ == 0) return true;  // no constraints: nothing to factor
        if constexpr (!kLoopsOnly) {
            if (!loops_) {
                llt_.compute(M);
                return llt_.info() == Eigen::Success &&
                       pivots_regular(llt_.matrixLLT().diagonal().cwiseAbs2().eval(), margin);
            }
        }
        L_.resize(n_, n_);
        d_.resize(n_);
        inv_d_.resize(n_);
        factor_ldlt(M, n_, L_, d_, inv_d_);
        return pivots_regular(d_, margin);
    }

    /// Overwrites every column b of B (n rows) with M⁻¹ b.
    template <class MatB>
    void solve_in_place(MatB& B) const {
        if constexpr (kLoopsOnly) {
            substitute_ldlt(L_, inv_d_, n_, B);
        } else {
            if (loops_)
                substitute_ldlt(L_, inv_d_, n_, B);
            else
                llt_.solveInPlace(B);
        }
    }

  private:
    Eigen::Index n_ = 0;
    bool loops_ = true;
    Eigen::Matrix<S, N, N, Eigen::RowMajor> L_;  // row i: L_ik for k < i
    Eigen::Matrix<S, N, 1> d_, inv_d_;
    std::conditional_t<kLoopsOnly, char, Eigen::LLT<Eigen::Matrix<S, N, N>>> llt_{};  // unused when kLoopsOnly
};

/**
 * solve_mass_matrix, then `then(solve)` with `solve(B)` overwriting each column of B (n rows) with M⁻¹ of it by the
 * same factorization: more right-hand sides that depend on q̈ (the generated analytic Jacobians,
 * analytic_jacobian.hpp) for one factorization of M.
 */
template <class MatM, class VecF, class VecQdd, class Scalar, class VecX, class Then>
void solve_mass_matrix_then(const MatM& M, const VecF& f, VecQdd& qdd, const Scalar& t, const VecX& x, Then&& then) {
    MassFactor<typename MatM::Scalar, MatM::RowsAtCompileTime> factor;
    if (!factor.compute(M)) throw_solve_failure(M, f, true, t, x);
    qdd = f;
    factor.solve_in_place(qdd);
    if (!qdd.allFinite()) throw_solve_failure(M, f, false, t, x);
    then([&factor](auto& B) { factor.solve_in_place(B); });
}

template <class MatM, class VecF, class VecQdd, class Scalar, class VecX>
void solve_mass_matrix(const MatM& M, const VecF& f, VecQdd& qdd, const Scalar& t, const VecX& x) {
    solve_mass_matrix_then(M, f, qdd, t, x, [](const auto&) {});
}

}  // namespace eomgen
