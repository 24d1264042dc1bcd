/** @file results.hpp  Closed-form results a model declares ([[results]]): what `equals` names, the
 * constraints solved for coordinates and velocities, and the check that a declared result holds. */
#pragma once

#include "mechanics/lagrangian.hpp"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace eomgen {

/**
 * The constraints solved for some of the coordinates and velocities, to put an expression "on the
 * constraints": each holonomic constraint g(q, t) = 0 that is linear in a coordinate q_j is solved for it
 * (q_j = s(q, t), and q̇_j, q̈_j = ds/dt, d²s/dt²); the velocity constraints A q̇ + b = 0 left (nonholonomic
 * ones, and holonomic ones no coordinate could be solved from) are solved for as many velocities by
 * elimination. Coordinates and velocities that `keep` does not use are solved for first, so that an
 * expression written in the remaining ones stays in them.
 */
struct ConstraintReduction {
    GiNaC::exmap coordinates;         ///< q_j → s, q̇_j → ṡ, q̈_j → s̈
    GiNaC::exmap velocities;          ///< q̇_k → in the remaining velocities, free of the solved q_j
    std::vector<std::string> solved;  ///< "theta = ...", "psi' = ...", for messages
    GiNaC::ex apply(const GiNaC::ex& e) const { return e.subs(coordinates).subs(velocities); }
};

ConstraintReduction reduce_on_constraints(const Model& model, const Equations& eq, const GiNaC::ex& keep);

/**
 * What must vanish for `result` to hold: expr − X for X among T, V, L, energy (h), p_<coordinate>,
 * inertia.<body>.<ij> (the body's tensor about its centre of mass, body axes, as eomgen uses it) and
 * inertia_origin.<body>.<ij> (the same tensor shifted to the space origin, I_c + M(c²1 − c cᵀ), c the
 * centre of mass in body axes); det(I − expr 1) for principal.<body> and principal_origin.<body> (expr is a
 * principal moment). Throws ModelError at `equals` when it names nothing of the model.
 */
GiNaC::ex result_residual(const Model& model, const Equations& eq, const Result& result);

/// A human name of what `equals` names: "T", "the momentum p_phi", "a principal moment of body 'plate'".
std::string result_target_name(const Result& result);

/// Checks every result with `equals` (on the constraints when `on_constraints`); throws ModelError at the
/// result's expr when one does not hold, with the difference.
void verify_results(const Model& model, const Equations& eq);

}  // namespace eomgen
