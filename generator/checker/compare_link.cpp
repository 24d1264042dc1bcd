/** @file compare_link.cpp  One link a = b judged: its role, the comparisons (compare_values.cpp) and the
 * corrections checked before they are printed. */
#include "checker/checker_internals.hpp"
#include "checker/generic_expansion.hpp"
#include "checker/indefinite_integral.hpp"

namespace eomgen::checker::detail {

EquationCheck Checker::check_link(const FullChain& c, std::size_t i, std::size_t j, bool bridge) {
    EquationCheck r;
    const PSide& L = c.sides[i];
    const PSide& R = c.sides[j];
    const std::size_t rel_at = c.relation_offsets[j - 1];
    r.where = d_.position(bridge ? c.relation_offsets[i] : rel_at);
    hints_.angles = trig::angle_sums((L.side->ok ? L.side->value : 0) + (R.side->ok ? R.side->value : 0));
    if (c.section >= 0) r.section = d_.sections[std::size_t(c.section)].title;
    Relation rel = Relation::Equal;
    for (std::size_t q = i; q < j; ++q)
        if (c.relations[q] != Relation::Equal) rel = c.relations[q];
    const std::string sign = rel == Relation::Approx       ? " \\approx "
                             : rel == Relation::Inequality ? " \\;?\\; "
                             : rel == Relation::NotEqual   ? " \\neq "
                                                           : " = ";
    r.equation = (L.side->source.empty() ? std::string("\\ldots") : L.side->source) + sign +
                 (R.side->source.empty() ? std::string("\\ldots") : R.side->source);
    if (bridge) r.notes.push_back("compared across the step(s) between them that cannot be compared");
    if (discourse_->sets_trial(rel_at) && j == i + 1) {
        const ExponentialTrial* e = discourse_->exponential_at(rel_at + 1);
        not_judged(r, Role::Trial,
                   e && e->from == rel_at
                       ? "a trial solution: not judged; the equation for its exponent that follows is compared with the "
                         "characteristic equation $\\det(\\lambda^2 M_0 + \\lambda C_0 + K_0) = 0$ about rest"
                       : "a trial solution: not judged; the equations for its amplitudes that follow are compared with "
                         "the rows of $(K - \\omega^2 M) A = 0$ about rest");
        return r;
    }
    // `r = r_{eq} + \rho`: the text's new name for the deviation from a point (change_of_variable.cpp).
    if (const auto change = variable_change_rows_.find(rel_at); change != variable_change_rows_.end() && j == i + 1) {
        not_judged(r, Role::Definition, change->second);
        return r;
    }
    // `q = r, \theta` ("for q = r, θ" after the Euler–Lagrange equation of a generic q): the name stands for each
    // of the model's coordinates listed.
    if (j == i + 1 && L.side->ok && !R.side->ok && GiNaC::is_a<GiNaC::symbol>(L.side->value)) {
        const FreeName* f = ctx_.free_name_of(L.side->value);
        std::vector<std::string> listed;
        std::string piece;
        const auto coordinate = [&](const std::string& p) {
            const auto it = ctx_.names.find(canonical_name(p));
            return it != ctx_.names.end() &&
                   std::any_of(model_.coordinates.begin(), model_.coordinates.end(),
                               [&](const Coordinate& q) { return it->second.is_equal(q.q); });
        };
        bool all = f && f->kind == NameKind::Unknown;
        for (const char ch : R.side->source + ",") {
            if (ch != ',') {
                piece += ch;
                continue;
            }
            piece = trimmed(piece);
            all = all && coordinate(piece);
            listed.push_back(piece);
            piece.clear();
        }
        if (all && listed.size() >= 2) {
            std::string names;
            for (std::size_t k = 0; k < listed.size(); ++k) names += (k ? ", " : "") + std::string("$") + listed[k] + "$";
            not_judged(r, Role::Definition,
                       "a definition: the text's $" + f->name + "$ stands for each of " + names + " in turn");
            return r;
        }
    }
    if (const Discourse::Naming* n = discourse_->naming_at(rel_at); n && j == i + 1) {
        not_judged(r, Role::Definition,
                   "a definition: the text names $" + n->quantity_latex + "$ $" + n->letter_latex +
                       "$ here, and reads so to the end of its section (outside ∂/∂, where $" + n->letter_latex +
                       "$ is still eomgen's)");
        return r;
    }
    if (rel == Relation::Inequality || rel == Relation::NotEqual) {
        // `\gamma < 0`, `0 \le \theta < \pi`, `g > 0`: one name against a number is the range or sign of a
        // quantity the text considers (a convention, an assumption, the case at hand), not a result.
        for (int side = 0; side < 2; ++side) {
            const PSide& N = side == 0 ? L : R;
            const PSide& O = side == 0 ? R : L;
            if (N.side->ok && O.side->ok && GiNaC::is_a<GiNaC::symbol>(N.side->value) &&
                GiNaC::is_a<GiNaC::numeric>(GiNaC::evalf(O.side->value))) {  // 0, 2, \pi, \pi/2
                not_judged(r, Role::Condition,
                           "a condition: the range or sign of $" + N.side->source +
                               "$ the text considers (a convention or an assumption, not a result)");
                return r;
            }
        }
        if (rel == Relation::NotEqual) {
            check_not_equal(L, R, r);
            return r;
        }
        r.reason = "an inequality or a relation other than equality is not compared";
        return r;
    }
    // A parameter the text set for this paragraph (`m_1 = 0`), an assumption (`m_1 = m_2`), a condition: both the text
    // and eomgen's quantities take it, in every comparison below (the matrices' and the modes' too).
    GiNaC::exmap chosen;
    chosen_notes_.clear();
    for (std::size_t k = 0; k < model_.parameters.size(); ++k)
        if (const auto [v, origin] = parameter_values_.at(k, rel_at); origin.rfind("chosen by the text", 0) == 0) {
            chosen[model_.parameters[k].symbol] = exact_decimal(v);
            chosen_notes_.push_back("with $" + (model_.parameters[k].latex.empty() ? model_.parameters[k].name
                                                                                : model_.parameters[k].latex) +
                                    " = " + latex(exact_decimal(v)) + "$, the value the text chose on line " +
                                    origin.substr(origin.rfind(' ') + 1));
        }
    for (const auto& [symbol, stated] : discourse_->conditions_at(rel_at)) {
        chosen[symbol] = stated.first;
        const bool parameter = std::any_of(model_.parameters.begin(), model_.parameters.end(),
                                           [&](const Parameter& p) { return symbol.is_equal(p.symbol); });
        if (discourse_->limit_at(symbol, rel_at))
            chosen_notes_.push_back("in the limit $" + latex(symbol) + " \\to " + latex(stated.first) +
                                    "$ the text takes on line " + std::to_string(stated.second) +
                                    ": the model's equations there, with that value put in");
        else
        chosen_notes_.push_back(parameter ? "with $" + latex(symbol) + " = " + latex(stated.first) +
                                                "$, as the text assumes on line " + std::to_string(stated.second)
                                          : "at $" + latex(symbol) + " = " + latex(stated.first) +
                                                "$, the condition the text states on line " + std::to_string(stated.second));
    }
    struct Unpin {
        Numbers& n;
        ~Unpin() { n.pin({}); }
    } const unpin{numbers_};
    numbers_.pin(chosen);
    // "Let $\omega_c^2 = g/R$": a frequency the text introduces by name is its definition, not a claim about the
    // normal modes.
    const bool introduced = rel == Relation::Equal && !definitions_.defined_at(L.base + L.side->begin).empty() &&
                            introduces_name(d_, L.base + L.side->begin);
    if (rel == Relation::Equal && !introduced &&
        modes_.check(with_common_values(*L.side, L.base + L.side->begin),
                     with_common_values(*R.side, R.base + R.side->begin), ctx_, *this, r))
        return r;
    if (!both_signs_ && (two_equations_in_one(*L.side) || two_equations_in_one(*R.side)))
        return check_both_signs(c, i, j, bridge);
    // `\vec{r}_m = (x + l\sin\theta)\hat{x} - l\cos\theta\,\hat{y}`: a point the model gives (point_positions.cpp).
    if (rel == Relation::Equal && check_position(c, j, true, r)) return r;
    if (rel == Relation::Equal && algebra_.check(*L.side, L.base, *R.side, R.base, *this, r)) return r;
    // A part of T or V defined by this link: compare it with its share of eomgen's T or V.
    for (int side = 0; side < 2; ++side) {
        const PSide& P = side == 0 ? L : R;
        const PSide& O = side == 0 ? R : L;
        if (!P.side->ok || !is_part(P.side->value)) continue;
        const GiNaC::ex part = P.side->value;
        Prepared o = prepare(O, &part);
        if (!o.ok) {
            r.reason = o.problem;
            return r;
        }
        if (o.value.has(part)) break;  // T_{a} = T_{a}: an identity, handled below
        if (!o.comparable() || !o.units.empty()) break;
        const double tol = std::max(1e-9, L.side->rounding + R.side->rounding);
        r.notes.insert(r.notes.end(), o.notes.begin(), o.notes.end());
        check_part(part, P.side->source, o, tol, r);
        return r;
    }
    Prepared a = prepare(L), b = prepare(R);
    if (!a.ok || !b.ok) {
        r.reason = !a.ok ? a.problem : b.problem;
        return r;
    }
    // A name an assumption gives the parameters' common value (`m_1 = m_2 = m`) is known in its paragraph.
    for (Prepared* p : {&a, &b})
        p->unknown.erase(std::remove_if(p->unknown.begin(), p->unknown.end(),
                                        [&](const FreeName* f) {
                                            return std::any_of(chosen.begin(), chosen.end(), [&](const auto& kv) {
                                                return kv.second.is_equal(f->symbol);
                                            });
                                        }),
                         p->unknown.end());
    for (const Prepared* p : {&a, &b}) r.notes.insert(r.notes.end(), p->notes.begin(), p->notes.end());
    std::sort(r.notes.begin(), r.notes.end());
    r.notes.erase(std::unique(r.notes.begin(), r.notes.end()), r.notes.end());
    // Comparing the sides takes their difference and their ratio over a common denominator.
    if (const double terms = expanded_terms(a.value - b.value); terms > kMaxExpandedTerms) {
        std::ostringstream os;
        os << "too large to compare within the budget: the two sides over a common denominator expand to up to "
           << std::setprecision(3) << terms << " terms (at most " << static_cast<long>(kMaxExpandedTerms) << ")";
        r.reason = os.str();
        return r;
    }
    // `\cos\alpha \approx 1 - \frac{\alpha^2}{2}`: a series in a small quantity the model does not know.
    if (rel == Relation::Approx && a.vectors.empty() && b.vectors.empty() && a.units.empty() && b.units.empty()) {
        std::vector<const FreeName*> unknown = a.unknown;
        unknown.insert(unknown.end(), b.unknown.begin(), b.unknown.end());
        if (check_generic_expansion(a.value, b.value, L.side->source, R.side->source, unknown, model_, *this, r))
            return r;
    }
    double tol = std::max(1e-9, L.side->rounding + R.side->rounding);
    if (rel == Relation::Approx) tol = std::max(tol, 1e-2);
    if (up_to_constant(a, b, tol, r)) return r;
    if (has_antiderivative(a.value) || has_antiderivative(b.value)) {
        std::vector<const FreeName*> unknown = a.unknown;
        unknown.insert(unknown.end(), b.unknown.begin(), b.unknown.end());
        check_antiderivative(a.value, b.value, unknown, *this, tol, r);
        return r;
    }
    // `\frac{3}{2} \ddot x (R-r)\dot\theta + g x \dot\theta = 0`: an equation of motion times a velocity (the time
    // derivative of an energy, before the text cancels the velocity) holds where that equation does.
    std::string divided;
    if (a.comparable() && b.comparable() && has_acceleration(a.value - b.value) &&
        equal(a.value, b.value, tol) != Tri::Yes) {
        const GiNaC::ex whole = (a.value - b.value).expand();
        for (const Coordinate& q : model_.coordinates) {
            try {
                if (!whole.has(q.qd) || !whole.subs(q.qd == 0).is_zero()) continue;
                const GiNaC::ex rest = (whole / q.qd).expand();
                if (!has_acceleration(rest)) continue;
                a.value = rest;
                b.value = 0;
                divided = "read as " + m("\\dot{" + q.latex + "}") + " times an equation, which is compared";
                break;
            } catch (const std::exception&) {  // a pole at q' = 0: not such a product
            }
        }
    }
    // \approx, \simeq: the Taylor expansion to the order the text keeps; "= ... for small θ" too, where it
    // would otherwise disagree.
    if (!divided.empty()) r.notes.push_back(divided);
    const bool approx = rel == Relation::Approx;
    if (approx && approximation(rel_at, L.side->source, R.side->source, a, b, true, r)) return r;
    check_values(c, i, j, a, b, tol, r);
    // `K = K_{cm} + K_{p}` with a part's value wrong where the text gives it: that line is the slip, not the split
    // (with every part right, a split that misses a part is the slip, and disagrees).
    if (r.verdict == Verdict::Disagrees && (a_part_is_wrong(L, tol) || a_part_is_wrong(R, tol)) &&
        names_parts(L, R, r, true)) {
        r.difference.clear();
        r.wrong_terms.clear();
        r.corrected.clear();
        return r;
    }
    if (r.verdict == Verdict::Disagrees && r.compared_with == "$L$") {  // L + dF/dt: the same equations
        EquationCheck alt;
        alt.where = r.where;
        alt.section = r.section;
        alt.equation = r.equation;
        alt.notes = r.notes;
        if (check_equivalent_lagrangian(a.value, b.value, model_, *this, tol,
                                        says_total_derivative_dropped(d_, rel_at), alt))
            return alt;
        r.notes = alt.notes;
        // L = L_cm + L_rel: the text's L of the coordinates it keeps (a two-body problem's relative motion).
        const bool a_is_L = equal(a.value, eq_.L, 1e-9) == Tri::Yes, b_is_L = equal(b.value, eq_.L, 1e-9) == Tri::Yes;
        if (a_is_L != b_is_L &&
            check_separated_lagrangian(a_is_L ? b.value : a.value, eq_.L, model_, *this, alt))
            return alt;
    }
    // `U = mgr` where eomgen's V = −m g (l − r): the same potential, its zero elsewhere.
    if (r.verdict == Verdict::Disagrees && r.compared_with == "$V$" && !approx && a.has_truth_label != b.has_truth_label)
        potential_with_another_zero(a.has_truth_label ? b.value : a.value, a.has_truth_label ? a.value : b.value, model_,
                                    *this, tol, r);
    // ∂H/∂θ after the text wrote H in velocities: the reading it set up (at fixed θ̇) when Hamilton's disagrees.
    if (r.verdict == Verdict::Disagrees && velocity_h_line_ > 0 && rel_at > velocity_h_at_ &&
        (hamilton_.has_hamiltonian(L.side->value) || hamilton_.has_hamiltonian(R.side->value))) {
        hamilton_.set_velocity_reading(true);
        Prepared va = prepare(L), vb = prepare(R);
        EquationCheck alt;
        alt.where = r.where;
        alt.section = r.section;
        alt.equation = r.equation;
        if (va.ok && vb.ok) check_values(c, i, j, va, vb, tol, alt);
        hamilton_.set_velocity_reading(false);
        if (alt.verdict == Verdict::Agrees) {
            alt.notes.push_back("read as the text set it up: H written in velocities (line " +
                                std::to_string(velocity_h_line_) +
                                ") and differentiated at fixed velocities; Hamilton's equations take ∂H/∂q at "
                                "fixed momenta, under which this line does not hold");
            return alt;
        }
    }
    // (Not comparable as it stands, `\sin(\varphi) = \varphi` after "approximating": the approximation, where it holds.)
    const bool as_written = r.verdict == Verdict::NotComparable && a.comparable() && b.comparable();
    if (!approx && (r.verdict == Verdict::Disagrees || as_written)) {
        EquationCheck alt;
        alt.where = r.where;
        alt.section = r.section;
        alt.equation = r.equation;
        if (!divided.empty()) alt.notes.push_back(divided);
        // Its verdict stands, agreeing or not, where the text says it approximates: it calls the coordinates small
        // ("linearizing", "for small θ"), or writes the deviation from the point of a change of variable.
        if (approximation(rel_at, L.side->source, R.side->source, a, b, false, alt) &&
            (alt.verdict == Verdict::Agrees || (!as_written && approximation_stated(c, i, j))))
            return alt;
    }
    return r;
}

bool Checker::approximation_stated(const FullChain& c, std::size_t i, std::size_t j) const {
    const std::size_t at = c.relation_offsets[j - 1];
    const ExpansionPoints points = expansion_points(at);
    if (!small_coordinates_in_prose(d_, at, model_, points).empty()) return true;
    // "… makes small oscillations" (or "approximating $\sin\varphi = \varphi$") before it in the text.
    if (small_motion_stated_before(d_, at)) return true;
    for (const std::size_t k : {i, j})
        for (const NameUse& u : c.sides[k].side->uses)
            for (const std::string& deviation : points.deviation)
                if (!deviation.empty() && u.name.find(deviation) != std::string::npos) return true;
    return false;
}

bool Checker::approximation(std::size_t at, const std::string& left, const std::string& right, const Prepared& a,
                            const Prepared& b, bool implied, EquationCheck& r) {
    if (!a.comparable() || !b.comparable() || !a.units.empty() || !b.units.empty()) return false;
    const int ref_side = a.has_truth_label && !a.has_part ? 0 : (b.has_truth_label && !b.has_part ? 1 : -1);
    const ExpansionPoints points = expansion_points(at);
    // `V \approx \frac12 m g l(2\theta_1^2 + \theta_2^2) + \text{const}`: up to an additive constant, each side
    // less its value at the point of the expansion.
    if (a.constants.empty() && b.constants.empty())
        return check_approximation(d_, model_, motion_, at, {left, right}, a.value, b.value, ref_side, implied, *this,
                                   r, points);
    GiNaC::exmap zero, there;
    for (const Prepared* p : {&a, &b})
        for (const GiNaC::ex& k : p->constants) zero[k] = 0;
    for (std::size_t k = 0; k < model_.dof(); ++k) {
        there[model_.coordinates[k].q] = points.point(k);
        there[model_.coordinates[k].qd] = 0;
        there[model_.coordinates[k].qdd] = 0;
    }
    const GiNaC::ex x = a.value.subs(zero), y = b.value.subs(zero);
    const bool done = check_approximation(d_, model_, motion_, at, {left, right}, x - x.subs(there),
                                          y - y.subs(there), ref_side, implied, *this, r, points);
    if (done) r.notes.push_back("compared up to the text's additive constant");
    return done;
}

EquationCheck Checker::check_parsed_link(const FullChain& like, std::size_t at, const Chain& ch, std::size_t a,
                                         std::size_t b) {
    FullChain f;
    f.section = like.section;
    f.display = like.display;
    for (const Side& s : ch.sides) f.sides.push_back({&s, at});
    f.relations = ch.relations;
    // Where the slip is: what holds there (definitions, conditions, a trial solution) holds for the correction.
    f.relation_offsets.assign(ch.relation_offsets.size(), at);
    return safe_check_link(f, a, b, false);
}

void Checker::verify_correction(const FullChain& c, std::size_t j, EquationCheck& r) {
    const std::size_t at = c.relation_offsets[j - 1];
    const auto saved_names = ctx_.names;
    const auto saved_free = ctx_.free_names;
    verifying_ = true;
    apply_map(d_.position(at).line);
    std::string why;
    try {
        why = correction_problem(r.corrected, ctx_, [&](const Chain& ch, std::size_t a, std::size_t b) {
            return check_parsed_link(c, at, ch, a, b);
        });
    } catch (const std::exception& e) {
        why = std::string("it could not be checked: ") + e.what();
    }
    verifying_ = false;
    ctx_.names = saved_names;
    ctx_.free_names = saved_free;
    if (why.empty()) return;
    r.notes.push_back("no correction is printed: the one computed does not check (" + why + ")");
    r.corrected.clear();
}

bool Checker::is_share_of(const GiNaC::ex& value, const GiNaC::ex& whole, double tol) {
    std::vector<GiNaC::ex> wt, pt;
    const GiNaC::ex we = whole.expand(), pe = value.expand();
    if (GiNaC::is_a<GiNaC::add>(we))
        for (const GiNaC::ex& t : we) wt.push_back(t);
    else
        wt.push_back(we);
    if (GiNaC::is_a<GiNaC::add>(pe))
        for (const GiNaC::ex& t : pe) pt.push_back(t);
    else
        pt.push_back(pe);
    bool subset = !pe.is_zero();
    std::vector<bool> used(wt.size(), false);
    for (const GiNaC::ex& t : pt) {
        bool found = false;
        for (std::size_t k = 0; k < wt.size() && !found; ++k)
            if (!used[k] && same_signature(signature(t), signature(wt[k]), tol)) found = used[k] = true;
        subset = subset && found;
    }
    return subset;
}

bool Checker::a_part_is_wrong(const PSide& s, double tol) {
    if (!s.side->ok || !GiNaC::is_a<GiNaC::add>(s.side->value)) return false;
    for (const GiNaC::ex& part : s.side->value) {
        GiNaC::ex whole;
        const auto value = part_value_.find(part);
        if (is_part(part, nullptr, &whole) && value != part_value_.end() && !is_share_of(value->second, whole, tol))
            return true;
    }
    return false;
}

void Checker::check_part(const GiNaC::ex& part, const std::string& part_source, const Prepared& other,
                         double tol, EquationCheck& r) {
    std::string name;
    GiNaC::ex whole;
    is_part(part, &name, &whole);
    const std::string whole_name = name.substr(0, 1);
    r.compared_with = m(name) + ", a part of " + m(whole_name);
    // Its terms are terms of T (or V): then it is a part of it.
    if (is_share_of(other.value, whole, tol)) {
        r.verdict = Verdict::Agrees;
        r.reason = "its terms are terms of eomgen's " + m(whole_name);
        return;
    }
    // Otherwise it should be T minus the other parts the text defines.
    GiNaC::ex others = 0;
    std::vector<std::string> names;
    for (const auto& [sym, value] : part_value_) {
        std::string n2;
        GiNaC::ex w2;
        if (sym.is_equal(part) || !is_part(sym, &n2, &w2) || n2[0] != name[0]) continue;
        others += value;
        names.push_back(m(n2) + " (" + part_origin_.at(sym) + ")");
    }
    std::sort(names.begin(), names.end());
    GiNaC::ex expected;
    if (!names.empty()) {
        expected = whole - others;
        std::string list;
        for (std::size_t k = 0; k < names.size(); ++k) list += (k ? ", " : "") + names[k];
        if (equal(other.value, expected, tol) == Tri::Yes) {
            r.verdict = Verdict::Agrees;
            r.reason = "it is eomgen's " + m(whole_name) + " minus the text's other parts: " + list;
            return;
        }
        r.notes.push_back("compared with eomgen's " + m(whole_name) +
                          " minus the text's other parts: " + list);
    } else {
        // No other parts: its share of T is the terms of T of the same kinds (velocity monomials).
        expected = 0;
        for (const Group& g : groups(whole))
            for (const Group& h : groups(other.value))
                if (g.monomial.is_equal(h.monomial)) expected += g.coefficient * g.monomial;
        r.notes.push_back("compared with the terms of eomgen's " + m(whole_name) + " of the same kinds");
    }
    r.verdict = Verdict::Disagrees;
    const Diagnosis dg = compare_to(other.value, expected, tol);
    r.difference = dg.difference;
    r.wrong_terms = dg.lines;
    r.corrected = part_source + " = " + latex(expected);
}

EquationCheck Checker::safe_check_link(const FullChain& c, std::size_t i, std::size_t j, bool bridge) {
    try {
        EquationCheck r = check_link(c, i, j, bridge);
        if (i == 0 && r.verdict == Verdict::Disagrees && !verifying_) {
            const std::size_t at = c.relation_offsets[j - 1];
            for (const TextMeaning& m : meanings_)
                if (at >= m.begin && at < m.end) {
                    EquationCheck n;
                    n.where = r.where;
                    n.section = r.section;
                    n.equation = r.equation;
                    not_judged(n, Role::Definition,
                               "a definition: the text's $" + m.name + "$ is the " + m.noun +
                                   " here, not eomgen's $" + m.name + "$; read so from line " +
                                   std::to_string(m.line + 1) + " to the end of its section");
                    return n;
                }
        }
        // (A label of eomgen's — V, T, L, p_θ — set to an expression in the state is a claim about it, whatever
        // the sentence's cue; set to a number, `T = 1` "the unit of time", it is the text's other meaning. The
        // amplitudes of a trial solution are not values the text sets either: `A_1 = A_2` "with ω² = 3k/m" is the
        // mode's shape, a claim.)
        const auto label_claim = [&](std::size_t label, std::size_t other) {
            return truth_.count(c.sides[label].side->value) && depends_on_state(prepare(c.sides[other]).value);
        };
        const auto amplitudes = [&] {
            const TrialSolution* t = discourse_->trial_at(c.relation_offsets[j - 1]);
            if (!t) return false;
            for (const GiNaC::ex& a : t->amplitude)
                if (!a.is_zero() && (c.sides[i].side->value.has(a) || c.sides[j].side->value.has(a))) return true;
            return false;
        };
        // (A point's coordinate at a point the text considers, which the model's point contradicts, is a claim too.)
        const auto position_there = [&] {
            const auto p = positions_.find(c.relation_offsets[j - 1]);
            return p != positions_.end() && p->second.disagrees;
        };
        if (r.verdict == Verdict::Disagrees && !verifying_ && c.sides[i].side->ok && c.sides[j].side->ok &&
            !label_claim(i, j) && !label_claim(j, i) && !amplitudes() && !position_there() &&
            sets_a_value(c.sides[i].side->value, c.sides[j].side->value, model_) &&
            !defined_quantity(c.sides[i]) && !defined_quantity(c.sides[j]) && !after_implication(c)) {
            // "started with θ̇ = 0", "with m₁ = m₂ = m": values set for what follows, not an equation of motion.
            const std::string cue = condition_cue(d_, c.relation_offsets[j - 1]);
            if (!cue.empty()) {
                EquationCheck n;
                n.where = r.where;
                n.section = r.section;
                n.equation = r.equation;
                not_judged(n, Role::Condition,
                           "a condition or a given value (after “" + cue +
                               "”): it sets a value for what follows, not an equation of motion, and is not judged");
                return n;
            }
        }
        if (r.verdict == Verdict::Disagrees && !verifying_) {
            blame_definition(c, i, j, r);
            note_disagreeing_uses(c, i, j, r);
        }
        if (r.verdict == Verdict::Disagrees && !verifying_ && !solved_corrections_.count({r.where.line, r.where.column}) &&
            correct_in_authors_form(c, i, j, r)) {
            // checked as it was found
        } else if (!r.corrected.empty() && !verifying_ && !solved_corrections_.count({r.where.line, r.where.column})) {
            verify_correction(c, j, r);
        }
        if (!verifying_ && c.display) check_prose_label(c, i, j, r);
        return r;
    } catch (const std::exception& e) {
        EquationCheck r;
        r.where = d_.position(c.relation_offsets[j - 1]);
        if (c.section >= 0) r.section = d_.sections[std::size_t(c.section)].title;
        r.equation = c.sides[i].side->source + " = " + c.sides[j].side->source;
        r.reason = std::string("cannot be evaluated: ") + e.what();
        return r;
    }
}

// The text's sign of λ, kept for its section (compare_values.cpp asks).
bool Checker::keeps_multiplier_sign(bool with_eomgens, bool with_opposite, EquationCheck& r) {
    if (with_eomgens == with_opposite || verifying_) return true;  // both (λ cancels) or neither: nothing learnt
    const int sign = with_eomgens ? 1 : -1;
    // The convention holds in its section; another section may take the other one.
    if (multiplier_sign_ == 0 || r.section != multiplier_sign_section_) {
        multiplier_sign_ = sign;
        multiplier_sign_line_ = r.where.line;
        multiplier_sign_section_ = r.section;
        return true;
    }
    if (sign == multiplier_sign_) return true;
    const std::string line = std::to_string(multiplier_sign_line_);
    r.verdict = Verdict::Disagrees;
    r.reason = "it holds only with λ of the sign opposite to the one the text takes on line " + line + " (" +
               (multiplier_sign_ > 0 ? "eomgen's, M q'' = f + A^T λ" : "the opposite of eomgen's M q'' = f + A^T λ") +
               ")";
    r.wrong_terms = {"the multiplier, or the constraint force it gives, has the wrong sign for the text's own "
                     "convention of line " + line};
    return false;
}

}  // namespace eomgen::checker::detail
