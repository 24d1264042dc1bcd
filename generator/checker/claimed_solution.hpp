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

/// A solution the text claimed for a coordinate, once judged: the rows after it that use its constants (s_0) are
/// read on it (the text puts it back into its equations: "putting s(t) = s_0 cos ωt back into the equation for φ").
struct ClaimedMotion {
    std::size_t coordinate = 0;
    GiNaC::exmap at;  ///< q_k, q̇_k, q̈_k, and the coordinates a holonomic constraint gives as functions of t
    std::vector<GiNaC::ex> constants;  ///< the text's names in it (s_0, A): what rows on it are recognised by
    bool solves = false;               ///< whether it solves the equation of motion (exactly or to first order)
    int line = 0;
    std::string source;                ///< as the text writes it
    std::size_t from = 0, until = 0;   ///< its link's offset, and the end of its section
};

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
                            EquationCheck& r, const GiNaC::exmap& stated = {}, ClaimedMotion* claimed = nullptr);

/// The latest of `claimed` in force at `at` (after its link, in its section) whose constants are every name in `a`
/// and `b` (the names of a row the model does not know); nullptr when there is none, or the row has no such name.
const ClaimedMotion* claimed_motion_at(const std::vector<ClaimedMotion>& claimed, std::size_t at,
                                       const std::vector<const FreeName*>& a, const std::vector<const FreeName*>& b);

/**
 * Judges `a = b` on a motion the text claimed before it (`claimed`: it fills `coordinate`, `at`, `constants` and
 * `solves` of the claim it judges), when the names of the text in a and b are all constants of that motion:
 * q_k, q̇_k, q̈_k and the coordinates the constraints fix are put in, each multiplier in `multipliers` becomes `sign`
 * times the one solved from the constrained equations at that state (sign 0: either sign), and a − b must vanish
 * for every t and every value of the constants. On a motion that solves the equations it agrees or disagrees so;
 * on one that does not, a row that holds on it disagrees all the same — it carries the claim's error — and one
 * that does not hold disagrees twice over. False (r untouched) when the row still holds a coordinate the motion
 * does not fix, or a multiplier cannot be solved for.
 */
bool check_on_claimed_motion(const GiNaC::ex& a, const GiNaC::ex& b, const ClaimedMotion& claimed,
                             const Model& model, const Equations& eq, const std::vector<GiNaC::symbol>& multipliers,
                             int sign, Comparisons& cmp, double tol, EquationCheck& r);

}  // namespace eomgen::checker
