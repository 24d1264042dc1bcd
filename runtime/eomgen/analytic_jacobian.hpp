/**
 * @file analytic_jacobian.hpp  The solve behind a generated header's analytic state_jacobian() and
 * parameter_jacobian() (docs/generated_code.md): q̈ from M q̈ = f, then the columns X = M⁻¹ R(q̈) of ∂q̈/∂x or
 * ∂q̈/∂p, with one factorization of M for both.
 */
#pragma once

#include "eomgen/linear_solve.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace eomgen {

/**
 * Solves M qdd = f, calls terms(qdd, R) for the right-hand sides R (the generated jacobian_terms(): ∂(f − M q̈)/∂z at
 * the solved q̈), and overwrites R with M⁻¹ R, all with one factorization of M (solve_mass_matrix_then): the
 * L D Lᵀ of solve_mass_matrix up to kLoopSolveMaxN, Eigen's LLT above, as there. rhs() of a model with at most
 * kUnrolledSolveMaxN (12) coordinates solves by the same L D Lᵀ unrolled, so q̈ agrees with its q̈ to round-off. The
 * same failures as solve_mass_matrix: SingularMassMatrix when the pivots are not regular (pivots_regular),
 * NonFiniteState when M, f, q̈ or the solved columns are not finite. `t` and `x` only go into the message.
 */
template <class MatM, class VecF, class VecQdd, class MatR, class Scalar, class VecX, class Terms>
void solve_jacobian_columns(const MatM& M, const VecF& f, VecQdd& qdd, MatR& R, const Scalar& t, const VecX& x,
                            Terms&& terms) {
    solve_mass_matrix_then(M, f, qdd, t, x, [&](const auto& solve) {
        terms(qdd, R);
        solve(R);
    });
    if (!R.allFinite()) throw NonFiniteState(describe_state("Jacobian columns are not finite", t, x), value_of(t));
}

}  // namespace eomgen
