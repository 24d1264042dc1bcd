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
 * velocities, or a constraint that depends on no velocity at all, for redundant constraints (A of
 * deficient rank at every sampled q: the later, dependent one is named), for as many independent constraints as
 * coordinates when none moves with t (no motion is left), and for constraints dependent at the model's initial
 * state.
 */
std::vector<ConstraintEquations> derive_constraints(const Model& model);

/// Whether a constraint moves with t (rheonomic): b = ∂g/∂t ≢ 0, or its Jacobian depends on t. Energy is not
/// conserved under one, and ones that fix every coordinate prescribe a motion rather than leave none.
bool moves_with_time(const ConstraintEquations& c, const Model& model);

/**
 * Integrability of the nonholonomic constraints, each as the Pfaffian form ω = Σ a_i dq_i + b dt on
 * (q, t): exact when dω = 0, integrable (by an integrating factor) when ω ∧ dω = 0, and for several
 * together the Frobenius condition dω_k ∧ ω_1 ∧ … ∧ ω_m = 0 for every k (Flanders, "Differential Forms",
 * §6.1). Checked numerically at random points (the conditions are identities in q, t). Fills each
 * constraint's exact/integrable/verdict and returns the verdict on the set ("" for fewer than two).
 */
std::string analyse_integrability(const Model& model, std::vector<ConstraintEquations>& constraints);

}  // namespace eomgen
