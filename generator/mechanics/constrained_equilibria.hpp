/**
 * @file constrained_equilibria.hpp  Rest and small oscillations on a constraint manifold: the holonomic,
 * time-independent constraints g(q) = 0 of a model, the conditions of rest with their multipliers, and the
 * tangent space the linearization is restricted to (used by small_oscillations.cpp).
 *
 * At rest on the manifold the applied generalized forces are balanced by the forces of constraint: with
 * G = ∂V_eff/∂q − Q (Q at q̇ = 0) and A = ∂g/∂q, the equations M q̈ = f + Aᵀλ at rest read
 *
 *     G(q) − A(q)ᵀ λ = 0,   g(q) = 0,
 *
 * n + m equations in q and λ (λ as in the generated code: λ_k is the generalized force of constraint k).
 * Near such a point the motion stays on the manifold to first order, δq = N δs with N an orthonormal basis
 * of A's null space, and the constraint's curvature enters the stiffness through the multipliers:
 *
 *     K₀ = ∂G/∂q − Σ_k λ_k ∂²g_k/∂q²,   reduced: NᵀM₀N δs̈ + NᵀD₀N δṡ + NᵀK₀N δs = 0
 *
 * (the Hessian of the Lagrangian function V_eff − λᵀg on the tangent space: the second-order condition of
 * a constrained minimum, Nocedal & Wright, Numerical Optimization, 2nd ed., §12.4). A plane pendulum in
 * Cartesian x, y with x² + y² − l² = 0: λ = −m g/(2l) at the bottom, K₀ = (m g/l) I, N = (1, 0), ω² = g/l.
 */
#pragma once

#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <Eigen/Core>
#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace eomgen {

/// The constraints as the linearization needs them, over the coordinates that remain after a reduction.
struct ManifoldConstraints {
    std::vector<std::string> names;
    std::vector<GiNaC::ex> g;                        ///< g_k(q)
    std::vector<std::vector<GiNaC::ex>> jacobian;    ///< A_kj = ∂g_k/∂q_j
    std::vector<std::vector<std::vector<GiNaC::ex>>> hessian;  ///< ∂²g_k/∂q_i∂q_j
    std::vector<GiNaC::symbol> lambda;               ///< one multiplier symbol per constraint
    bool empty() const { return g.empty(); }
    std::size_t size() const { return g.size(); }
};

/**
 * The model's constraints over the coordinates `q` (those that remain; `reduced` names the ones reduced away).
 * Throws ModesError for what has no equilibria of this kind: a nonholonomic constraint, one that depends on t
 * (a prescribed motion), one on a coordinate reduced away by --momentum.
 */
ManifoldConstraints manifold_constraints(const Model& model, const Equations& eq, const std::vector<GiNaC::symbol>& q,
                                         const std::vector<std::string>& reduced);

/**
 * The rest conditions with multipliers, as one system in (q, λ): G − Aᵀλ over the coordinates and g over the
 * constraints, with its Jacobian. Without constraints, G and ∂G/∂q themselves.
 */
void rest_conditions(const std::vector<GiNaC::ex>& G, const std::vector<std::vector<GiNaC::ex>>& dG,
                     const ManifoldConstraints& c, std::vector<GiNaC::ex>& F, std::vector<std::vector<GiNaC::ex>>& J);

/// An orthonormal basis of the null space of A (m × n), n × (n − rank A); the identity when A has no rows.
Eigen::MatrixXd tangent_basis(const Eigen::MatrixXd& A);

}  // namespace eomgen
