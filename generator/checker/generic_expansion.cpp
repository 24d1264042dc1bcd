/** @file generic_expansion.cpp  A Taylor expansion in a small quantity of the text's own. */
#include "checker/generic_expansion.hpp"
#include "checker/approximation.hpp"
#include "checker/state_symbols.hpp"

#include <algorithm>
#include <string>

namespace eomgen::checker {

bool check_generic_expansion(const GiNaC::ex& a, const GiNaC::ex& b, const std::string& left_source,
                             const std::string& right_source, const std::vector<const FreeName*>& unknown,
                             const Model& model, Comparisons& cmp, EquationCheck& r) {
    if (unknown.empty() || unknown.front()->kind != NameKind::Unknown) return false;
    for (const FreeName* f : unknown)
        if (f->name != unknown.front()->name) return false;
    const GiNaC::symbol& x = unknown.front()->symbol;
    if (holds_state(a, model) || holds_state(b, model) || a.has(model.t) || b.has(model.t)) return false;
    try {
        // The truncation: the side that is a polynomial in x; the function it expands: the other.
        const bool a_poly = a.is_polynomial(x), b_poly = b.is_polynomial(x);
        if (a_poly == b_poly) return false;
        const GiNaC::ex poly = (a_poly ? a : b).expand(), function = a_poly ? b : a;
        // `\cos\alpha \approx 1`: a constant holds to first order, the order such approximations are made to.
        const int order = std::max(1, poly.degree(x));
        if (!function.has(x) || order > 8) return false;
        const GiNaC::ex series = GiNaC::series_to_poly(function.series(x == 0, order + 1)).expand();
        if (series.has(GiNaC::Order(x)) || !series.is_polynomial(x)) return false;
        const std::string name = "$" + unknown.front()->name + "$";
        const std::string about =
            "the Taylor expansion about $" + unknown.front()->name + " = 0$ (a small quantity of the text's own)";
        for (int n = 0; n <= order; ++n) {
            const GiNaC::ex want = series.coeff(x, n), have = poly.coeff(x, n);
            if (cmp.same(want, have, 1e-9)) continue;
            r.compared_with = about;
            r.verdict = Verdict::Disagrees;
            const GiNaC::ex power = GiNaC::pow(x, n);
            r.difference = cmp.latex(((have - want) * power).expand());
            r.wrong_terms = {"the " + (n == 0 ? std::string("constant term") : "$" + cmp.latex(power) + "$ term") +
                             " should be $" + cmp.latex((want * power).expand()) + "$, not $" +
                             cmp.latex((have * power).expand()) + "$"};
            // The series as the author orders a truncation, by rising powers; the expanded side as written.
            std::string truncated;
            for (int m = 0; m <= order; ++m) {
                const GiNaC::ex term = (series.coeff(x, m) * GiNaC::pow(x, m)).expand();
                if (term.is_zero()) continue;
                const std::string t = cmp.latex(term);
                truncated += truncated.empty() ? t : (t.rfind('-', 0) == 0 ? " - " + t.substr(1) : " + " + t);
            }
            if (truncated.empty()) truncated = "0";
            r.corrected = a_poly ? truncated + " \\approx " + right_source : left_source + " \\approx " + truncated;
            return true;
        }
        r.compared_with = about;
        r.verdict = Verdict::Agrees;
        r.reason = "agrees to " + ordinal(order) + " order in " + name;
        return true;
    } catch (const std::exception&) {  // no series there (a pole, a branch point): not such an expansion
        return false;
    }
}

}  // namespace eomgen::checker
