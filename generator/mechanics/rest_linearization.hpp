/**
 * @file rest_linearization.hpp  The symbolic coefficients of the equations of motion linearized about rest.
 *
 * L is at most quadratic in the velocities (derive_equations checks T), so it splits as
 * L = ½ q̇ᵀ M(q) q̇ + β(q)ᵀ q̇ + L₀(q), with V_eff = −L₀ = V − T₀. About a state of rest (q₀, q̇ = 0), with the
 * generalized forces Q(q, q̇) (applied, and −∂R/∂q̇ of a Rayleigh function),
 *
 *     M(q₀) δq̈ + D(q₀) δq̇ + K(q₀) δq = −G(q₀),
 *     G = ∂V_eff/∂q − Q|₀,   K = ∂G/∂q,   D_ij = ∂β_i/∂q_j − ∂β_j/∂q_i − ∂Q_i/∂q̇_j|₀,
 *
 * G = 0 at an equilibrium; D's symmetric part is damping, its skew part gyroscopic (Goldstein §6.1–6.2;
 * Meirovitch, Methods of Analytical Dynamics, ch. 6). Used by `eomgen modes` (small_oscillations.cpp, on a
 * Routh-reduced L too) and by the generated headers' stiffness(), damping() and gyroscopic().
 */
#pragma once

#include <ginac/ginac.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen {

struct RestLinearization {
    GiNaC::ex V_eff;                           ///< −L(q̇ = 0)
    std::vector<GiNaC::ex> beta;               ///< ∂L/∂q̇ at q̇ = 0 (the part of L linear in q̇)
    std::vector<GiNaC::ex> gradient;           ///< G = ∂V_eff/∂q − Q at q̇ = 0: zero at an equilibrium
    std::vector<std::vector<GiNaC::ex>> M;     ///< ∂²L/∂q̇² (at q̇ = 0, on which it does not depend)
    std::vector<std::vector<GiNaC::ex>> K;     ///< ∂G/∂q
    std::vector<std::vector<GiNaC::ex>> D;     ///< damping (symmetric part) + gyroscopic (skew part)
    /// False where ∂Q_i/∂q̇_j has no value at rest (dry friction, sign(q̇_j)): D_ij then holds the rest, without it.
    std::vector<std::vector<bool>> D_defined;
    std::vector<std::string> undefined;  ///< what is not defined and why, one line each (empty when all is)
};

/// A coefficient that has no value at rest: a force whose derivative in a velocity has no limit as it goes to 0
/// (a dry friction sign(q̇)); the message names the expression and the velocity.
struct NoValueAtRest : std::runtime_error {
    NoValueAtRest(const GiNaC::ex& e, const GiNaC::symbol& velocity);
};

/// The coefficients for L(q, q̇) and the forces Q(q, q̇) (one per coordinate), in the symbols q and qd. Where
/// substituting q̇ = 0 divides by zero (∂/∂θ' of θ' sqrt(θ'²), 0/0), the two-sided limit is taken; throws
/// NoValueAtRest where there is none.
RestLinearization linearize_about_rest(const GiNaC::ex& L, const std::vector<GiNaC::ex>& Q,
                                       const std::vector<GiNaC::symbol>& q, const std::vector<GiNaC::symbol>& qd);

}  // namespace eomgen
