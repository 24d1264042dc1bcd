/** @file jacobian_emitter.hpp  The analytic Jacobians ∂ẋ/∂x and ∂ẋ/∂p in the header of an unconstrained model. */
#pragma once

#include "codegen/cpp_emitter.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <string>

namespace eomgen::codegen {

/**
 * The members (4-space indented) `jacobian_terms(t, q_, qd_, qdd_, p_, R_)` (R = [∂r/∂q, ∂r/∂q̇], r = f − M q̈,
 * mechanics/jacobian_terms.hpp), `parameter_jacobian_terms(t, q_, qd_, qdd_, p_, Rp_)` (∂r/∂p), each CSE'd, and the
 * member templates `state_jacobian(t, x_, p_, J_)` and `parameter_jacobian(t, x_, p_, Jp_)`, which solve M q̈ = f
 * and M X = R with one factorization (eomgen::solve_jacobian_columns, analytic_jacobian.hpp).
 */
std::string emit_analytic_jacobian(const Model& model, const Equations& eq, const SymbolTable& table);

/**
 * For a header whose rhs() is a tree of point masses' O(n) recursion (tree_emitter.hpp): the member templates
 * `state_jacobian(t, x_, p_, J_)` and `parameter_jacobian(t, x_, p_, Jp_)` by forward differentiation through that
 * recursion (eomgen::state_jacobian, eomgen::linearize), exact to round-off, for Model<double>. Differentiating
 * the dense r = f − M q̈ symbolically (emit_analytic_jacobian) was 70 % of generating the 30-link pendulum with
 * every optional function; this costs the generator nothing and the run O(n) per seeded direction.
 */
std::string emit_recursion_jacobian();

}  // namespace eomgen::codegen
