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

bool check_separated_lagrangian(const GiNaC::ex& text_L, const GiNaC::ex& model_L, const Model& model,
                                Comparisons& cmp, EquationCheck& r) {
    try {
        const GiNaC::ex D = (model_L - text_L).expand();
        if (cmp.same(D, 0, 1e-9)) return false;
        std::vector<std::size_t> left_out, kept;
        for (std::size_t k = 0; k < model.dof(); ++k) {
            const Coordinate& c = model.coordinates[k];
            const bool in_D = D.has(c.q) || D.has(c.qd), in_text = text_L.has(c.q) || text_L.has(c.qd);
            if (in_D && in_text) return false;  // coupled through this coordinate
            if (D.has(c.qdd) || text_L.has(c.qdd)) return false;
            (in_D ? left_out : kept).push_back(k);
        }
        if (left_out.empty() || kept.empty() || D.has(model.t)) return false;
        // Coordinates in neither: they must be in neither's equations either (a text may not name a cyclic one).
        for (std::size_t k : kept)
            if (!text_L.has(model.coordinates[k].q) && !text_L.has(model.coordinates[k].qd)) return false;
        auto names = [&](const std::vector<std::size_t>& ks) {
            std::string s;
            for (std::size_t i = 0; i < ks.size(); ++i)
                s += (i ? ", $" : "$") + model.coordinates[ks[i]].latex + "$";
            return s;
        };
        r.verdict = Verdict::Agrees;
        r.compared_with = "$L$";
        r.reason = "the Lagrangian of " + names(kept) + " alone: eomgen's L separates, and the part in " +
                   names(left_out) + " is left out ($" + cmp.latex(D) + "$)";
        r.difference.clear();
        r.wrong_terms.clear();
        r.corrected.clear();
        return true;
    } catch (...) {
        return false;
    }
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
