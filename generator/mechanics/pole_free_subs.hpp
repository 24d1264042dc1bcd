/** @file pole_free_subs.hpp  Substituting values without dividing by zero inside GiNaC. */
#pragma once

#include <ginac/ginac.h>

#include <optional>

namespace eomgen {

/// Whether e.subs(m) divides by zero: a base of a negative power that the substitution makes zero (looked for
/// innermost first, so that no substitution below divides by zero either).
bool subs_divides_by_zero(const GiNaC::ex& e, const GiNaC::exmap& m, unsigned options = 0);

/// e.subs(m, options), or nothing where that would divide by zero. GiNaC throws then from inside the product it
/// is building and leaks it (found by LeakSanitizer), so the zero denominators are looked for first.
std::optional<GiNaC::ex> subs_unless_pole(const GiNaC::ex& e, const GiNaC::exmap& m, unsigned options = 0);

}  // namespace eomgen
