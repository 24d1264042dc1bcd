/** @file claimed_solution.hpp  A solution the text claims for a coordinate (`s(t) = s_0\cos(\omega t)`, `x =
 * \frac12 g t^2`): put into the equation of motion of that coordinate, it must make it hold for every t. */
#pragma once

#include "checker/checker.hpp"
#include "checker/comparisons.hpp"
#include "checker/latex_parser.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace eomgen::checker {

/**
 * Judges `left = right` as a claimed solution, when one side is a coordinate q_k alone and the other a function
 * F of t (in the parameters, and in constants the text introduces: s_0, A, φ_0), without q, q̇ or q̈. The other
 * coordinates that a holonomic constraint fixes as functions of t (φ = ωt for a rod turned at a constant rate)
 * are put in with it; the Euler–Lagrange equation of q_k (EL − Q, without the constraint forces, which must not
 * act along q_k) must then hold with q_k = F, q̇_k = F', q̈_k = F'' at every t and every value of the text's
 * constants — or to first order in F's terms in t (a small oscillation about where they vanish). Agrees "it
 * solves the equation of motion for $s$"; disagrees with what it leaves (the equation's residual, no correction:
 * a solution is not unique) only when the text's constants in F are coefficients (s_0 cos ωt), not inside a
 * function of t (Ω' and δ in cos(Ω' t − δ) could make it a solution at their right values). False (r untouched) when the link is no such claim or the
 * equation of q_k still holds other coordinates. `stated`: the frequencies the text has stated (ω → √(g/l)), put in
 * first.
 */
bool check_claimed_solution(const GiNaC::ex& left, const GiNaC::ex& right, const Model& model, const Equations& eq,
                            const std::vector<GiNaC::ex>& motion, const LatexContext& ctx, Comparisons& cmp,
                            EquationCheck& r, const GiNaC::exmap& stated = {});

}  // namespace eomgen::checker
