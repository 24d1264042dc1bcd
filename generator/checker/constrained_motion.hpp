/** @file constrained_motion.hpp  Whether an equation with accelerations and no multipliers holds on every motion of a
 * model with constraints: `\ddot x = r\ddot\theta` (a rolling constraint differentiated twice), `\ddot x =
 * \frac{2}{3} g \sin\alpha` (the equations with the constraint forces eliminated) — neither is a combination of
 * the Euler–Lagrange equations alone (issue 28). */
#pragma once

#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>
#include <optional>

namespace eomgen::checker {

/**
 * r(q, q̇, q̈, t) = 0 at three sample states of the model with constraints: the parameters at their values, q
 * and t drawn, q̇ drawn and projected onto the velocity constraints A q̇ + b = 0, and q̈ from
 * [M Aᵀ; A 0] [q̈; −λ] = [f + Q; γ]. True when |r| is within `tol` of the size of its terms at every state,
 * false when it is not at one; nothing when r holds a name the model does not know, a state gives no finite
 * value or the system is singular there. Position-level constraints are not imposed on q (an equation that
 * needs them, such as x = R θ substituted, is not decided by this).
 */
std::optional<bool> holds_on_constrained_motion(const GiNaC::ex& r, const Model& model, const Equations& eq,
                                                double tol);

}  // namespace eomgen::checker
