/** @file constrained_motion.hpp  Whether an equation with accelerations and no multipliers holds on every motion of a
 * model with constraints: `\ddot x = r\ddot\theta` (a rolling constraint differentiated twice), `\ddot x =
 * \frac{2}{3} g \sin\alpha` (the equations with the constraint forces eliminated) — neither is a combination of
 * the Euler–Lagrange equations alone (issue 28). */
#pragma once

#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>
#include <optional>
#include <vector>

namespace eomgen::checker {

/**
 * r(q, q̇, q̈, t) = 0 at three sample states of the model with constraints: the parameters at their values, q
 * and t drawn, q̇ drawn and projected onto the velocity constraints A q̇ + b = 0, and q̈ from
 * [M Aᵀ; A 0] [q̈; −λ] = [f + Q; γ], q first moved onto the holonomic constraints g(q, t) = 0. With `multipliers`
 * (one symbol per constraint, as the text writes them), r may hold them: each takes `sign` times the λ of that
 * state (sign −1: the text's multiplier has the opposite sign to eomgen's M q̈ = f + Aᵀλ). `assumed`: parameters the
 * text sets for its paragraph (m_1 = m_2), which take that value. True when |r| is within
 * `tol` of the size of its terms at every state, false when it is not at one; nothing when r holds a name the
 * model does not know, a state gives no finite value or the system is singular there.
 */
/// The multiplier of constraint k solved from [M −Aᵀ; A 0][q̈; λ] = [f + Q; γ] (eomgen's sign, M q̈ = f + Aᵀλ), for up
/// to 6 unknowns; nothing when larger or singular.
std::optional<GiNaC::ex> solved_multiplier(const Model& model, const Equations& eq, std::size_t k);

std::optional<bool> holds_on_constrained_motion(const GiNaC::ex& r, const Model& model, const Equations& eq,
                                                double tol, const std::vector<GiNaC::symbol>& multipliers = {},
                                                int sign = 1, const GiNaC::exmap& assumed = {});

}  // namespace eomgen::checker
