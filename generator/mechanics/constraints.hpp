/** @file constraints.hpp  Constraint Jacobians, acceleration-level equations, redundancy and integrability. */
#pragma once

#include "mechanics/lagrangian.hpp"

#include <vector>

namespace eomgen {

/**
 * Derives every constraint of `model` at position, velocity and acceleration level:
 * holonomic g(q,t) = 0 gives c = dg/dt = G q̇ + ∂g/∂t with A = G = ∂g/∂q; nonholonomic c = a·q̇ + b gives
 * A = a. Differentiating c once more, A q̈ = γ with γ = −(dc/dt)|_{q̈=0}.
 * Throws ModelError (at the constraint) for a "nonholonomic" constraint that is not linear in the
 * velocities, or a constraint that depends on no velocity at all, and for redundant constraints (A of
 * deficient rank at every sampled q: the later, dependent one is named).
 */
std::vector<ConstraintEquations> derive_constraints(const Model& model);

/**
 * Integrability of the nonholonomic constraints, each as the Pfaffian form ω = Σ a_i dq_i + b dt on
 * (q, t): exact when dω = 0, integrable (by an integrating factor) when ω ∧ dω = 0, and for several
 * together the Frobenius condition dω_k ∧ ω_1 ∧ … ∧ ω_m = 0 for every k (Flanders, "Differential Forms",
 * §6.1). Checked numerically at random points (the conditions are identities in q, t). Fills each
 * constraint's exact/integrable/verdict and returns the verdict on the set ("" for fewer than two).
 */
std::string analyse_integrability(const Model& model, std::vector<ConstraintEquations>& constraints);

}  // namespace eomgen
