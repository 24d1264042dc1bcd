/** @file equivalent_lagrangian.hpp  A Lagrangian that differs from the model's by a total time derivative: the
 * same Euler–Lagrange equations, so a text that drops such a term (as it says, or silently) is right. */
#pragma once

#include "checker/checker.hpp"
#include "checker/comparisons.hpp"
#include "checker/derivation.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

namespace eomgen::checker {

/**
 * When D = `text_L − model_L` (no accelerations in it) is not 0 but its Euler–Lagrange expressions
 * d/dt ∂D/∂q̇ − ∂D/∂q vanish identically for every coordinate, D is dF(q, t)/dt or a function of t alone. A D
 * free of the coordinates and velocities (a constant: the zero of V; a function of t) agrees; one that holds them
 * agrees where `text_drops_it` (the text says it drops a total time derivative), else r keeps its verdict and
 * gets a note that the line is an equivalent Lagrangian, though not the one it says it is. Returns whether r
 * was set to "agrees".
 */
bool check_equivalent_lagrangian(const GiNaC::ex& text_L, const GiNaC::ex& model_L, const Model& model,
                                 Comparisons& cmp, double tol, bool text_drops_it, EquationCheck& r);

/**
 * When eomgen's L is the text's L plus a part D in coordinates the text's L does not hold (L = L_cm(Ẋ, Ẏ) +
 * L_rel(r, θ, ṙ, θ̇): the centre of mass of a two-body problem), and D holds none of the others, the text writes the
 * Lagrangian of the coordinates it keeps, which give the same equations for them: agrees ("the Lagrangian of $r$,
 * $\theta$ alone: eomgen's L separates, and the part in $X$, $Y$ is left out ($D$)"). Returns whether r was set.
 */
bool check_separated_lagrangian(const GiNaC::ex& text_L, const GiNaC::ex& model_L, const Model& model,
                                Comparisons& cmp, EquationCheck& r);

/// True when the sentences that lead into the math at `offset` (the last three of its paragraph's prose) say that
/// a total time derivative is dropped: "total (time) derivative", "drop", "omit", "discard", "equivalent
/// Lagrangian", "gauge".
bool says_total_derivative_dropped(const Derivation& d, std::size_t offset);

}  // namespace eomgen::checker
