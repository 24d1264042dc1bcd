/** @file budget.hpp  How much symbolic work a formula from a derivation may cause: every comparison expands,
 * normalizes or squares what the text wrote, so a formula whose expansion is too large is refused up front
 * ("not comparable: too large to compare within the budget") instead of running for minutes. */
#pragma once

#include <ginac/ginac.h>

#include <cstddef>

namespace eomgen::checker {

/// The most terms a formula of the text may expand to. Derivations' equations have tens of terms; a side
/// at this size is compared (expanded, normalized, squared) in well under a second.
constexpr double kMaxExpandedTerms = 2000;

/**
 * An upper bound on the number of terms of e.expand() and of GiNaC::normal(e)'s numerator and denominator
 * (and of any expansion inside a function's argument, which expand() also does), computed without expanding:
 * sums add (over a common denominator: a/b + c/d = (ad + cb)/(bd)), products multiply, a sum of k terms to
 * an integer power ±n gives at most C(k + n − 1, n). Saturates at 1e18.
 */
double expanded_terms(const GiNaC::ex& e);

}  // namespace eomgen::checker
