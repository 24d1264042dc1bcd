/** @file linear_solve.hpp  Solving M(q) q̈ = f for the generated right-hand sides, with failures reported. */
#pragma once

#include "eomgen/errors.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace eomgen {

/**
 * Solves M qdd = f for symmetric positive definite M (size n×n, fixed or dynamic) by Cholesky (LLT).
 * Throws SingularMassMatrix when the factorisation fails or M is singular to working precision, and
 * NonFiniteState when M or f is not finite. `t` and `x` (the full state) only go into the error message.
 *
 * Singular to working precision: the smallest Cholesky pivot L_ii² is below n·eps times the largest. The
 * pivots are Schur complements of M's leading blocks, so λ_min(M) ≤ L_ii² ≤ λ_max(M) (interlacing): the
 * pivot ratio is never below 1/cond₂(M), and a collapsing pivot is how a singular M shows in its factor. It
 * costs n comparisons, where LLT::rcond() costs several triangular solves — most of the solve for small n.
 */
template <class MatM, class VecF, class VecQdd, class Scalar, class VecX>
void solve_mass_matrix(const MatM& M, const VecF& f, VecQdd& qdd, const Scalar& t, const VecX& x) {
    using S = typename MatM::Scalar;
    if (!M.allFinite() || !f.allFinite())
        throw NonFiniteState(describe_state("mass matrix or forcing is not finite", t, x), value_of(t));
    Eigen::LLT<typename MatM::PlainObject> llt(M);
    bool singular = llt.info() != Eigen::Success;
    if (!singular) {
        const auto pivots = llt.matrixLLT().diagonal().cwiseAbs2();
        singular = !(pivots.minCoeff() > S(M.rows()) * S(Eigen::NumTraits<S>::epsilon()) * pivots.maxCoeff());
    }
    if (singular)
        throw SingularMassMatrix(describe_state("mass matrix is singular or not positive definite", t, x),
                                 value_of(t));
    qdd = llt.solve(f);
}

}  // namespace eomgen
