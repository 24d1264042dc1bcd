/** @file change_of_variable.cpp  `\phi = \phi_0 + \tilde{\phi}`, `r = r_{eq} + \rho`, `\theta = \pi + \varphi`: the
 * text's new name for a coordinate's deviation from a point. From its row to the end of its section the new name is
 * the deviation (its time derivatives the coordinate's), and the point is a constant: the value the text gave the
 * point's name earlier (`r_{eq} = l_0 + \frac{mg}{k}`), else a constant of the text's own; approximations there are
 * expanded about the point (approximation.hpp). The row itself is a definition, not judged. */
#include "checker/checker_internals.hpp"

#include <cstring>

namespace eomgen::checker::detail {

namespace {

/// A name that can be a deviation or a point: no accent, no prime.
bool plain(const FreeName& f) {
    return f.kind == NameKind::Unknown && f.name.find("\\dot") == std::string::npos &&
           f.name.find("\\ddot") == std::string::npos && f.name.find('\'') == std::string::npos;
}

/// Whether the prose says a new variable is introduced: "let", "split", "put", "write", "deviation", "small",
/// "lineariz…" (as a word or the start of one). `ψ = π/2 − Ω` after "the rotation about the axis is" is a claim.
bool introduces_variable(const std::string& prose) {
    const auto letter = [](char ch) { return std::isalpha(static_cast<unsigned char>(ch)) != 0; };
    for (const char* cue : {"let", "put", "set", "write", "writing", "split", "substitut", "introduc", "defin",
                            "deviation", "displacement", "perturb", "small", "expand", "lineariz", "linearis", "shift",
                            "new variable", "new coordinate", "measured from"}) {
        const std::string w = cue;
        const bool whole = w == "let" || w == "put" || w == "set";
        for (std::size_t k = prose.find(w); k != std::string::npos; k = prose.find(w, k + 1)) {
            if (k > 0 && letter(prose[k - 1])) continue;
            if (whole && k + w.size() < prose.size() && letter(prose[k + w.size()])) continue;
            return true;
        }
    }
    return false;
}

/// Written like a point: `\phi_{0}`, `r_{eq}`, `x_{e}`, `\theta_{*}`.
bool named_like_point(const std::string& name) {
    for (const char* sub : {"_{0}", "_{eq}", "_{e}", "_{*}", "_{c}", "_{s}", "_{equilibrium}"})
        if (name.size() > std::strlen(sub) && name.compare(name.size() - std::strlen(sub), std::string::npos, sub) == 0)
            return true;
    return false;
}

}  // namespace

std::optional<GiNaC::ex> Checker::earlier_value(const std::vector<FullChain>& chains, const GiNaC::ex& name,
                                                std::size_t before, int* line) {
    std::optional<GiNaC::ex> found;
    for (const FullChain& c : chains) {
        if (c.sides.size() < 2 || c.relation_offsets.front() >= before) continue;
        if (!c.sides[0].side->ok) continue;
        // The name, or its cosine, sine or tangent (`\cos\alpha_0 = \frac{g}{R\omega^2}`, an equilibrium's angle):
        // the last value the text gives before `before`.
        const GiNaC::ex head = c.sides[0].side->value;
        const bool trig = head.nops() == 1 && head.op(0).is_equal(name) &&
                          (GiNaC::is_the_function<GiNaC::cos_SERIAL>(head) ||
                           GiNaC::is_the_function<GiNaC::sin_SERIAL>(head) ||
                           GiNaC::is_the_function<GiNaC::tan_SERIAL>(head));
        if (!head.is_equal(name) && !trig) continue;
        for (std::size_t k = c.sides.size(); k-- > 1;) {
            if (c.relations[k - 1] != Relation::Equal) break;
            const Prepared p = prepare(c.sides[k]);
            if (!p.comparable() || !p.units.empty() || p.value.has(name) || depends_on_state(p.value) ||
                has_acceleration(p.value) || p.value.has(model_.t))
                continue;
            found = !trig                                               ? p.value
                    : GiNaC::is_the_function<GiNaC::cos_SERIAL>(head) ? GiNaC::acos(p.value)
                    : GiNaC::is_the_function<GiNaC::sin_SERIAL>(head) ? GiNaC::asin(p.value)
                                                                        : GiNaC::atan(p.value);
            if (line) *line = d_.position(c.relation_offsets.front()).line;
            break;
        }
    }
    return found;
}

void Checker::collect_changes_of_variable(const std::vector<FullChain>& chains) {
    for (const FullChain& c : chains) {
        if (c.sides.size() != 2 || c.relations[0] != Relation::Equal) continue;
        const std::size_t at = c.relation_offsets[0];
        for (std::size_t qside = 0; qside < 2; ++qside) {
            const PSide& qs = c.sides[qside];
            const PSide& vs = c.sides[1 - qside];
            if (!qs.side->ok || !vs.side->ok) continue;
            std::size_t qi = model_.coordinates.size();
            for (std::size_t k = 0; k < model_.coordinates.size(); ++k)
                if (qs.side->value.is_equal(model_.coordinates[k].q)) qi = k;
            if (qi == model_.coordinates.size()) continue;
            // The value's free names: the deviation, and perhaps the point's name.
            std::vector<const FreeName*> names;
            for (std::vector<GiNaC::ex> stack{vs.side->value}; !stack.empty();) {
                const GiNaC::ex e = stack.back();
                stack.pop_back();
                for (std::size_t q = 0; q < e.nops(); ++q) stack.push_back(e.op(q));
                const FreeName* f = GiNaC::is_a<GiNaC::symbol>(e) ? ctx_.free_name_of(e) : nullptr;
                if (f && std::find(names.begin(), names.end(), f) == names.end()) names.push_back(f);
            }
            if (names.empty() || names.size() > 2 ||
                !std::all_of(names.begin(), names.end(), [](const FreeName* f) { return plain(*f); }))
                continue;
            const auto dotted = [&](const FreeName* f) {
                return ctx_.free_names.count("\\dot{" + f->name + "}") || ctx_.free_names.count("\\ddot{" + f->name + "}");
            };
            const FreeName* deviation = names.front();
            const FreeName* point_name = nullptr;
            if (names.size() == 2) {
                const bool d0 = dotted(names[0]), d1 = dotted(names[1]);
                const bool p0 = named_like_point(names[0]->name), p1 = named_like_point(names[1]->name);
                if (d0 != d1)
                    deviation = d0 ? names[0] : names[1];
                else if (p0 != p1)
                    deviation = p0 ? names[1] : names[0];
                else
                    continue;
                point_name = deviation == names[0] ? names[1] : names[0];
            }
            GiNaC::ex sigma, a;
            try {
                const GiNaC::ex v = vs.side->value.expand();
                if (v.degree(deviation->symbol) != 1 || v.ldegree(deviation->symbol) != 0) continue;
                sigma = v.coeff(deviation->symbol, 1);
                a = v.coeff(deviation->symbol, 0);
            } catch (const std::exception&) {
                continue;
            }
            if (!(sigma.is_equal(1) || sigma.is_equal(-1))) continue;
            if (depends_on_state(a) || has_acceleration(a) || a.has(model_.t)) continue;
            if (definitions_.value_at(deviation->symbol, at)) continue;  // the text's own quantity already
            const std::size_t begin = c.sides.front().base + c.sides.front().side->begin;
            const std::size_t end = c.sides.back().base + c.sides.back().side->end;
            if (!introduces_variable(lead_in(d_, begin, 1)) && !introduces_variable(sentence_around(d_.text, begin, end)))
                continue;
            const std::size_t until = c.section >= 0 ? d_.sections[std::size_t(c.section)].end : std::string::npos;
            const std::size_t section_begin = c.section >= 0 ? d_.sections[std::size_t(c.section)].begin : 0;
            const int line = d_.position(at).line;
            GiNaC::ex point = a;
            bool own = false;
            std::string about;
            if (point_name) {
                int given_line = 0;
                GiNaC::ex value;
                if (const std::optional<GiNaC::ex> given = earlier_value(chains, point_name->symbol, at, &given_line)) {
                    value = *given;
                    about = "$" + point_name->name + "$ as the text gives it on line " + std::to_string(given_line);
                } else {
                    // A constant of the text's own: a symbol of the checker's, with values at the sample points.
                    const GiNaC::symbol own_point(point_name->name + "__point", point_name->name);
                    numbers_.add_state_symbol(own_point);
                    value = own_point;
                    own = true;
                    about = "$" + point_name->name + "$, a constant";
                }
                point = a.subs(point_name->symbol == value);
                definitions_.add(point_name->symbol, point_name->name, value, at, line, until, latex(value),
                                 std::string::npos, false, nullptr, section_begin);
            } else {
                about = "$" + latex(a) + "$";
            }
            const Coordinate& q = model_.coordinates[qi];
            const GiNaC::ex deviation_value = sigma * (q.q - point);
            std::size_t head = std::string::npos;
            for (const NameUse& u : vs.side->uses)
                if (u.name == deviation->name) head = vs.base + u.offset;
            definitions_.add(deviation->symbol, deviation->name, deviation_value, at, line, until,
                             latex(deviation_value), head, false, nullptr, section_begin);
            const std::string point_latex = point_name ? point_name->name : latex(a);
            variable_changes_.push_back({at, until, qi, point, own, point_latex, deviation->name, sigma});
            variable_change_rows_[at] = "a change of variable: $" + deviation->name + "$ is $" +
                                        latex(deviation_value) + "$, the deviation of $" + q.latex + "$ from " +
                                        about + ", for the rest of its section (approximations there are " +
                                        "expanded about $" + q.latex + " = " + point_latex + "$)";
            break;
        }
    }
}

ExpansionPoints Checker::expansion_points(std::size_t at) const {
    ExpansionPoints e;
    if (variable_changes_.empty()) return e;
    const std::size_t n = model_.coordinates.size();
    e.at.assign(n, 0);
    e.own.assign(n, false);
    e.latex.assign(n, "");
    e.deviation.assign(n, "");
    for (const VariableChange& v : variable_changes_)
        if (at > v.from && at < v.until) {
            e.at[v.coordinate] = v.point;
            e.own[v.coordinate] = v.own;
            e.latex[v.coordinate] = v.point_latex;
            e.deviation[v.coordinate] = v.deviation;
            // q = point + sign·s, q̇ = sign·ṡ, q̈ = sign·s̈, in the text's names where it writes them.
            const Coordinate& q = model_.coordinates[v.coordinate];
            const auto name = ctx_.free_names.find(v.deviation);
            if (name == ctx_.free_names.end()) continue;
            e.in_text[q.q] = v.point + v.sign * name->second.symbol;
            for (const auto& [prefix, symbol] : {std::pair<std::string, GiNaC::symbol>{"\\dot{", q.qd}, {"\\ddot{", q.qdd}})
                if (const auto d = ctx_.free_names.find(prefix + v.deviation + "}"); d != ctx_.free_names.end())
                    e.in_text[symbol] = v.sign * d->second.symbol;
        }
    return e;
}

}  // namespace eomgen::checker::detail
