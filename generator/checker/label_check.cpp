/** @file label_check.cpp  A display's equation compared with what the sentence before it calls it (labels.cpp
 * reads the name): which quantities an equation states, and a mismatch said with the phrase and its line. */
#include "checker/labels.hpp"

#include <algorithm>
#include <utility>

namespace eomgen::checker {
namespace {

std::string m(const std::string& latex) { return "$" + latex + "$"; }

// ----- what an equation is

struct Identity {
    LabelKind kind;
    std::size_t coordinate = 0;  ///< Momentum
    bool conservation = false;   ///< a − b is a function of the conserved quantity (not a side equal to it)
};

std::string quantity_name(LabelKind kind, std::size_t i, const Model& model) {
    switch (kind) {
        case LabelKind::Energy:
            return "the energy $E = T + V$";
        case LabelKind::Hamiltonian:
            return "the energy function $h$";
        case LabelKind::Kinetic:
            return "the kinetic energy $T$";
        case LabelKind::Potential:
            return "the potential energy $V$";
        case LabelKind::Lagrangian:
            return "the Lagrangian $L$";
        case LabelKind::Momentum:
            return m("p_{" + model.coordinates[i].latex + "}") + ", the momentum conjugate to " +
                   m(model.coordinates[i].latex);
        case LabelKind::EulerLagrange:
            break;
    }
    return "the equation for " + m(model.coordinates[i].latex);
}

/// "the $\theta$ equation", "the $\theta$ or $\phi$ equation".
std::string equations_named(const std::vector<std::size_t>& coordinates, const Model& model, const char* joiner) {
    std::string s;
    for (std::size_t k = 0; k < coordinates.size(); ++k)
        s += (k == 0 ? "" : (k + 1 == coordinates.size() ? joiner : ", ")) + m(model.coordinates[coordinates[k]].latex);
    return "the " + s + " equation" + (coordinates.size() > 1 && std::string(joiner) == " and " ? "s" : "");
}

bool depends_on_state(const GiNaC::ex& e, const Model& model) {
    for (const Coordinate& c : model.coordinates)
        if (e.has(c.q) || e.has(c.qd)) return true;
    return false;
}

/// q = f(C) locally: every partial derivative of q is c times C's, with the same c (q = c C + k for a constant c).
bool function_of(const GiNaC::ex& q, const GiNaC::ex& C, const Model& model, Comparisons& cmp, double tol) {
    std::vector<GiNaC::symbol> state{model.t};
    for (const Coordinate& x : model.coordinates) state.insert(state.end(), {x.q, x.qd});
    std::optional<GiNaC::ex> c;
    for (const GiNaC::symbol& x : state) {
        const GiNaC::ex dC = GiNaC::diff(C, x);
        if (cmp.same(dC, 0, tol)) continue;
        c = GiNaC::normal(GiNaC::diff(q, x) / dC);
        break;
    }
    if (!c || cmp.same(*c, 0, tol)) return false;
    for (const GiNaC::symbol& x : state)
        if (!cmp.same(GiNaC::diff(q, x), *c * GiNaC::diff(C, x), tol)) return false;
    return true;
}

/// What the link a = b (without accelerations, agreeing) is: the quantities a side equals, or the conserved
/// quantity a − b is a function of.
std::vector<Identity> identities(const GiNaC::ex& a, const GiNaC::ex& b, const Model& model, const Equations& eq,
                                 Comparisons& cmp, double tol) {
    std::vector<Identity> out;
    std::vector<std::pair<GiNaC::ex, Identity>> quantities{{eq.T, {LabelKind::Kinetic}},
                                                           {eq.V, {LabelKind::Potential}},
                                                           {eq.L, {LabelKind::Lagrangian}},
                                                           {eq.T + eq.V, {LabelKind::Energy}},
                                                           {eq.energy, {LabelKind::Hamiltonian}}};
    for (std::size_t i = 0; i < eq.momenta.size(); ++i) quantities.push_back({eq.momenta[i], {LabelKind::Momentum, i}});
    for (const GiNaC::ex& side : {a, b}) {
        if (!depends_on_state(side, model)) continue;  // a constant equals any quantity that vanishes
        for (const auto& [value, what] : quantities)
            if (depends_on_state(value, model) && cmp.same(side, value, tol)) out.push_back(what);
    }
    const GiNaC::ex r = (a - b).expand();
    if (!depends_on_state(r, model)) return out;
    for (const ConservedQuantity& c : eq.conserved) {
        if (!function_of(r, c.value, model, cmp, tol)) continue;
        if (cmp.same(c.value, eq.energy, tol)) {
            if (cmp.same(eq.energy, eq.T + eq.V, tol)) out.push_back({LabelKind::Energy, 0, true});  // h = T + V
            out.push_back({LabelKind::Hamiltonian, 0, true});
        }
        for (std::size_t i = 0; i < eq.momenta.size(); ++i)
            if (cmp.same(c.value, eq.momenta[i], tol)) out.push_back({LabelKind::Momentum, i, true});
    }
    return out;
}

bool names(const ProseLabel& l, const Identity& id) {
    if (l.kind == LabelKind::Energy && id.kind == LabelKind::Hamiltonian) return true;  // h is an energy too
    if (l.kind != id.kind) return false;
    if (l.kind != LabelKind::Momentum || l.coordinates.empty()) return true;
    return std::find(l.coordinates.begin(), l.coordinates.end(), id.coordinate) != l.coordinates.end();
}

std::string cited(const ProseLabel& l) { return "\u201C" + l.phrase + "\u201D, line " + std::to_string(l.line); }

void mismatch(const ProseLabel& l, const std::string& labelled, const std::string& is, EquationCheck& r) {
    r.verdict = Verdict::Disagrees;
    r.compared_with = "its label (" + cited(l) + ")";
    r.reason = "the equation holds, but it is not the one its label names";
    r.wrong_terms = {"labelled " + labelled + " (" + cited(l) + "), but it is " + is +
                     ": the label or the equation is wrong"};
    r.difference.clear();
    r.corrected.clear();
}

}  // namespace

void check_label(const ProseLabel& label, const GiNaC::ex& a, const GiNaC::ex& b, const Model& model,
                 const Equations& eq, Comparisons& cmp, double tol, EquationCheck& r) {
    const GiNaC::ex diff = (a - b).expand();
    bool accelerations = false;
    for (const Coordinate& c : model.coordinates) accelerations = accelerations || diff.has(c.qdd);
    if ((label.kind == LabelKind::EulerLagrange) != accelerations) return;  // the other family
    if (!label.unknown.empty()) {
        std::string list;
        for (std::size_t k = 0; k < label.unknown.size(); ++k) list += (k ? ", " : "") + m(label.unknown[k]);
        r.notes.push_back("its label (" + cited(label) + ") names " + list + ", which " +
                          (label.unknown.size() > 1 ? "are no coordinates" : "is no coordinate") +
                          " of the model: the label is not checked");
        return;
    }
    if (label.kind == LabelKind::EulerLagrange && r.verdict == Verdict::Disagrees) {
        // Compared with the equation it is closest to; say so when that is not the one its label names.
        const int closest = cmp.closest_euler_lagrange(diff, tol);
        if (closest >= 0 && std::find(label.coordinates.begin(), label.coordinates.end(), std::size_t(closest)) ==
                                label.coordinates.end())
            r.notes.push_back("its label (" + cited(label) + ") names " +
                              equations_named(label.coordinates, model, " or ") + ", but the equation is closest to " +
                              equations_named({std::size_t(closest)}, model, " and "));
        return;
    }
    if (r.verdict != Verdict::Agrees) return;
    if (label.kind == LabelKind::EulerLagrange) {
        const std::vector<bool> used = cmp.euler_lagrange_terms(diff, tol);
        if (used.empty()) return;
        std::vector<std::size_t> is;
        for (std::size_t i = 0; i < used.size(); ++i)
            if (used[i]) is.push_back(i);
        for (std::size_t k : label.coordinates)
            if (k < used.size() && used[k]) {
                r.notes.push_back("the equation its label names (" + cited(label) + ")");
                return;
            }
        const std::string what =
            is.size() == 1 ? equations_named(is, model, " and ") + " (the Euler–Lagrange equation for " +
                                 m(model.coordinates[is[0]].latex) + ", " + r.reason + ")"
                           : "a combination of " + equations_named(is, model, " and ") +
                                 " (of their Euler–Lagrange equations), without the " +
                                 m(model.coordinates[label.coordinates.front()].latex) + " equation";
        mismatch(label, equations_named(label.coordinates, model, " or "), what, r);
        return;
    }
    const std::vector<Identity> ids = identities(a, b, model, eq, cmp, tol);
    if (ids.empty()) return;
    for (const Identity& id : ids)
        if (names(label, id)) {
            r.notes.push_back("the quantity its label names (" + cited(label) + ")");
            return;
        }
    // "X = const" is the conservation of X more than X itself.
    const Identity& id = *std::min_element(ids.begin(), ids.end(), [](const Identity& x, const Identity& y) {
        return x.conservation > y.conservation;
    });
    const std::string is = (id.conservation ? "the conservation of " : "") + quantity_name(id.kind, id.coordinate, model);
    std::string labelled;
    if (label.kind == LabelKind::Momentum && label.coordinates.empty())
        labelled = "a momentum";
    else if (label.kind == LabelKind::Energy)
        labelled = "the energy";  // E or h
    else if (label.kind == LabelKind::Hamiltonian)
        labelled = "the Hamiltonian $h$";
    else if (label.kind == LabelKind::Momentum)
        labelled = quantity_name(label.kind, label.coordinates.front(), model);
    else
        labelled = quantity_name(label.kind, 0, model);
    mismatch(label, labelled, is, r);
}

}  // namespace eomgen::checker
