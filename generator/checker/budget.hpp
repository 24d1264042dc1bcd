/** @file budget.hpp  How much symbolic work a formula from a derivation may cause: every comparison expands,
 * normalizes or squares what the text wrote, so a formula whose expansion is too large is refused up front
 * ("not comparable: too large to compare within the budget") instead of running for minutes. */
#pragma once

#include "mechanics/expansion_bound.hpp"

#include <ginac/ginac.h>

#include <cstddef>

namespace eomgen::checker {

/// The most terms a formula of the text may expand to. Derivations' equations have tens of terms; a side
/// at this size is compared (expanded, normalized, squared) in well under a second.
constexpr double kMaxExpandedTerms = 2000;

/// The bound itself lives with the mechanics (mechanics/expansion_bound.hpp), which uses it too.
using eomgen::expanded_terms;

}  // namespace eomgen::checker
