/** @file equivalent_lagrangian.cpp  L' = L + dF/dt: the same equations of motion. */
#include "checker/equivalent_lagrangian.hpp"

#include "checker/prose.hpp"
#include "mechanics/lagrangian.hpp"

#include <cctype>
#include <string>

namespace eomgen::checker {

bool says_total_derivative_dropped(const Derivation& d, std::size_t offset) {
    const std::string lower = lead_in(d, offset, 3);
    for (const char* cue : {"total derivative", "total time derivative", "total time-derivative", "dropping",
                            "drop ", "dropped", "omit", "discard", "equivalent lagrangian", "gauge"})
        if (lower.find(cue) != std::string::npos) return true;
    return false;
}

bool check_equivalent_lagrangian(const GiNaC::ex& text_L, const GiNaC::ex& model_L, const Model& model,
                                 Comparisons& cmp, double tol, bool text_drops_it, EquationCheck& r) {
    try {
        const GiNaC::ex D = text_L - model_L;
        for (const Coordinate& c : model.coordinates)
            if (D.has(c.qdd)) return false;
        bool of_motion = false;  // after simplification: terms in q and q' may cancel
        for (const Coordinate& c : model.coordinates)
            of_motion = of_motion || !cmp.same(D.diff(c.q), 0, tol) || !cmp.same(D.diff(c.qd), 0, tol);
        for (const Coordinate& c : model.coordinates) {
            const GiNaC::ex el = time_derivative(D.diff(c.qd), model) - D.diff(c.q);
            if (!cmp.same(el, 0, tol)) return false;
        }
        const std::string by = "it differs from eomgen's $L$ by $" + cmp.latex(D) + "$";
        if (of_motion && !text_drops_it) {
            r.notes.push_back("an equivalent Lagrangian (" + by +
                              ", a total time derivative: the same Euler–Lagrange equations), but not the one the "
                              "line says it is");
            return false;
        }
        r.verdict = Verdict::Agrees;
        r.compared_with = "$L$";
        r.difference.clear();
        r.wrong_terms.clear();
        r.corrected.clear();
        r.reason = "an equivalent Lagrangian: " + by +
                   (of_motion ? ", a total time derivative the text drops," : ", a function of $t$ alone (or a constant),") +
                   " which leaves every Euler–Lagrange equation as it is";
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace eomgen::checker
