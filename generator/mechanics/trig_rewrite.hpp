/** @file trig_rewrite.hpp  Expressions rewritten for people: angle sums, sin² + cos² = 1, like terms
 * collected. */
#pragma once

#include "model/model.hpp"

#include <ginac/ginac.h>

#include <vector>

namespace eomgen::trig {

/// sin(a ± b) = sin a cos b ± cos a sin b and cos(a ± b) = cos a cos b ∓ sin a sin b, applied to every sine
/// and cosine whose argument is a sum, recursively, then expanded: what is left are sines and cosines of
/// the terms of those sums (sin(−θ) = −sin θ). Denominators are left as they are. Equal in value to e.
GiNaC::ex expand_sums(const GiNaC::ex& e);

/// The arguments of e's sines and cosines that are a sum or difference of two terms (θ₁ − θ₂, φ + ψ), each
/// once, in a deterministic (printed) order.
std::vector<GiNaC::ex> angle_sums(const GiNaC::ex& e);

/// The same formulas backwards, for each angle u = a ± b of `angles` in turn: pairs of terms of the expanded
/// e, X cos a cos b and ∓X sin a sin b, become X cos u; X sin a cos b and ±X cos a sin b become X sin u,
/// with u as given (sin(φ − θ) stays sin(φ − θ)). Numerical coefficients may differ: the common part pairs,
/// the rest stays (3 cos a cos b + sin a sin b = cos(a − b) + 2 cos a cos b). Terms that do not pair stay.
GiNaC::ex contract_sums(const GiNaC::ex& e, const std::vector<GiNaC::ex>& angles);

/// sin² x + cos² x = 1, angle by angle: e with cos² x → 1 − sin² x or sin² x → 1 − cos² x (higher even
/// powers alike, cos⁴ x = (1 − sin² x)²), expanded, wherever that lowers the number of terms. So
/// m₁ + m₂ sin² θ + m₂ cos² θ becomes m₁ + m₂, and m R²(cos² θ cos² ωt + cos² θ sin² ωt + sin² θ) becomes
/// m R². Equal in value to e.
GiNaC::ex pythagoras(const GiNaC::ex& e);

/// Like terms collected: terms that differ only in a factor made of `constants` (parameters) and numbers are
/// summed into one, whose coefficient is factored: m₁ l₁² θ̈₁ + m₂ l₁² θ̈₁ becomes (m₁ + m₂) l₁² θ̈₁.
/// Coefficients with denominators are factored over a common one ((I₃ − I)/I); a sum of parameters alone
/// with denominators stays as written (2 g/l − √2 g/l, k/m + 2 k/M). Terms are those of e expanded; the result is not expanded
/// again (expand() undoes it).
GiNaC::ex collect_like_terms(const GiNaC::ex& e, const GiNaC::exset& constants);

/// What to rewrite towards.
struct Hints {
    std::vector<GiNaC::ex> angles;  ///< angle sums the author wrote (angle_sums of their text), tried first
    bool other_angles = true;       ///< also pair sines and cosines into sums no one wrote, where terms fall
    GiNaC::exset constants;         ///< the symbols collect_like_terms may gather into coefficients
    bool collect = true;            ///< collect like terms (off where terms are compared one by one)
};

/// e as a person reads it: sines and cosines of the angle sums of `hints` (then of others, where that
/// shortens e), sin² + cos² = 1 applied, like terms collected with their common factors pulled out. The
/// result never has more terms than e expanded, and equals e in value (every step is an identity).
/// Expressions of more than `max_terms` terms are only collected (the rewriting is quadratic in terms).
GiNaC::ex readable(const GiNaC::ex& e, const Hints& hints, std::size_t max_terms = 400);

/// num/den in lowest terms after both are made readable (GiNaC's normal() cannot see sin² + cos² = 1): the
/// ratio of the same equation's coefficients written two ways is exactly 1.
GiNaC::ex readable_ratio(const GiNaC::ex& num, const GiNaC::ex& den, const Hints& hints);

/// The hints of a model's own text, for `eomgen show` and the report: the angle sums its T, V, bodies and
/// constraints write (cos(θ₁ − θ₂)), its parameters as the constants.
Hints model_hints(const Model& model);

}  // namespace eomgen::trig
