/** @file additive_constant.cpp  Equal up to a constant, or a constant of the motion. */
#include "checker/additive_constant.hpp"

#include "mechanics/lagrangian.hpp"
#include "mechanics/pole_free_subs.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

namespace eomgen::checker {

bool names_a_constant(const std::string& name) {
    const std::size_t under = name.find('_');
    const std::string base = name.substr(0, under);
    if (base.size() != 1 || !std::isalpha(static_cast<unsigned char>(base[0])) ||
        std::string("TVULHEKPW").find(base[0]) != std::string::npos)
        return false;
    if (under == std::string::npos) return true;
    std::string sub = name.substr(under + 1);
    if (sub.size() >= 2 && sub.front() == '{' && sub.back() == '}') sub = sub.substr(1, sub.size() - 2);
    if (sub.size() == 1) return std::isalnum(static_cast<unsigned char>(sub[0])) != 0;
    return !sub.empty() && std::all_of(sub.begin(), sub.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
}

bool potential_with_another_zero(const GiNaC::ex& text, const GiNaC::ex& truth, const Model& model, Comparisons& cmp,
                                 double tol, EquationCheck& r) {
    const GiNaC::ex diff = text - truth;
    if (cmp.same(diff, 0, tol)) return false;
    GiNaC::exmap rest;  // every coordinate, velocity and acceleration at 0
    for (const Coordinate& q : model.coordinates)
        for (const GiNaC::ex& x : {q.q, q.qd, q.qdd}) {
            if (!cmp.same(GiNaC::diff(diff, GiNaC::ex_to<GiNaC::symbol>(x)), 0, tol)) return false;
            rest[x] = 0;
        }
    if (!cmp.same(GiNaC::diff(diff, GiNaC::ex_to<GiNaC::symbol>(model.t)), 0, tol)) return false;
    GiNaC::ex shown = diff;
    try {
        shown = GiNaC::normal(diff.expand());
    } catch (const std::exception&) {
    }
    // A zero a reader takes for a choice: the text writes no constant term (`U = m g r`), or its V vanishes where
    // the coordinates do (`m g l (1 - \cos\theta)`). A constant term written otherwise (`- h\cos\theta` for
    // `+ h\cos\theta`, θ a fixed tilt) is a slip, harmless to the motion: it still disagrees, and says so.
    GiNaC::ex constant_terms = 0;
    const GiNaC::ex expanded = text.expand();
    for (const GiNaC::ex& term : GiNaC::is_a<GiNaC::add>(expanded) ? expanded : GiNaC::ex(GiNaC::lst{expanded})) {
        bool state = term.has(model.t);
        for (const auto& [x, zero] : rest) state = state || term.has(x);
        if (!state) constant_terms += term;
    }
    const std::optional<GiNaC::ex> at_rest = subs_unless_pole(text, rest);
    if (!cmp.same(constant_terms, 0, tol) && !(at_rest && cmp.same(*at_rest, 0, tol))) {
        r.notes.push_back("the two differ by the constant $" + cmp.latex(shown) +
                          "$ only, which changes no equation of motion");
        return false;
    }
    r.verdict = Verdict::Agrees;
    r.difference.clear();
    r.wrong_terms.clear();
    r.corrected.clear();
    r.reason = "equal to eomgen's $V$ up to the constant $" + cmp.latex(shown) +
               "$: the text takes the zero of the potential energy elsewhere, which changes no equation of motion";
    return true;
}

bool check_additive_constant(const GiNaC::ex& a, const GiNaC::ex& b, int constant_side, const Model& model,
                             Comparisons& cmp, double tol, EquationCheck& r) {
    const GiNaC::ex diff = a - b;
    if (constant_side == 0 || constant_side == 1) {
        const GiNaC::ex rate = time_derivative(diff, model);
        bool accelerations = false;
        for (const Coordinate& c : model.coordinates) accelerations = accelerations || rate.has(c.qdd);
        r.compared_with = "the equations of motion";
        if (cmp.same(rate, 0, tol) || (accelerations && cmp.equation_of_motion(rate, tol))) {
            r.verdict = Verdict::Agrees;
            r.reason = "a constant of the motion: its time derivative vanishes on the equations of motion";
        } else if (cmp.vanishes_on_constrained_motion(rate, tol)) {
            // `a z \dot\varphi = c_0` on the paraboloid ρ² = a z: conserved where the constraints hold.
            r.verdict = Verdict::Agrees;
            r.compared_with = "the equations of motion with the constraint forces";
            r.reason = "a constant of the motion: its time derivative vanishes on the constrained motion (at states on "
                       "the constraints)";
        } else {
            r.reason = "said to be constant, but its time derivative does not vanish on the equations of motion "
                       "(not a constant of this model's motion)";
        }
        return true;
    }
    std::vector<GiNaC::symbol> state{model.t};
    for (const Coordinate& q : model.coordinates) state.insert(state.end(), {q.q, q.qd, q.qdd});
    for (const GiNaC::symbol& x : state)
        if (!cmp.same(GiNaC::diff(diff, x), 0, tol)) return false;
    r.verdict = Verdict::Agrees;
    r.compared_with = "an identity up to an additive constant";
    r.reason = "the two sides differ by a constant, which the text's constant stands for";
    return true;
}

}  // namespace eomgen::checker
