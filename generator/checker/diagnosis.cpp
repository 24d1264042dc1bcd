/** @file diagnosis.cpp  What a disagreement says: the groups of terms, the wrong, missing and extra ones, the
 * factor that tells two sides apart, the Euler–Lagrange equation (or solved acceleration) it is closest to. */
#include "checker/checker_internals.hpp"
#include "checker/linear_solve.hpp"

namespace eomgen::checker::detail {

// -------------------------------------------------------------------------------------------- diagnosis

std::string Checker::latex(const GiNaC::ex& e) {
    // Integrals become placeholders printed from their parts, so that everything goes through the canonical
    // printer: GiNaC's own order changes from process to process.
    GiNaC::exmap placeholders;
    std::function<GiNaC::ex(const GiNaC::ex&)> hide = [&](const GiNaC::ex& x) -> GiNaC::ex {
        if (GiNaC::is_a<GiNaC::integral>(x)) {
            const std::string var = GiNaC::ex_to<GiNaC::symbol>(x.op(0)).get_TeX_name();
            const std::string text =
                "\\int_{" + latex(x.op(1)) + "}^{" + latex(x.op(2)) + "} " + latex(x.op(3)) + " \\, d" + var;
            return GiNaC::symbol(text, text);
        }
        if (x.nops() == 0) return x;
        GiNaC::ex out = x;
        struct Each : GiNaC::map_function {
            std::function<GiNaC::ex(const GiNaC::ex&)>& f;
            explicit Each(std::function<GiNaC::ex(const GiNaC::ex&)>& g) : f(g) {}
            GiNaC::ex operator()(const GiNaC::ex& y) override { return f(y); }
        } each(hide);
        return x.map(each);
    };
    try {
        const GiNaC::ex shown = has_integral(e) ? hide(e) : e;
        codegen::SymbolTable table = printer_table_;
        auto add = [&](const GiNaC::ex& sym, const std::string& name) {
            table.info.push_back(
                {codegen::SymbolKind::Constant, int(table.info.size()), name, name, name, name});
            table.exprs.push_back(sym);
        };
        for (const auto& [name, f] : ctx_.free_names) add(f.symbol, name);
        // Placeholders, bound variables of integrals and anything else the table does not know, by their TeX
        // names, in the order of those names (the table's order is the printed order).
        ExSet known(table.exprs.begin(), table.exprs.end());
        std::vector<std::pair<std::string, GiNaC::ex>> others;
        std::vector<GiNaC::ex> stack{shown};
        while (!stack.empty()) {
            const GiNaC::ex x = stack.back();
            stack.pop_back();
            if (GiNaC::is_a<GiNaC::symbol>(x) && !known.count(x)) {
                others.push_back({GiNaC::ex_to<GiNaC::symbol>(x).get_TeX_name(), x});
                known.insert(x);
            }
            for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
        }
        std::sort(others.begin(), others.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [name, sym] : others) add(sym, name);
        codegen::MathPrinter printer(table);
        printer.prefer_angles(hints_.angles);
        return printer.print(trig::readable(shown, hints_), codegen::MathStyle::Latex);
    } catch (...) {
    }
    std::ostringstream os;
    os << GiNaC::latex << e;
    return os.str();
}

std::vector<Group> Checker::groups(const GiNaC::ex& e) const {
    std::vector<GiNaC::ex> terms;
    const GiNaC::ex x = e.expand();
    if (GiNaC::is_a<GiNaC::add>(x)) {
        for (const GiNaC::ex& t : x) terms.push_back(t);
    } else if (!x.is_zero()) {
        terms.push_back(x);
    }
    ExSet motion;
    for (const Coordinate& c : model_.coordinates) {
        motion.insert(c.qd);
        motion.insert(c.qdd);
    }
    auto is_motion = [&](const GiNaC::ex& f) {
        if (motion.count(f)) return true;
        return GiNaC::is_a<GiNaC::power>(f) && motion.count(f.op(0)) &&
               f.op(1).info(GiNaC::info_flags::integer);
    };
    std::vector<Group> out;
    for (const GiNaC::ex& t : terms) {
        GiNaC::ex mono = 1, coeff = 1;
        if (GiNaC::is_a<GiNaC::mul>(t)) {
            for (const GiNaC::ex& f : t) (is_motion(f) ? mono : coeff) *= f;
        } else if (is_motion(t)) {
            mono = t;
        } else {
            coeff = t;
        }
        auto it =
            std::find_if(out.begin(), out.end(), [&](const Group& g) { return g.monomial.is_equal(mono); });
        if (it == out.end()) {
            out.push_back({mono, {}, 0});
            it = out.end() - 1;
        }
        it->terms.push_back(t);
        it->coefficient += coeff;
    }
    // Accelerations first, then higher powers of velocities; coordinates in model order.
    auto key = [&](const GiNaC::ex& mono) {
        std::vector<int> k;
        int acc = 0, vel = 0;
        for (const Coordinate& c : model_.coordinates) {
            acc += mono.degree(c.qdd);
            vel += mono.degree(c.qd);
        }
        k.push_back(-acc);
        k.push_back(-vel);
        for (const Coordinate& c : model_.coordinates) {
            k.push_back(-mono.degree(c.qdd));
            k.push_back(-mono.degree(c.qd));
        }
        return k;
    };
    std::stable_sort(out.begin(), out.end(),
                     [&](const Group& a, const Group& b) { return key(a.monomial) < key(b.monomial); });
    return out;
}

std::string Checker::group_name(const GiNaC::ex& monomial) const {
    if (monomial.is_equal(1)) return "the terms without velocities";
    std::string s = const_cast<Checker*>(this)->latex(monomial);
    return "the " + m(s) + " terms";
}

std::string Checker::pair_kind(const GiNaC::ex& t, const GiNaC::ex& u, double tol, int* score) {
    const auto su = signature(u);
    if (same_signature(signature(-t), su, tol)) {
        *score = 1;
        return "a flipped sign";
    }
    // One sine or cosine at a time turned into the other.
    std::vector<std::pair<GiNaC::ex, std::string>> swaps;
    {
        ExSet trig;
        std::vector<GiNaC::ex> stack{t};
        while (!stack.empty()) {
            const GiNaC::ex x = stack.back();
            stack.pop_back();
            if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(x) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(x))
                trig.insert(x);
            for (std::size_t k = 0; k < x.nops(); ++k) stack.push_back(x.op(k));
        }
        for (const GiNaC::ex& f : trig) {
            const bool is_sin = GiNaC::is_the_function<GiNaC::sin_SERIAL>(f);
            const GiNaC::ex other = is_sin ? GiNaC::cos(f.op(0)) : GiNaC::sin(f.op(0));
            // a swap that divides by zero (1/(I_3 - I) with I for I_3) is no candidate
            if (const auto swapped = subs_unless_pole(t, GiNaC::exmap{{f, other}}))
                swaps.push_back({*swapped, is_sin ? m("\\sin") + " where " + m("\\cos") + " belongs"
                                                  : m("\\cos") + " where " + m("\\sin") + " belongs"});
        }
    }
    for (const auto& [x, what] : swaps) {
        if (x.is_equal(t)) continue;
        if (same_signature(signature(x), su, tol)) {
            *score = 2;
            return what;
        }
        if (same_signature(signature(-x), su, tol)) {
            *score = 2;
            return what + ", and a flipped sign";
        }
    }
    std::vector<std::pair<GiNaC::ex, std::string>> names;
    for (const Parameter& p : model_.parameters) names.push_back({p.symbol, p.latex});
    for (const Coordinate& c : model_.coordinates) names.push_back({c.q, c.latex});
    for (const auto& [a, la] : names)
        for (const auto& [b, lb] : names) {
            if (a.is_equal(b) || !t.has(a)) continue;
            const auto swapped = subs_unless_pole(t, GiNaC::exmap{{a, b}});
            if (swapped && same_signature(signature(*swapped), su, tol)) {
                *score = 2;
                return m(la) + " where " + m(lb) + " belongs";
            }
        }
    try {
        const GiNaC::ex q = GiNaC::normal(t / u);
        if (GiNaC::is_a<GiNaC::numeric>(q)) {
            *score = 3;
            return "off by a factor " + m(latex(q));
        }
    } catch (...) {
    }
    *score = 9;
    return "";
}

Diagnosis Checker::compare_to(const GiNaC::ex& text_as_read, const GiNaC::ex& truth_as_derived, double tol) {
    // Term by term in the author's sines and cosines: k sin(θ₁ − θ₂) where k cos(θ₁ − θ₂) belongs.
    trig::Hints terms_hints = hints_;
    terms_hints.collect = false;
    const GiNaC::ex text = trig::readable(text_as_read, terms_hints);
    const GiNaC::ex truth = trig::readable(truth_as_derived, terms_hints);
    Diagnosis d;
    const GiNaC::ex diff = (text - truth).expand();
    d.difference = latex(diff);
    const std::vector<Group> tg = groups(text), ug = groups(truth);
    std::vector<GiNaC::ex> keys;
    for (const Group& g : tg) keys.push_back(g.monomial);
    for (const Group& g : ug)
        if (std::none_of(keys.begin(), keys.end(),
                         [&](const GiNaC::ex& k) { return k.is_equal(g.monomial); }))
            keys.push_back(g.monomial);
    auto find = [](const std::vector<Group>& gs, const GiNaC::ex& k) -> const Group* {
        for (const Group& g : gs)
            if (g.monomial.is_equal(k)) return &g;
        return nullptr;
    };
    // Order keys as groups() would: use a combined expression of monomials.
    {
        GiNaC::ex probe = 0;
        GiNaC::symbol marker("__k");
        for (const GiNaC::ex& k : keys) probe += marker * k;
        std::vector<GiNaC::ex> sorted;
        for (const Group& g : groups(probe)) sorted.push_back(g.monomial);
        if (sorted.size() == keys.size()) keys = sorted;
    }
    for (const GiNaC::ex& k : keys) {
        const Group* a = find(tg, k);
        const Group* b = find(ug, k);
        const GiNaC::ex ca = a ? a->coefficient : GiNaC::ex(0), cb = b ? b->coefficient : GiNaC::ex(0);
        if (equal(ca * k, cb * k, tol) == Tri::Yes) continue;
        const std::string group = group_name(k);
        // The whole group off by a constant factor (a dropped 1/3, a flipped sign): say so once.
        if (a && b) {
            try {
                const GiNaC::ex q = GiNaC::normal(ca / cb);
                if (GiNaC::is_a<GiNaC::numeric>(q)) {
                    d.lines.push_back(
                        group + ": " + m(latex(ca * k)) + " where " + m(latex(cb * k)) + " belongs (" +
                        (q.is_equal(-1) ? std::string("a flipped sign") : "off by a factor " + m(latex(q))) +
                        ")");
                    continue;
                }
            } catch (...) {
            }
        }
        std::vector<GiNaC::ex> ts = a ? a->terms : std::vector<GiNaC::ex>{};
        std::vector<GiNaC::ex> us = b ? b->terms : std::vector<GiNaC::ex>{};
        // In a printed order, not GiNaC's (which changes from process to process).
        auto printed = [this](std::vector<GiNaC::ex>& v) {
            std::vector<std::pair<std::string, GiNaC::ex>> keyed;
            for (const GiNaC::ex& x : v) keyed.push_back({latex(x), x});
            std::stable_sort(keyed.begin(), keyed.end(),
                             [](const auto& x, const auto& y) { return x.first < y.first; });
            for (std::size_t i = 0; i < v.size(); ++i) v[i] = keyed[i].second;
        };
        printed(ts);
        printed(us);
        // Terms equal on both sides are not the problem.
        for (std::size_t i = 0; i < ts.size();) {
            bool removed = false;
            for (std::size_t j = 0; j < us.size(); ++j)
                if (same_signature(signature(ts[i]), signature(us[j]), std::max(tol, 1e-9))) {
                    us.erase(us.begin() + long(j));
                    ts.erase(ts.begin() + long(i));
                    removed = true;
                    break;
                }
            if (!removed) ++i;
        }
        // Pair what is left, best explanations first.
        struct Cand {
            int score;
            std::size_t i, j;
            std::string kind;
        };
        std::vector<Cand> cands;
        for (std::size_t i = 0; i < ts.size(); ++i)
            for (std::size_t j = 0; j < us.size(); ++j) {
                int score = 9;
                std::string kind = pair_kind(ts[i], us[j], std::max(tol, 1e-9), &score);
                cands.push_back({score, i, j, kind});
            }
        std::stable_sort(cands.begin(), cands.end(),
                         [](const Cand& x, const Cand& y) { return x.score < y.score; });
        std::vector<bool> ti(ts.size(), false), uj(us.size(), false);
        for (const Cand& c : cands) {
            if (ti[c.i] || uj[c.j]) continue;
            // A lone pair is explained even without a kind; among several, only recognised kinds pair up.
            if (c.score == 9 && !(ts.size() == 1 && us.size() == 1)) continue;
            ti[c.i] = uj[c.j] = true;
            d.lines.push_back(group + ": " + m(latex(ts[c.i])) + " where " + m(latex(us[c.j])) + " belongs" +
                              (c.kind.empty() ? "" : " (" + c.kind + ")"));
        }
        for (std::size_t j = 0; j < us.size(); ++j)
            if (!uj[j]) d.lines.push_back(group + ": missing " + m(latex(us[j])));
        for (std::size_t i = 0; i < ts.size(); ++i)
            if (!ti[i]) d.lines.push_back(group + ": " + m(latex(ts[i])) + " should not be there");
        if (ts.empty() && us.empty())  // equal term by term within the tolerance, not as a sum: say so
            d.lines.push_back(group + ": " + m(latex(ca * k)) + " where " + m(latex(cb * k)) + " belongs");
    }
    if (d.lines.empty()) d.lines.push_back("the two differ by " + m(d.difference));
    return d;
}

int Checker::best_factor(const GiNaC::ex& text, const GiNaC::ex& truth, double tol, GiNaC::ex* c) {
    const std::vector<Group> tg = groups(text), ug = groups(truth);
    std::vector<GiNaC::ex> candidates;
    for (const Group& a : tg)
        for (const Group& b : ug)
            if (a.monomial.is_equal(b.monomial)) {
                try {
                    const GiNaC::ex q = GiNaC::normal(a.coefficient / b.coefficient);
                    if (!q.is_zero()) candidates.push_back(q);
                } catch (...) {
                }
            }
    if (candidates.empty()) candidates.push_back(1);
    int best = -1;
    for (const GiNaC::ex& q : candidates) {
        int agree = 0;
        for (const Group& a : tg) {
            GiNaC::ex cb = 0;
            for (const Group& b : ug)
                if (b.monomial.is_equal(a.monomial)) cb = b.coefficient;
            if (equal(a.coefficient, q * cb, tol) == Tri::Yes) ++agree;
        }
        const bool better = agree > best || (agree == best && GiNaC::is_a<GiNaC::numeric>(q) &&
                                             !GiNaC::is_a<GiNaC::numeric>(*c));
        if (better) {
            best = agree;
            *c = q;
        }
    }
    return best;
}

std::vector<std::string> Checker::factor_analysis(const GiNaC::ex& a, const GiNaC::ex& b, double tol,
                                                  std::string* ratio) {
    std::vector<std::string> out;
    auto factors = [](const GiNaC::ex& e) {
        std::vector<GiNaC::ex> f;
        if (GiNaC::is_a<GiNaC::mul>(e))
            for (const GiNaC::ex& x : e) f.push_back(x);
        else
            f.push_back(e);
        return f;
    };
    std::vector<GiNaC::ex> fa = factors(a), fb = factors(b);
    // Factors equal on both sides (numerically: two integrals with the same value count as equal) cancel.
    for (std::size_t i = 0; i < fa.size();) {
        bool removed = false;
        for (std::size_t j = 0; j < fb.size(); ++j)
            if (same_signature(signature(fa[i]), signature(fb[j]), std::max(tol, 1e-9))) {
                fa.erase(fa.begin() + long(i));
                fb.erase(fb.begin() + long(j));
                removed = true;
                break;
            }
        if (!removed) ++i;
    }
    GiNaC::ex A = 1, B = 1;
    for (const GiNaC::ex& x : fa) A *= x;
    for (const GiNaC::ex& x : fb) B *= x;
    try {
        // A number?
        const auto sa = signature(A / B);
        bool constant = !std::isnan(sa[0].real());
        for (const Complex& v : sa) constant = constant && std::abs(v - sa[0]) <= 1e-9 * std::abs(sa[0]);
        if (constant && std::abs(sa[0].imag()) < 1e-12 * std::abs(sa[0])) {
            const double k = sa[0].real();
            std::ostringstream os;
            os.precision(6);
            os << k;
            const bool minus_one = std::abs(k + 1) <= std::max(tol, 1e-9);
            out.push_back(minus_one
                              ? std::string("the two sides have opposite signs") +
                                    (std::abs(k + 1) > 1e-9 ? " (the left side is " + os.str() +
                                                                  " times the right side; equal in size "
                                                                  "within the rounding of the numbers)"
                                                            : "")
                              : "the left side is " + os.str() + " times the right side");
            *ratio = minus_one ? "-" : os.str();
            return out;
        }
        GiNaC::ex q = GiNaC::normal(A / B);
        std::string shown;
        if (!has_root(q) && !has_integral(q)) {
            shown = latex(q);
        } else {
            const GiNaC::ex q2 = GiNaC::normal(GiNaC::pow(A / B, 2));
            if (!has_root(q2) && !has_integral(q2)) shown = "\\sqrt{" + latex(q2) + "}";
        }
        if (!shown.empty()) {
            out.push_back("the left side is " + m(shown) + " times the right side");
            *ratio = shown;
        }
        if (fa.size() == 1 && fb.size() == 1)
            out.push_back("the factor " + m(latex(fa[0])) + " where the right side has " + m(latex(fb[0])));
    } catch (...) {
    }
    return out;
}

int Checker::closest_euler_lagrange(const GiNaC::ex& r, double tol, GiNaC::ex* factor, int* groups) {
    int best_i = -1, best_count = -1;
    for (std::size_t i = 0; i < model_.dof(); ++i) {
        GiNaC::ex c = 1;
        const int count = best_factor(r, motion_[i], tol, &c);
        // Ties: the coordinate whose own acceleration the text's equation has.
        const bool better = count > best_count || (count == best_count && r.has(model_.coordinates[i].qdd) &&
                                                   !r.has(model_.coordinates[std::size_t(best_i)].qdd));
        if (better) {
            best_count = count;
            best_i = int(i);
            *factor = c;
        }
    }
    if (groups) *groups = best_count;
    return best_i;
}

void Checker::diagnose_euler_lagrange(const PSide& left, const PSide& right, const GiNaC::ex& r, double tol,
                                      EquationCheck& out) {
    (void)left;
    (void)right;
    if (diagnose_solved_acceleration(left, right, r, tol, out)) return;
    GiNaC::ex best_c = 1;
    const std::size_t i = std::size_t(closest_euler_lagrange(r, tol, &best_c, nullptr));
    const Coordinate& q = model_.coordinates[i];
    out.verdict = Verdict::Disagrees;
    out.compared_with = "the Euler–Lagrange equation for " + m(q.latex);
    if (!best_c.is_equal(1))
        out.notes.push_back("compared after scaling eomgen's equation by " + m(latex(best_c)));
    GiNaC::ex truth = (best_c * motion_[i]).expand();
    // Written with the multipliers: the equation with the constraint forces Σ_k A_ki λ_k, λ with the text's sign
    // (keeps_multiplier_sign), else the sign that leaves fewer terms wrong.
    GiNaC::ex force = 0;
    for (std::size_t k = 0; k < multipliers_.size() && k < eq_.constraints.size(); ++k)
        if (r.has(multipliers_[k])) force += GiNaC::diff(eq_.constraints[k].velocity, q.qd) * multipliers_[k];
    if (!force.is_zero()) {
        int sign = multiplier_sign_;
        if (sign == 0)
            sign = compare_to(r, (best_c * (motion_[i] + force)).expand(), tol).lines.size() <
                           compare_to(r, (best_c * (motion_[i] - force)).expand(), tol).lines.size()
                       ? -1
                       : 1;
        truth = (best_c * (motion_[i] - sign * force)).expand();
        out.compared_with += " with the constraint forces";
        if (multiplier_sign_ != 0)
            out.notes.push_back("with the sign of λ the text takes on line " + std::to_string(multiplier_sign_line_));
    }
    // A value the text chose or a limit it takes (`m_1 = 0`, "as $c \to 0$"): eomgen's equation there.
    if (!numbers_.pinned().empty()) truth = subs_unless_pole(truth, numbers_.pinned()).value_or(truth).expand();
    const Diagnosis dg = compare_to(r, truth, tol);
    out.difference = dg.difference;
    out.wrong_terms = dg.lines;
    out.corrected = latex(truth) + " = 0";
    // d/dt(X) − (Y) = 0 written out: say which of ∂L/∂q̇ and ∂L/∂q is wrong.
    for (const PSide* s : {&left, &right}) {
        if (!s->side->ok) continue;
        std::vector<GiNaC::ex> found;
        std::vector<GiNaC::ex> stack{s->side->value};
        while (!stack.empty()) {
            GiNaC::ex x = stack.back();
            stack.pop_back();
            if (is_ex_the_function(x, ddt)) found.push_back(x);
            for (std::size_t k = 0; k < x.nops(); ++k) stack.push_back(x.op(k));
        }
        if (found.size() != 1) continue;
        try {
            const GiNaC::ex D = found[0];
            const GiNaC::symbol z("__d");
            GiNaC::exmap labels;
            for (const auto& [sym, val] : truth_) labels[sym] = val;
            const GiNaC::ex side_z = s->side->value.subs(D == z).subs(labels);
            const GiNaC::ex k = GiNaC::diff(side_z, z);
            if (has_velocity(k) || k.has(z)) continue;
            const double sign = s == &left ? 1 : -1;
            const GiNaC::ex X = resolve_operators(D.op(0).subs(labels));
            const GiNaC::ex rest = resolve_operators(side_z.subs(z == 0));
            const GiNaC::ex other = resolve_operators(prepare(s == &left ? right : left).value);
            // side = k·d/dt X + rest. With sign +1 on the left, −1 on the right, the equation matches
            // c·(d/dt p − ∂L/∂q) when sign·k·X = c·p and −sign·(rest − other side) = c·∂L/∂q.
            const GiNaC::ex p_text = (sign * k * X).expand();
            const GiNaC::ex dLdq_text = (-sign * (rest - other)).expand();
            // d/dt(c p) is c d/dt(p) only for a constant c: a factor that depends on the state stays outside.
            const GiNaC::ex c = depends_on_state(best_c) || best_c.has(model_.t) ? GiNaC::ex(1) : best_c;
            const GiNaC::ex p_true = (c * eq_.momenta[i]).expand();
            const GiNaC::ex dLdq_true = (c * (time_derivative(eq_.momenta[i], model_) - motion_[i])).expand();
            const std::string pl = m("\\partial L/\\partial \\dot{" + q.latex + "}");
            const std::string ql = m("\\partial L/\\partial " + q.latex);
            if (equal(p_text, p_true, tol) == Tri::Yes) {
                out.notes.push_back("inside " + m("\\frac{d}{dt}") + ": the text's " + pl + " agrees");
            } else {
                const Diagnosis dp = compare_to(p_text, p_true, tol);
                for (const std::string& line : dp.lines)
                    out.wrong_terms.push_back("inside " + m("\\frac{d}{dt}") + " (" + pl + "), " + line);
            }
            if (equal(dLdq_text, dLdq_true, tol) == Tri::Yes) {
                out.notes.push_back("the text's " + ql + " agrees");
            } else {
                const Diagnosis dq = compare_to(dLdq_text, dLdq_true, tol);
                for (const std::string& line : dq.lines) out.wrong_terms.push_back("in " + ql + ", " + line);
            }
            out.corrected = lagrange_form(latex(p_true), latex(dLdq_true));
        } catch (...) {
        }
    }
}

bool Checker::diagnose_solved_acceleration(const PSide& left, const PSide& right, const GiNaC::ex& r, double tol,
                                           EquationCheck& out) {
    // `\ddot x_2 = …` with the other accelerations eliminated, in a model of 2 to 4 unconstrained coordinates:
    // compared with q''_i solved from M q'' = f, not with the Euler–Lagrange equation that still holds the others.
    const std::size_t n = model_.dof();
    if (n < 2 || n > 4 || !eq_.constraints.empty()) return false;
    int solved = -1;
    for (std::size_t k = 0; k < n; ++k)
        if (r.has(model_.coordinates[k].qdd)) {
            if (solved >= 0) return false;
            solved = int(k);
        }
    if (solved < 0) return false;
    const std::size_t i = std::size_t(solved);
    const GiNaC::symbol& qdd = model_.coordinates[i].qdd;
    const PSide* alone = nullptr;  // the side that is q''_i itself
    for (const PSide* s : {&left, &right})
        if (s->side->ok && s->side->value.is_equal(qdd)) alone = s;
    if (!alone) return false;
    GiNaC::matrix rhs(unsigned(n), 1);
    for (std::size_t k = 0; k < n; ++k) rhs(unsigned(k), 0) = eq_.f[k];
    const std::optional<GiNaC::ex> solution = solved_unknown(eq_.M, rhs, unsigned(i));
    if (!solution) return false;
    GiNaC::ex value = *solution;
    if (!numbers_.pinned().empty()) value = GiNaC::normal(subs_unless_pole(value, numbers_.pinned()).value_or(value));
    if (expanded_terms(value) > kMaxExpandedTerms) return false;
    const GiNaC::ex truth_r = alone == &left ? GiNaC::ex(qdd - value) : GiNaC::ex(value - qdd);
    out.verdict = Verdict::Disagrees;
    out.compared_with = m("\\ddot{" + model_.coordinates[i].latex + "}") + " solved from the Euler–Lagrange equations";
    const Diagnosis dg = compare_to(r, truth_r, tol);
    out.difference = dg.difference;
    out.wrong_terms = dg.lines;
    out.corrected = alone == &left ? alone->side->source + " = " + latex(value)
                                   : latex(value) + " = " + alone->side->source;
    return true;
}

std::string Checker::printed_value(const Prepared& ref, const PSide& ref_side, const Prepared& text) {
    const std::string in_velocities = latex(ref.value);
    std::optional<GiNaC::ex> in_p;
    if (text.has_momenta && ref.has_momenta) in_p = hamilton_.in_momenta(ref.value_p);
    if (text.has_momenta && ref_side.side->ok && hamilton_.is_hamiltonian(ref_side.side->value))
        in_p = hamilton_.hamiltonian();
    // In the momenta unless that is much longer (an inverse mass matrix GiNaC cannot simplify).
    if (in_p && expanded_terms(*in_p) <= kMaxExpandedTerms / 10) {
        const std::string shown = latex(*in_p);
        if (shown.size() <= 2 * in_velocities.size()) return shown;
    }
    return in_velocities;
}

}  // namespace eomgen::checker::detail
