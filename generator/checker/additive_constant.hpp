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

bool check_additive_constant(const GiNaC::ex& a, const GiNaC::ex& b, int constant_side, const Model& model,
                             Comparisons& cmp, double tol, EquationCheck& r);

}  // namespace eomgen::checker
