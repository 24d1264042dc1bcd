/** @file additive_constant.hpp  Equations with an arbitrary constant: `V = -m g l \cos\theta + \text{const}` (equal
 * up to a constant) and `p_\phi = m l^2 \sin^2\theta\,\dot\phi = \text{const}` (a constant of the motion). */
#pragma once

#include "checker/checker.hpp"
#include "checker/comparisons.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <string>

namespace eomgen::checker {

/**
 * Judges a = b where the text's constant (latex_normalize.hpp's is_constant_name) was set to 0 in a and b.
 * When one side was the constant alone (`constant_side` 0 or 1), the other is claimed conserved: it agrees
 * when d/dt (a − b) vanishes on the equations of motion, else it is not comparable, saying so. Otherwise it
 * agrees when a − b is free of q, q̇, q̈ and t. Returns false (r untouched) when neither holds: the caller
 * compares a and b as they are.
 */
/// A name that can be an additive constant the text adds to V, L or h (`+ f`, `+ C_0`): one letter that names no
/// energy or its part (not T, V, U, L, H, E, K, P, W: `T_{rot}` is a part of T), with a subscript of digits or one
/// letter at most.
bool names_a_constant(const std::string& name);

/**
 * `U = m g r` where eomgen's V is −m g (l − r), `V = m g l (1 - \cos\theta)`: a potential energy whose zero the text
 * takes elsewhere. After a comparison of the text's `text` with eomgen's V (`truth`) that disagreed: true (r set to
 * agree, the constant said) when text − truth is a constant (free of q, q̇, q̈ and t, not 0) and the text writes no
 * constant term or its V vanishes where the coordinates do; false otherwise (r untouched, but for a note when the
 * two differ by a constant all the same: a constant term written wrong, harmless to the motion).
 */
bool potential_with_another_zero(const GiNaC::ex& text, const GiNaC::ex& truth, const Model& model, Comparisons& cmp,
                                 double tol, EquationCheck& r);

bool check_additive_constant(const GiNaC::ex& a, const GiNaC::ex& b, int constant_side, const Model& model,
                             Comparisons& cmp, double tol, EquationCheck& r);

}  // namespace eomgen::checker
