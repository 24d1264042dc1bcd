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
 * Throws SingularMassMatrix when the factorisation fails or M's reciprocal condition number is below
 * n·eps (M is singular to working precision), and NonFiniteState when f or the result is not finite.
 * `t` and `x` (the full state) only go into the error message.
 */
template <class MatM, class VecF, class VecQdd, class Scalar, class VecX>
void solve_mass_matrix(const MatM& M, const VecF& f, VecQdd& qdd, const Scalar& t, const VecX& x) {
    using S = typename MatM::Scalar;
    if (!M.allFinite() || !f.allFinite())
        throw NonFiniteState(describe_state("mass matrix or forcing is not finite", t, x), double(t));
    Eigen::LLT<typename MatM::PlainObject> llt(M);
    const S tiny = S(M.rows()) * std::numeric_limits<S>::epsilon();
    if (llt.info() != Eigen::Success || !(llt.rcond() > tiny))
        throw SingularMassMatrix(describe_state("mass matrix is singular or not positive definite", t, x),
                                 double(t));
    qdd = llt.solve(f);
}

}  // namespace eomgen
