/** @file expansion_bound.hpp  How many terms a formula expands to, bounded without expanding it: what lets
 * symbolic work driven by user text (the checker's comparisons, the Legendre transform of `show`) refuse a
 * formula that would take minutes instead of starting on it. */
#pragma once

#include <ginac/ginac.h>

namespace eomgen {

/**
 * An upper bound on the number of terms of e.expand() and of GiNaC::normal(e)'s numerator and denominator
 * (and of any expansion inside a function's argument, which expand() also does), computed without expanding:
 * sums add (over a common denominator: a/b + c/d = (ad + cb)/(bd)), products multiply, a sum of k terms to
 * an integer power ±n gives at most C(k + n − 1, n). Saturates at 1e18.
 */
double expanded_terms(const GiNaC::ex& e);

}  // namespace eomgen
