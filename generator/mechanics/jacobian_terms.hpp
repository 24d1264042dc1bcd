/**
 * @file jacobian_terms.hpp  The symbolic parts of the analytic Jacobians ∂ẋ/∂x and ∂ẋ/∂p of an unconstrained model.
 *
 * With x = [q, q̇] and M(q, t; p) q̈ = f(q, q̇, t; p), differentiating M q̈ = f gives, for z any of q_k, q̇_k, p_j,
 *
 *     M ∂q̈/∂z = ∂f/∂z − (∂M/∂z) q̈ = ∂r/∂z at fixed q̈,   r(q, q̇, q̈, t; p) = f − M q̈,
 *
 * so ∂ẋ/∂x = [[0, I], [M⁻¹ ∂r/∂q, M⁻¹ ∂r/∂q̇]] and ∂ẋ/∂p = [[0], [M⁻¹ ∂r/∂p]] (∂M/∂q̇ = 0: M does not depend on
 * the velocities). The columns of ∂r/∂z are ∂f/∂z − Σ_j (∂M_·j/∂z) q̈_j in the symbols q̈_j: ∂M/∂z appears only
 * through its product with q̈, and where it is zero (∂M/∂q_k for a cyclic coordinate, every ∂M/∂g) so is the term.
 * The generated headers evaluate ∂r/∂z (codegen/jacobian_emitter.cpp) once q̈ is solved, and apply M⁻¹ with the
 * same factorization of M. Constrained models have no such terms (their Jacobian goes through the constrained
 * solve, by automatic differentiation in the runtime).
 */
#pragma once

#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <vector>

namespace eomgen {

struct JacobianTerms {
    std::vector<std::vector<GiNaC::ex>> dq;   ///< n×n: ∂r_i/∂q_k = ∂f_i/∂q_k − Σ_j ∂M_ij/∂q_k q̈_j
    std::vector<std::vector<GiNaC::ex>> dqd;  ///< n×n: ∂r_i/∂q̇_k = ∂f_i/∂q̇_k
    std::vector<std::vector<GiNaC::ex>> dp;   ///< n×n_p: ∂r_i/∂p_j = ∂f_i/∂p_j − Σ_l ∂M_il/∂p_j q̈_l
};

/// ∂r/∂q, ∂r/∂q̇ and ∂r/∂p for the model's M and f (eq.M, eq.f), in the symbols q, q̇, q̈, t and the parameters.
JacobianTerms jacobian_terms(const Model& model, const Equations& eq);

}  // namespace eomgen
