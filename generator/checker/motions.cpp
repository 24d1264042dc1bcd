/** @file motions.cpp  Lines checked on a particular motion of the model ([[motions]]). */
#include "checker/motions.hpp"

#include "checker/latex_normalize.hpp"

#include <algorithm>
#include <cctype>

namespace eomgen::checker {

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string m(const std::string& latex) { return "$" + latex + "$"; }

/// The symbols of e.
void symbols_of(const GiNaC::ex& e, std::vector<GiNaC::ex>& out) {
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        if (std::none_of(out.begin(), out.end(), [&](const GiNaC::ex& x) { return x.is_equal(e); })) out.push_back(e);
        return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) symbols_of(e.op(i), out);
}

/// Whether e evaluates to a finite real number at some of a few points (every symbol a rational in
/// (0.5, 1.5)): otherwise a comparison on the motion proves nothing (a root of a negative number, a pole).
bool evaluable(const GiNaC::ex& e) {
    std::vector<GiNaC::ex> symbols;
    symbols_of(e, symbols);
    // By name: GiNaC's term order, and so the order symbols_of finds them in, changes from run to run (its
    // hashes are seeded from addresses), and with it which value each symbol would get.
    std::sort(symbols.begin(), symbols.end(), [](const GiNaC::ex& x, const GiNaC::ex& y) {
        return GiNaC::ex_to<GiNaC::symbol>(x).get_name() < GiNaC::ex_to<GiNaC::symbol>(y).get_name();
    });
    for (unsigned seed = 1; seed <= 5; ++seed) {
        GiNaC::exmap at;
        for (std::size_t k = 0; k < symbols.size(); ++k)
            at[symbols[k]] = GiNaC::numeric(int(500 + (seed * 7919u + k * 104729u) % 1000), 1000);
        try {
            const GiNaC::ex v = GiNaC::evalf(e.subs(at));
            if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return true;
        } catch (...) {
        }
    }
    return false;
}

}  // namespace

GiNaC::ex ParticularMotions::on(const Reading& rd, const GiNaC::ex& e) const {
    GiNaC::ex x = e;
    // Conditions may use coordinates other conditions give: substitute until nothing changes (bounded).
    for (std::size_t round = 0; round <= 3 * model_.dof() + 2; ++round) {
        const GiNaC::ex y = x.subs(rd.subs);
        if (y.is_equal(x)) break;
        x = y;
    }
    return x;
}

ParticularMotions::Reading& ParticularMotions::reading(const Motion& mo, Comparisons& cmp) {
    for (Reading& rd : readings_)
        if (rd.motion == &mo) return rd;
    Reading rd;
    rd.motion = &mo;
    GiNaC::exmap constants;  // the model file's symbols → the text's names (the text's \Omega is the motion's)
    for (const Motion::Constant& c : mo.constants) {
        std::string name = canonical_name(c.latex);
        if (name.empty()) name = c.latex;
        const GiNaC::symbol s = ctx_.free_symbol(name, NameKind::Unknown);
        constants[c.symbol] = s;
        rd.constants.push_back(s);
    }
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> velocities;  // q' → its value (before closing)
    for (const MotionCondition& mc : mo.conditions) {
        const Coordinate& q = model_.coordinates[mc.coordinate];
        const GiNaC::ex value = mc.value.expr.subs(constants);
        if (mc.velocity) {
            rd.subs[q.qd] = value;
            velocities.push_back({q.qd, value});
        } else {
            rd.subs[q.q] = value;
            const GiNaC::ex v = time_derivative(value, model_);
            rd.subs[q.qd] = v;
            velocities.push_back({q.qd, v});
        }
        if (!rd.conditions.empty()) rd.conditions += ", ";
        rd.conditions += m(cmp.latex(mc.velocity ? q.qd : q.q) + " = " + cmp.latex(value));
    }
    // The accelerations: the time derivatives of the velocities along the motion.
    for (const auto& [qd, v] : velocities)
        for (const Coordinate& q : model_.coordinates)
            if (GiNaC::ex(q.qd).is_equal(qd)) rd.subs[q.qdd] = time_derivative(v, model_);
    // The motion must solve the Euler–Lagrange equations (with constraints, their multipliers are unknown:
    // not checked).
    if (eq_.constraints.empty()) {
        for (std::size_t i = 0; i < model_.dof() && rd.problem.empty(); ++i) {
            const GiNaC::ex el = i < eq_.generalized_forces.size() ? eq_.euler_lagrange[i] - eq_.generalized_forces[i]
                                                                 : eq_.euler_lagrange[i];
            const GiNaC::ex left = on(rd, el);
            if (!evaluable(left))
                rd.problem = "the Euler–Lagrange equation for " + m(model_.coordinates[i].latex) +
                             " cannot be evaluated on the motion '" + mo.name + "' (" + rd.conditions + ")";
            else if (!cmp.same(left, 0, 1e-9))
                rd.problem = "the motion '" + mo.name + "' (" + rd.conditions +
                             ") does not solve the model's Euler–Lagrange equation for " +
                             m(model_.coordinates[i].latex) + ", which leaves " + m(cmp.latex(left)) + " (not 0) on it";
        }
    }
    readings_.push_back(std::move(rd));
    return readings_.back();
}

std::vector<GiNaC::ex> ParticularMotions::text_names(const Reading& rd, const GiNaC::ex& e) const {
    std::vector<GiNaC::ex> all, out;
    symbols_of(e, all);
    for (const GiNaC::ex& s : all) {
        const FreeName* f = ctx_.free_name_of(s);
        if (!f || f->kind != NameKind::Unknown || is_constant_name(f->name)) continue;
        if (std::any_of(rd.constants.begin(), rd.constants.end(), [&](const GiNaC::ex& c) { return c.is_equal(s); }))
            continue;
        out.push_back(s);
    }
    // In the order of their names: the order of GiNaC's terms is not the same from run to run.
    std::sort(out.begin(), out.end(), [&](const GiNaC::ex& x, const GiNaC::ex& y) {
        return ctx_.free_name_of(x)->name < ctx_.free_name_of(y)->name;
    });
    return out;
}

bool ParticularMotions::check(const GiNaC::ex& a, const GiNaC::ex& b, const std::string& left_source,
                              const std::vector<std::string>& sections, Comparisons& cmp, double tol,
                              EquationCheck& r) {
    const Motion* mo = nullptr;
    for (const Motion& x : model_.motions) {
        const bool applies = x.section.empty() || std::any_of(sections.begin(), sections.end(), [&](const std::string& s) {
                                 return lower(s).find(lower(x.section)) != std::string::npos;
                             });
        if (applies) {
            mo = &x;
            break;
        }
    }
    if (!mo) return false;
    Reading& rd = reading(*mo, cmp);
    const GiNaC::ex diff = a - b;
    // Only a line the motion speaks to: one with a quantity the conditions give, or a constant of the motion.
    bool touched = false;
    for (const auto& [x, v] : rd.subs) touched = touched || diff.has(x);
    for (const Coordinate& q : model_.coordinates) touched = touched || diff.has(q.q);
    for (const GiNaC::ex& c : rd.constants) touched = touched || diff.has(c);
    if (!touched) return false;
    const std::string on_motion = "on the motion '" + mo->name + "' (" + rd.conditions + ")";
    if (!rd.problem.empty()) {
        r.verdict = Verdict::NotComparable;
        r.reason = "not an identity; not compared " + on_motion + ": " + rd.problem;
        return true;
    }
    const GiNaC::ex ra = on(rd, a), rb = on(rd, b);
    const GiNaC::ex rdiff = ra - rb;
    auto agree = [&](const std::string& how) {
        r.verdict = Verdict::Agrees;
        r.compared_with = "the motion '" + mo->name + "'";
        r.reason = "agrees " + on_motion + how;
        return true;
    };
    if (cmp.same(ra, rb, tol)) return agree("");
    if (!evaluable(ra - rb)) {
        r.notes.push_back("on the motion '" + mo->name + "' it cannot be evaluated: not decided");
        return false;
    }
    const std::vector<GiNaC::ex> names = text_names(rd, rdiff);
    auto free_coordinates = [&](const GiNaC::ex& e) {
        for (const Coordinate& q : model_.coordinates)
            if (e.has(q.q)) return true;
        return false;
    };
    const GiNaC::ex rate = on(rd, time_derivative(diff, model_));
    // Not decided: the line uses names of the text's own besides the motion's constants.
    auto undecided = [&](const std::vector<GiNaC::ex>& names) {
        std::string list;
        for (const GiNaC::ex& x : names) list += (list.empty() ? "" : ", ") + m(ctx_.free_name_of(x)->name);
        r.notes.push_back("on the motion '" + mo->name + "' it still depends on " + list +
                          ", which the text does not define: not decided");
        return false;
    };
    if (names.empty()) {
        // `\phi = \dot\phi t`: a function of t whose difference is constant along the motion holds for the
        // initial values it chooses.
        if (rdiff.has(model_.t) && free_coordinates(rdiff) && cmp.same(rate, 0, tol))
            return agree(", for the initial value it chooses (the two sides differ by a constant there)");
        // With t and a coordinate the motion leaves free, a phase could still make it hold: not decided.
        if (rdiff.has(model_.t) && free_coordinates(rdiff)) {
            r.notes.push_back("on the motion '" + mo->name + "' it holds only for some initial values (t and a "
                              "coordinate the motion leaves free): not decided");
            return false;
        }
        r.verdict = Verdict::Disagrees;
        r.compared_with = "the motion '" + mo->name + "'";
        r.notes.push_back("not an identity; compared " + on_motion);
        r.difference = cmp.latex(GiNaC::normal(rb - ra));  // text − reference: the left side is the reference
        if (free_coordinates(ra) && !cmp.same(rate, 0, tol)) {
            // `\psi = \pi/2 - \Omega`: the left side still moves on the motion, the right does not keep up.
            r.wrong_terms.push_back("the two sides differ by " + m(r.difference) +
                                    ", which changes on the motion at the rate " + m(cmp.latex(GiNaC::normal(rate))) +
                                    ": the line holds at no instant but isolated ones");
            return true;
        }
        try {  // the diagnosis by terms: what GiNaC throws on a strange form leaves just the difference
            // Each side as one fraction: the substitutions leave sums in denominators that the term-by-term
            // diagnosis would split into terms the text never wrote.
            r.wrong_terms = cmp.wrong_terms(GiNaC::normal(rb), GiNaC::normal(ra), tol);
        } catch (const std::exception&) {
            r.wrong_terms.clear();
        }
        if (!ra.is_equal(a)) r.corrected = left_source + " = " + cmp.latex(ra);
        return true;
    }
    // `\omega_{0} = \dot\phi \sin\theta`: the text names a constant of the motion; its value must be constant
    // there.
    if (names.size() == 1 && (a.is_equal(names[0]) || b.is_equal(names[0]))) {
        const GiNaC::ex& f = a.is_equal(names[0]) ? b : a;
        if (f.has(names[0]) || f.has(model_.t) || !text_names(rd, f).empty()) return undecided(names);
        const std::string c = m(ctx_.free_name_of(names[0])->name);
        if (cmp.same(rate, 0, tol)) return agree(": " + m(cmp.latex(on(rd, f))) + " is constant on it, and " + c +
                                                 " is that constant of the motion");
        r.verdict = Verdict::Disagrees;
        r.compared_with = "the motion '" + mo->name + "'";
        r.notes.push_back("not an identity; compared " + on_motion);
        r.difference = cmp.latex(GiNaC::normal(rate));
        r.wrong_terms.push_back(c + " is set equal to " + m(cmp.latex(on(rd, f))) +
                                ", which is not constant on the motion (its rate of change is the difference)");
        return true;
    }
    return undecided(names);
}

}  // namespace eomgen::checker
