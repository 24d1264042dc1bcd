/** @file claimed_solution.cpp  A claimed solution q_k(t) put into the equation of motion of q_k. */
#include "checker/claimed_solution.hpp"
#include "checker/constrained_motion.hpp"
#include "checker/state_symbols.hpp"

#include "mechanics/pole_free_subs.hpp"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace eomgen::checker {

namespace {

/// Whether e holds a vector or a unit of the text (names that are no scalar constants).
bool has_non_scalar(const GiNaC::ex& e, const LatexContext& ctx) {
    if (const FreeName* f = ctx.free_name_of(e)) return f->kind != NameKind::Unknown;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (has_non_scalar(e.op(i), ctx)) return true;
    return false;
}

/// Whether every name of the text in F appears only to the first power, outside functions (a coefficient).
bool linear_in_its_names(const GiNaC::ex& F, const LatexContext& ctx) {
    std::vector<GiNaC::ex> stack{F};
    while (!stack.empty()) {
        const GiNaC::ex e = stack.back();
        stack.pop_back();
        if (GiNaC::is_a<GiNaC::function>(e) || (GiNaC::is_a<GiNaC::power>(e) && !e.op(1).is_equal(1))) {
            std::vector<GiNaC::ex> inner{e};
            while (!inner.empty()) {
                const GiNaC::ex x = inner.back();
                inner.pop_back();
                if (ctx.free_name_of(x)) return false;
                for (std::size_t i = 0; i < x.nops(); ++i) inner.push_back(x.op(i));
            }
            continue;
        }
        for (std::size_t i = 0; i < e.nops(); ++i) stack.push_back(e.op(i));
    }
    return true;
}

}  // namespace

bool check_claimed_solution(const GiNaC::ex& left, const GiNaC::ex& right, const Model& model, const Equations& eq,
                            const std::vector<GiNaC::ex>& motion, const LatexContext& ctx, Comparisons& cmp,
                            EquationCheck& r, const GiNaC::exmap& stated, ClaimedMotion* claimed) {
    const GiNaC::ex& t = model.t;
    for (const auto& [q, written] : {std::pair(left, right), std::pair(right, left)}) {
        const GiNaC::ex F = stated.empty() ? written : written.subs(stated);
        std::size_t k = model.dof();
        for (std::size_t i = 0; i < model.dof(); ++i)
            if (q.is_equal(model.coordinates[i].q)) k = i;
        if (k == model.dof() || !F.has(t) || holds_state(F, model) || has_non_scalar(F, ctx)) continue;
        // The constraint forces must not act along q_k: its equation holds without the multipliers.
        for (const ConstraintEquations& c : eq.constraints)
            if (!GiNaC::normal(c.jacobian[k]).is_zero()) return false;
        GiNaC::exmap at;
        // Coordinates a holonomic constraint gives as functions of t alone (φ = ωt).
        for (const ConstraintEquations& c : eq.constraints) {
            if (c.position.is_zero() || c.position.has(model.coordinates[k].q)) continue;
            std::size_t j = model.dof(), count = 0;
            for (std::size_t i = 0; i < model.dof(); ++i)
                if (c.position.has(model.coordinates[i].q)) {
                    j = i;
                    ++count;
                }
            if (count != 1) continue;
            const GiNaC::ex& qj = model.coordinates[j].q;
            try {
                const GiNaC::ex g = c.position.expand();
                if (g.degree(qj) != 1) continue;
                const GiNaC::ex sol = GiNaC::normal(-g.coeff(qj, 0) / g.coeff(qj, 1));
                if (holds_state(sol, model)) continue;
                at[qj] = sol;
                at[model.coordinates[j].qd] = GiNaC::diff(sol, GiNaC::ex_to<GiNaC::symbol>(t));
                at[model.coordinates[j].qdd] = GiNaC::diff(sol, GiNaC::ex_to<GiNaC::symbol>(t), 2);
            } catch (...) {
            }
        }
        // F = F0 + ε F1, F1 its terms in t: the residual at ε = 1 (exact), and its value and slope at ε = 0 (a
        // small oscillation θ_0 + A cos(Ω t − δ) about an equilibrium θ_0 holds to first order only).
        const GiNaC::symbol eps("__eps");
        GiNaC::ex residual, first_order;
        try {
            const GiNaC::symbol& ts = GiNaC::ex_to<GiNaC::symbol>(t);
            GiNaC::ex F0 = 0, F1 = 0;
            const GiNaC::ex Fx = F.expand();
            for (const GiNaC::ex& term : GiNaC::is_a<GiNaC::add>(Fx) ? Fx : GiNaC::ex(GiNaC::lst{Fx}))
                (term.has(t) ? F1 : F0) += term;
            const GiNaC::ex Fe = F0 + eps * F1;
            at[model.coordinates[k].q] = Fe;
            at[model.coordinates[k].qd] = GiNaC::diff(Fe, ts);
            at[model.coordinates[k].qdd] = GiNaC::diff(Fe, ts, 2);
            const std::optional<GiNaC::ex> x = subs_unless_pole(motion[k], at);
            if (!x) return false;
            // At ε = 0 a term 1/q of the equation may divide by zero (θ = A cos ωt about θ = 0): no first order then.
            const std::optional<GiNaC::ex> at_one = subs_unless_pole(*x, {{eps, 1}});
            if (!at_one) return false;
            residual = *at_one;
            const std::optional<GiNaC::ex> r0 = subs_unless_pole(*x, {{eps, 0}}),
                                           r1 = subs_unless_pole(GiNaC::diff(*x, eps), {{eps, 0}});
            first_order = r0 && r1 && cmp.same(*r0, 0, 1e-9) && cmp.same(*r1, 0, 1e-9) ? GiNaC::ex(1) : GiNaC::ex(0);
        } catch (...) {
            return false;
        }
        if (holds_state(residual, model)) return false;  // the equation still holds other coordinates
        // What the rows after it that use its constants are read on (check_on_claimed_motion).
        const auto record = [&](bool solves) {
            if (!claimed) return;
            const GiNaC::symbol& ts = GiNaC::ex_to<GiNaC::symbol>(t);
            claimed->coordinate = k;
            claimed->at = at;
            claimed->at[model.coordinates[k].q] = F;
            claimed->at[model.coordinates[k].qd] = GiNaC::diff(F, ts);
            claimed->at[model.coordinates[k].qdd] = GiNaC::diff(F, ts, 2);
            claimed->constants.clear();
            std::vector<GiNaC::ex> stack{F};
            while (!stack.empty()) {
                const GiNaC::ex x = stack.back();
                stack.pop_back();
                if (const FreeName* f = ctx.free_name_of(x); f && f->kind == NameKind::Unknown) {
                    if (std::none_of(claimed->constants.begin(), claimed->constants.end(),
                                     [&](const GiNaC::ex& c) { return c.is_equal(x); }))
                        claimed->constants.push_back(x);
                    continue;
                }
                for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
            }
            claimed->solves = solves;
        };
        const std::string name = "$" + model.coordinates[k].latex + "$";
        const std::string compared = "the equation of motion for " + name +
                                     (at.size() > 3 ? " on the constraints" : "") + ", with this as its solution";
        if (cmp.same(residual, 0, 1e-9)) {
            r.compared_with = compared;
            r.verdict = Verdict::Agrees;
            r.reason = "it solves the equation of motion for " + name + " at every $t$";
            record(true);
            return true;
        }
        if (first_order.is_equal(1)) {
            r.compared_with = compared;
            r.verdict = Verdict::Agrees;
            r.reason = "it solves the equation of motion for " + name +
                       " to first order in its terms in $t$ (a small oscillation about where they vanish), not exactly";
            record(true);
            return true;
        }
        // A name of the text inside a function of t (Ω' in cos(Ω' t − δ), defined later, or a phase) could make it
        // a solution for its right value: only a claim whose names are linear coefficients (s_0 cos ωt, x_0 + v_0 t)
        // is judged wrong.
        if (!linear_in_its_names(F, ctx)) return false;
        GiNaC::ex shown = residual;
        try {
            shown = GiNaC::normal(residual.expand());
        } catch (...) {
        }
        r.compared_with = compared;
        r.verdict = Verdict::Disagrees;
        r.difference = cmp.latex(shown);
        r.wrong_terms = {"put into the equation of motion for " + name + " it leaves $" + cmp.latex(shown) +
                         "$, not 0: it is not a solution"};
        record(false);
        return true;
    }
    return false;
}

const ClaimedMotion* claimed_motion_at(const std::vector<ClaimedMotion>& claimed, std::size_t at,
                                       const std::vector<const FreeName*>& a, const std::vector<const FreeName*>& b) {
    const ClaimedMotion* found = nullptr;
    for (const ClaimedMotion& m : claimed)
        if (m.from < at && at < m.until) found = &m;
    if (!found || (a.empty() && b.empty())) return nullptr;
    for (const auto* names : {&a, &b})
        for (const FreeName* f : *names)
            if (std::none_of(found->constants.begin(), found->constants.end(),
                             [&](const GiNaC::ex& k) { return k.is_equal(f->symbol); }))
                return nullptr;
    return found;
}

bool check_on_claimed_motion(const GiNaC::ex& a, const GiNaC::ex& b, const ClaimedMotion& claimed,
                             const Model& model, const Equations& eq, const std::vector<GiNaC::symbol>& multipliers,
                             int sign, Comparisons& cmp, double tol, EquationCheck& r) {
    // The multipliers at the claimed state: solved from the constrained equations there.
    std::vector<std::pair<GiNaC::symbol, GiNaC::ex>> solved;
    for (std::size_t k = 0; k < multipliers.size(); ++k) {
        if (!(a - b).has(multipliers[k])) continue;
        const std::optional<GiNaC::ex> value = solved_multiplier(model, eq, k);
        if (!value) return false;
        solved.emplace_back(multipliers[k], *value);
    }
    const auto on_motion = [&](int s) -> std::optional<bool> {
        GiNaC::exmap with;
        for (const auto& [l, v] : solved) with[l] = s * v;
        const std::optional<GiNaC::ex> x = subs_unless_pole((a - b).subs(with), claimed.at);
        if (!x || holds_state(*x, model)) return std::nullopt;
        return cmp.same(*x, 0, tol);
    };
    std::optional<bool> holds = on_motion(sign < 0 ? -1 : 1);
    if (holds && !*holds && sign == 0 && !solved.empty()) {
        const std::optional<bool> other = on_motion(-1);
        if (other && *other) holds = other;
    }
    if (!holds) return false;
    const std::string motion = "$" + claimed.source + "$ (line " + std::to_string(claimed.line) + ")";
    r.compared_with = "the motion " + motion + " the text claims, put in";
    if (claimed.solves) {
        r.verdict = *holds ? Verdict::Agrees : Verdict::Disagrees;
        r.reason = *holds ? "it holds on that motion at every $t$ (checked at sample points)"
                          : "it does not hold on that motion (checked at sample points)";
        if (!*holds) r.wrong_terms = {"on the motion " + motion + " the two sides differ"};
        return true;
    }
    r.verdict = Verdict::Disagrees;
    r.wrong_terms = {*holds ? "it follows from " + motion +
                                  ", which is not a motion of the model (it does not solve the equation of motion "
                                  "for $" + model.coordinates[claimed.coordinate].latex + "$): it carries that error"
                            : "it rests on " + motion +
                                  ", which is not a motion of the model, and does not hold on it either"};
    return true;
}

}  // namespace eomgen::checker
