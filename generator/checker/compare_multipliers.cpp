/** @file compare_multipliers.cpp  A link that writes the constraint forces' multipliers (`m\ddot x = 2x\lambda`,
 * `\lambda = -mg\cos\theta/l`): it holds on every motion with the constraints put in, with eomgen's sign of λ or the
 * opposite one kept through the text; a multiplier alone on a side that holds with neither sign is corrected to the
 * one solved from the constrained equations (compare_values.cpp asks first). */
#include "checker/checker_internals.hpp"

namespace eomgen::checker::detail {

bool Checker::check_multipliers(const PSide& L, const PSide& R, const GiNaC::ex& a, const GiNaC::ex& b,
                                const GiNaC::ex& r_ex, double tol, const std::string& within, EquationCheck& r) {
    // With the multipliers, written on the constraints (φ = ωt put in: cos ωt for cos φ, ω for φ̇, φ̈ = 0): it
    // holds at states on them, λ from the constrained equations.
    if (std::any_of(multipliers_.begin(), multipliers_.end(), [&](const GiNaC::symbol& l) { return r_ex.has(l); })) {
        bool holds[2] = {false, false};
        for (int k = 0; k < 2; ++k) {
            const std::optional<bool> h =
                holds_on_constrained_motion(r_ex, model_, eq_, tol, multipliers_, k == 0 ? 1 : -1, numbers_.pinned());
            holds[k] = h && *h;
        }
        if (holds[0] || holds[1]) {
            const int sign = holds[0] ? 1 : -1;
            r.compared_with = "the equations of motion with the constraint forces";
            if (!keeps_multiplier_sign(holds[0], holds[1], r)) {
                // `\lambda = …` alone: corrected to the multiplier with the text's sign.
                for (std::size_t k = 0; k < multipliers_.size() && !has_acceleration(r_ex); ++k) {
                    const PSide* alone =
                        a.is_equal(multipliers_[k]) ? &L : (b.is_equal(multipliers_[k]) ? &R : nullptr);
                    const std::optional<GiNaC::ex> value = alone ? solved_multiplier(model_, eq_, k) : std::nullopt;
                    if (!value || expanded_terms(*value) > kMaxExpandedTerms) continue;
                    const GiNaC::ex shown = GiNaC::normal(*value * multiplier_sign_);
                    r.corrected = alone == &L ? L.side->source + " = " + latex(shown) : latex(shown) + " = " + R.side->source;
                }
                return true;
            }
            r.verdict = Verdict::Agrees;
            r.reason = std::string("it holds on every motion, with the constraints put in (checked at sample states)") +
                       (sign < 0 ? ", the multiplier taken with the opposite sign to eomgen's (M q'' = f + A^T λ)" : "") +
                       within;
            return true;
        }
    }
    // `\lambda = …` (no accelerations) that holds with neither sign: wrong, corrected to the multiplier solved from the
    // constrained equations where it stands alone on a side.
    if (!has_acceleration(r_ex) && !eq_.constraints.empty())
        for (std::size_t k = 0; k < multipliers_.size(); ++k) {
            if (!r_ex.has(multipliers_[k])) continue;
            bool wrong = true;
            for (int sign : {1, -1}) {
                const std::optional<bool> holds =
                    holds_on_constrained_motion(r_ex, model_, eq_, tol, multipliers_, sign, numbers_.pinned());
                wrong = wrong && holds && !*holds;
            }
            if (!wrong) break;
            // `\dot\theta = \sqrt{\frac{g}{r}\cos\theta - \frac{\lambda}{Mr}}`: a root the text takes for the positive
            // rate holds on the motions where that rate is positive; squared, on every one.
            const GiNaC::ex root = GiNaC::pow(GiNaC::wild(0), GiNaC::numeric(1, 2));
            if (a.has(root) || b.has(root) || a.has(1 / root) || b.has(1 / root)) {
                const GiNaC::ex squared = (a * a - b * b).expand();
                // (With the sign of λ the text has taken in this section, where it has taken one.)
                const bool kept = multiplier_sign_ != 0 && r.section == multiplier_sign_section_;
                for (int sign : {1, -1}) {
                    if (kept && sign != multiplier_sign_) continue;
                    const std::optional<bool> holds =
                        holds_on_constrained_motion(squared, model_, eq_, tol, multipliers_, sign, numbers_.pinned());
                    if (!holds || !*holds) continue;
                    r.verdict = Verdict::Agrees;
                    r.compared_with = "the equations of motion with the constraint forces";
                    r.reason = "it holds on every motion, with the constraints put in, after squaring both sides (the "
                               "sign of the root is not checked)" + within;
                    return true;
                }
            }
            r.verdict = Verdict::Disagrees;
            r.compared_with = "the equations of motion with the constraint forces";
            r.reason = "it holds on no motion, with either sign of the multiplier (checked at sample states)";
            const PSide* alone = a.is_equal(multipliers_[k]) ? &L : (b.is_equal(multipliers_[k]) ? &R : nullptr);
            if (const std::optional<GiNaC::ex> value = solved_multiplier(model_, eq_, k); alone && value &&
                                                            expanded_terms(*value) <= kMaxExpandedTerms) {
                GiNaC::ex shown = *value;
                for (int round = 0; round < 3 && !numbers_.pinned().empty(); ++round)
                    shown = subs_unless_pole(shown, numbers_.pinned()).value_or(shown);
                shown = GiNaC::normal(shown);
                r.corrected = alone == &L ? L.side->source + " = " + latex(shown) : latex(shown) + " = " + R.side->source;
                r.wrong_terms = {"the multiplier is $" + latex(shown) + "$ (with eomgen's sign, M q'' = f + A^T λ)"};
            }
            return true;
        }
    return false;
}

}  // namespace eomgen::checker::detail
