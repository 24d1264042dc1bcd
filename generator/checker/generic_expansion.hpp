/** @file generic_expansion.hpp  A Taylor expansion in a small quantity of the text's own (`\cos\alpha \approx 1 -
 * \frac{\alpha^2}{2}`, `(1 + x)^{-1/2} \approx 1 - x/2`): no quantity of the model, a truncated series all the same. */
#pragma once

#include "checker/comparisons.hpp"
#include "checker/latex_parser.hpp"
#include "checker/verdict.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <vector>

namespace eomgen::checker {

/**
 * Judges `a ≈ b` as a Taylor expansion about x = 0 when the names in a and b that the model does not know are one
 * scalar x, neither side holds a coordinate, a velocity or t, one side is a polynomial in x of degree k (the
 * text's truncation) and the other is not (x inside a function, a root or a denominator): a − b must vanish to
 * order k in x (to first order for a constant, `\cos\alpha \approx 1`), for every value of the parameters. Agrees "to second order in $\alpha$"; disagrees at the lowest
 * order at which the coefficients differ, with that term of the series and the truncation corrected (by rising
 * powers; the other side as the text writes it, `left_source` or `right_source`). False (r
 * untouched) when the row is no such expansion.
 */
bool check_generic_expansion(const GiNaC::ex& a, const GiNaC::ex& b, const std::string& left_source,
                             const std::string& right_source, const std::vector<const FreeName*>& unknown,
                             const Model& model, Comparisons& cmp, EquationCheck& r);

}  // namespace eomgen::checker
