/** @file indefinite_integral.hpp  Equations with an indefinite integral: `-\int (-2k x_1 + k x_2)\,dx_1 = k x_1^2 -
 * k x_1 x_2 + c` holds when the two sides' derivatives in x_1 agree, whatever constant of integration (c, or any
 * name the text leaves unknown that the derivative removes) stands on the right. */
#pragma once

#include "checker/checker.hpp"
#include "checker/comparisons.hpp"
#include "checker/latex_parser.hpp"

#include <ginac/ginac.h>

#include <vector>

namespace eomgen::checker {

/// Whether e holds an indefinite integral (the parser's antiderivative(f, x)).
bool has_antiderivative(const GiNaC::ex& e);

/**
 * Judges a = b where a or b holds indefinite integrals ∫ f dx, all in one variable x: with each replaced by a symbol
 * A (entering linearly, its coefficient free of x), D = ∂/∂x (a − b) + Σ coefficient · f must vanish. The names in
 * `unknown` (the sides' names that are neither the model's nor the text's) that D no longer holds are constants of
 * integration; one that it still holds makes the link not comparable, as do integrals in two variables, an integral
 * times its own variable or a power of one. Sets r (verdict, compared_with, reason); `same` compares with 0.
 */
void check_antiderivative(const GiNaC::ex& a, const GiNaC::ex& b, const std::vector<const FreeName*>& unknown,
                          Comparisons& cmp, double tol, EquationCheck& r);

}  // namespace eomgen::checker
