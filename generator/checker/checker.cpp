/** @file checker.cpp  Equation by equation: the names and labels set up, the text's roles read (discourse.hpp),
 * its definitions and parts collected, every chain's links judged (compare_link.cpp) and the report put together. */
#include "checker/checker_internals.hpp"
#include "checker/text_macros.hpp"

namespace eomgen::checker {

int CheckReport::count(Verdict v) const {
    return int(std::count_if(equations.begin(), equations.end(),
                             [v](const EquationCheck& e) { return e.verdict == v; }));
}


namespace detail {


// ------------------------------------------------------------------------------------------------ setup

void Checker::setup_names() {
    ctx_.time = model_.t;
    ctx_.names["t"] = model_.t;
    ctx_.primes_are_time_derivatives = d_.text.find("\\dot") == std::string::npos;
    for (const Coordinate& c : model_.coordinates) {
        ctx_.coordinates.push_back(c.q);
        add_name(c.latex, c.q);
        add_name("\\dot{" + c.latex + "}", c.qd);
        add_name("\\ddot{" + c.latex + "}", c.qdd);
    }
    for (const Parameter& p : model_.parameters) add_name(p.latex, p.symbol);
    // \ell is how many texts typeset a length l (add_name keeps a model's own \ell).
    if (auto l = ctx_.names.find("l"); l != ctx_.names.end()) add_name("\\ell", l->second);

    // Labels for eomgen's quantities, unless the model uses the letter for something of its own.
    add_label("T", eq_.T, "T");
    add_label("V", eq_.V, "V");
    // U: the letter many texts use for the potential energy (a model's own U comes first). K for the kinetic
    // energy is not read so (a spring constant as often); KE and PE, the blogs' abbreviations, are.
    add_label("U", eq_.V, "V");
    add_label("KE", eq_.T, "T");
    add_label("PE", eq_.V, "V");
    add_label("L", eq_.L, "L");
    add_label("\\mathcal{L}", eq_.L, "L");
    add_label("\\mathscr{L}", eq_.L, "L");  // the script L some texts write for the Lagrangian
    add_label("E", eq_.T + eq_.V, "E = T + V");
    add_label("H", eq_.energy, "h");
    add_label("h", eq_.energy, "h");
    for (const char* b : {"H", "h"})
        if (truth_.count(ctx_.names.at(b))) bare_only_.insert(ctx_.names.at(b));
    std::vector<GiNaC::ex> momentum_labels;  // a model's own p_{q} is not a label: set_labels skips it
    for (std::size_t i = 0; i < model_.dof(); ++i) {
        std::string c = canonical_name(model_.coordinates[i].latex);
        if (c.empty()) c = model_.coordinates[i].latex;
        // The key as the text's p_{\theta_1} reads (a subscript inside a subscript is flattened).
        std::string key = canonical_name("p_{" + c + "}");
        if (key.empty()) key = "p_{" + c + "}";
        add_label(key, eq_.momenta[i], "p_{" + c + "}");
        momentum_labels.push_back(ctx_.names.at(key));
    }
    // The conserved quantities of symmetries (mechanics/noether.hpp): L_z of a particle on a sphere written in x, y, z.
    for (const ConservedQuantity& c : eq_.conserved) {
        if (c.name == "h" || c.name.rfind("p_", 0) == 0) continue;
        std::string key = canonical_name(c.latex);
        add_label(key.empty() ? c.latex : key, c.value, c.latex);
    }
    hamilton_.set_labels(momentum_labels, truth_.count(ctx_.names.at("H")) ? ctx_.names.at("H") : GiNaC::ex(0));
    // Declared results ([[results]]): their LaTeX stands for their closed form, before eomgen's own labels
    // (a result written 'T' is the closed form), after the model's coordinates and parameters.
    for (const Result& res : model_.results) {
        std::string c = canonical_name(res.latex);
        if (c.empty()) c = res.latex;
        auto it = ctx_.names.find(c);
        if (it != ctx_.names.end() && !truth_.count(it->second)) continue;  // a coordinate or a parameter
        const GiNaC::symbol s(c, c);
        ctx_.names[c] = s;
        truth_[s] = res.expr.expr;
        result_labels_.insert(s);
        label_what_[s] = "the declared result " + res.name + " (" + m(res.latex + " = " + latex(res.expr.expr)) +
                         (res.equals.empty() ? std::string(")")
                                             : ", verified against " + result_target_name(res) +
                                                   (res.on_constraints ? " on the constraints)" : ")"));
    }

    // h(0) and p(0) at the model's initial state, for the integrals of motion a derivation writes out.
    GiNaC::exmap init;
    init[model_.t] = 0;
    for (const Coordinate& c : model_.coordinates) {
        init[c.q] = exact_decimal(c.initial);
        init[c.qd] = exact_decimal(c.rate);
    }
    for (const ConservedQuantity& c : eq_.conserved)
        integrals_of_motion_.push_back(
            {c.value - c.value.subs(init),
             "the conservation of " + m(c.latex) + " with the model's initial state (" + c.reason + ")"});
    // A holonomic constraint's name is its function g(q, t) (`\frac{\partial f}{\partial\varphi}` of the constraint f),
    // unless the model uses the name for something else.
    for (const ConstraintEquations& k : eq_.constraints)
        if (!k.position.is_zero() && !ctx_.names.count(canonical_name(k.name))) add_name(k.name, k.position);
    // The constraints' multipliers: \lambda where there is one constraint, \lambda_{k} and \lambda_{name} (the model's
    // own names first); each takes a value per state, as it is a function of the state.
    for (std::size_t k = 0; k < eq_.constraints.size(); ++k) {
        const std::string& name = eq_.constraints[k].name;
        // (With one constraint the reports print it as the text writes it, λ.)
        const GiNaC::symbol s("lambda_" + name, eq_.constraints.size() == 1 ? std::string("\\lambda") : "\\lambda_{" + name + "}");
        multipliers_.push_back(s);
        numbers_.add_state_symbol(s);
        if (eq_.constraints.size() == 1) add_name("\\lambda", s);
        add_name("\\lambda_{" + std::to_string(k + 1) + "}", s);
        add_name("\\lambda_{" + name + "}", s);
        add_name("\\lambda_{\\text{" + name + "}}", s);
    }
    // The equations of motion: d/dt(∂L/∂q̇) − ∂L/∂q − Q = 0 (Q: generalized and dissipative forces).
    for (std::size_t i = 0; i < model_.dof(); ++i)
        motion_.push_back(i < eq_.generalized_forces.size()
                              ? eq_.euler_lagrange[i] - eq_.generalized_forces[i]
                              : eq_.euler_lagrange[i]);
}

void Checker::apply_map(int line) {
    std::vector<MapEntry> entries = options_.map;
    const std::size_t given = entries.size();  // the user's entries; then the text's meanings (never an error)
    entries.insert(entries.end(), meaning_map_.begin(), meaning_map_.end());
    for (std::size_t k = 0; k < entries.size(); ++k) {
        const MapEntry& e = entries[k];
        if (k >= given) {
            if (line == 0 || line < e.first_line || line > e.last_line) continue;
            const Side s = parse_expression(e.value, ctx_);
            if (s.ok) ctx_.names[canonical_name(e.name)] = s.value;
            continue;
        }
        if (line == 0 ? e.first_line != 0 : (e.first_line == 0 || line < e.first_line || line > e.last_line))
            continue;
        std::string name = canonical_name(e.name);
        // A bare word stands for \text{word}: the map key "Trod" names the text's \text{ Trod }.
        if (name.empty() && !e.name.empty() && std::all_of(e.name.begin(), e.name.end(), [](char ch) {
                return std::isalpha(static_cast<unsigned char>(ch));
            }))
            name = e.name;
        if (name.empty())
            throw CheckError(e.origin + ": '" + e.name +
                             "' is not a single LaTeX name (such as I_{0} or \\omega_{a})");
        const Side s = parse_expression(e.value, ctx_);
        if (!s.ok)
            throw CheckError(e.origin + ": cannot read '" + e.value + "' at column " +
                             std::to_string(s.error_offset + 1) + ": " + s.error);
        ctx_.names[name] = s.value;
    }
}

// ---------------------------------------------------------------------------------------------- checking

void Checker::add_label(const std::string& name, const GiNaC::ex& truth, const std::string& what) {
    const GiNaC::symbol s(name, name);
    if (auto own = ctx_.names.find(name); own != ctx_.names.end()) {  // the model's own names come first
        // (A parameter with the letter, a rod's length L, is still the label where only the label makes sense:
        // shadowed_labels.cpp.)
        if (std::any_of(model_.parameters.begin(), model_.parameters.end(),
                        [&](const Parameter& p) { return own->second.is_equal(p.symbol); }) &&
            !shadowed_labels_.count(own->second)) {
            shadowed_labels_[own->second] = ShadowedLabel{s, what};
            truth_[s] = truth;
            label_what_[s] = what;
        }
        return;
    }
    ctx_.names[name] = s;
    truth_[s] = truth;
    label_what_[s] = what;
}

void Checker::collect_definitions(const std::vector<FullChain>& chains) {
    // "lets $\ddot{x} = a_x$": a name first written on the right of `=` that the sentence introduces is defined by
    // the left side, in force after it to the end of the section; a value the text states for it later
    // (`a_y = -g`) is then a claim about it, not a new definition.
    std::set<std::string> named_on_the_right;
    const auto dotted_defined_name = [&](const std::string& name, std::size_t at) {
        const auto f = ctx_.free_names.find(name);
        if (f == ctx_.free_names.end() || (name.rfind("\\dot{", 0) != 0 && name.rfind("\\ddot{", 0) != 0))
            return false;
        std::vector<std::string> notes;
        const GiNaC::ex derivative = dotted_definitions(definitions_, f->second.symbol, at, ctx_, model_, notes);
        definitions_.take_uses();
        return !derivative.is_equal(f->second.symbol);
    };
    const auto name_on_the_right = [&](const FullChain& c) {
        if (c.sides.size() != 2 || c.relations[0] != Relation::Equal || !c.sides[1].side->ok) return false;
        const GiNaC::ex named = c.sides[1].side->value;
        const FreeName* f = GiNaC::is_a<GiNaC::symbol>(named) ? ctx_.free_name_of(named) : nullptr;
        if (!f || f->kind != NameKind::Unknown || is_part(named) || is_constant_name(f->name)) return false;
        const std::size_t at = c.sides[1].base + c.sides[1].side->begin;
        if (!introduces_name(d_, at) || definitions_.value_at(named, at)) return false;
        // (Never written before: a name the text used already is not introduced here.)
        for (const FullChain& e : chains)
            for (const PSide& s : e.sides)
                for (const NameUse& u : s.side->uses)
                    if (u.name == f->name && s.base + u.offset < at) return false;
        const Prepared p = prepare(c.sides[0]);
        if (!p.comparable() || !p.units.empty() || p.value.has(named)) return false;
        const std::size_t until = c.section >= 0 ? d_.sections[std::size_t(c.section)].end : std::string::npos;
        definitions_.add(named, f->name, p.value, at, d_.position(at).line, until, trimmed(c.sides[0].side->source),
                         c.sides[0].base + c.sides[0].side->begin, false, nullptr,
                         c.section >= 0 ? d_.sections[std::size_t(c.section)].begin : 0);
        named_on_the_right.insert(f->name);
        return true;
    };
    // After a condition (`s = \frac{1}{2h}`: "halfway along the first turn"), a value free of the state that the
    // paragraph gives a name (`y = r\cos\pi`) is that name's value at the point, not its definition: it holds
    // to the end of the paragraph only.
    for (const FullChain& c : chains) {
        if (c.sides.size() < 2 || !c.sides[0].side->ok) continue;
        if (name_on_the_right(c)) continue;
        // `\omega_0^2 = g/l`: the square of a name set to a constant (or to a speed squared) defines the name as its
        // positive root (a frequency, a rate), so that `\ddot\varphi + \omega_0^2 \sin\varphi = 0` after it is compared.
        const GiNaC::ex written = c.sides[0].side->value;
        const bool squared = GiNaC::is_a<GiNaC::power>(written) && written.op(1).is_equal(2) &&
                             GiNaC::is_a<GiNaC::symbol>(written.op(0));
        const GiNaC::ex head = squared ? written.op(0) : written;
        const FreeName* f = ctx_.free_name_of(head);
        if (!f || f->kind != NameKind::Unknown || is_part(head) || is_constant_name(f->name)) continue;
        if (named_on_the_right.count(f->name) &&
            definitions_.value_at(head, c.sides[0].base + c.sides[0].side->begin))
            continue;
        // `\dot{x_p} = …` after `x_p = x + L\sin\theta`: a claim about that definition's derivative
        // (check_derivative_of_definition), not a new name.
        if (dotted_defined_name(f->name, c.sides[0].base + c.sides[0].side->begin)) continue;
        for (std::size_t k = c.sides.size(); k-- > 1;) {
            // `\gamma < \omega_0`: only a side the name equals (every relation before it `=`) is its value.
            if (std::any_of(c.relations.begin(), c.relations.begin() + std::ptrdiff_t(k),
                            [](Relation rel) { return rel != Relation::Equal; }))
                continue;
            // `\ell := m r^2 \dot\theta \equiv \mathrm{const}`: the constant says that it is conserved, it is
            // not the definition.
            if (c.sides[k].side->ok && GiNaC::is_a<GiNaC::symbol>(c.sides[k].side->value))
                if (const FreeName* g = ctx_.free_name_of(c.sides[k].side->value); g && is_constant_name(g->name))
                    continue;
            Prepared p = prepare(c.sides[k]);
            if (!p.comparable() || !p.units.empty() || p.value.has(head)) continue;
            if (squared) {
                // A square stated again (`\omega_2^2 = k/M` after `\omega_2 = \sqrt{k/M}`) is a use.
                if (definitions_.value_at(head, c.sides[k].base + c.sides[k].side->begin)) break;
                // (A speed squared, `v^2 = \dot r^2 + r^2\dot\theta^2`, names the speed: its value is never negative.)
                if (has_acceleration(p.value) ||
                    ((depends_on_state(p.value) || p.value.has(model_.t)) && !speed_squared(p.value, model_)))
                    break;
                p.value = GiNaC::sqrt(p.value);
            }
            const std::size_t at = c.sides[k].base + c.sides[k].side->begin;
            std::size_t until = c.section >= 0 ? d_.sections[std::size_t(c.section)].end : std::string::npos;
            if (const std::size_t point = discourse_->condition_paragraph(at); point > 0 && !depends_on_state(p.value)) {
                until = std::min(until, point);
                at_a_point_.insert(c.sides[0].base + c.sides[0].side->begin);
            }
            const std::string source = trimmed(c.sides[k].side->source);
            // The value with the text's constants of the motion in it held (an effective potential in J).
            std::optional<GiNaC::ex> holding;
            if (definitions_.has_conserved()) {
                definitions_.set_holding(true);
                const Prepared h = prepare(c.sides[k]);
                definitions_.set_holding(false);
                if (h.ok && !h.value.has(head)) holding = squared ? GiNaC::sqrt(h.value) : h.value;
            }
            definitions_.add(head, f->name, p.value, in_force_from(c.sides[0].base + c.sides[0].side->begin, at),
                             d_.position(at).line, until,
                             squared ? "\\sqrt{" + source + "}" : c.sides[k].side->source,
                             c.sides[0].base + c.sides[0].side->begin, conserved_on_motion(p.value),
                             holding ? &*holding : nullptr,
                             c.section >= 0 ? d_.sections[std::size_t(c.section)].begin : 0);
            break;
        }
    }
}

bool Checker::conserved_on_motion(const GiNaC::ex& value) {
    if (!has_velocity(value)) return false;
    EquationCheck conserved;
    check_additive_constant(value, 0, 1, model_, *this, 1e-9, conserved);
    return conserved.verdict == Verdict::Agrees;
}

std::size_t Checker::in_force_from(std::size_t head, std::size_t at) const {
    // "…, where ω² = k/m", "where Q is the damper's force: Q = −c ẏ": the definition explains the formula before it,
    // in its own row (math before it there) or in the row before, and holds there too.
    if (!explains_formula_before(d_, head)) return at;
    std::size_t row = d_.rows.size();
    for (std::size_t r = 0; r < d_.rows.size() && d_.rows[r].offset <= head; ++r) row = r;
    if (row == d_.rows.size()) return at;
    const MathRow& here = d_.rows[row];
    // (From just before the row: a definition is in force after its offset, and the formula's first side may
    // start right at the row's.)
    const auto before_row = [](std::size_t offset) { return offset == 0 ? offset : offset - 1; };
    const std::size_t lead = d_.text.find_first_not_of(" \t\r\n", here.offset);
    if (lead != std::string::npos && lead < head) return before_row(here.offset);
    // The formula before: the row before, past inline mentions without a relation ("where $Q$ is").
    for (std::size_t r = row; r-- > 0;) {
        if (d_.rows[r].section != here.section) break;
        if (!d_.rows[r].display && d_.rows[r].text.find('=') == std::string::npos) continue;
        return before_row(d_.rows[r].offset);
    }
    return at;
}

void Checker::collect_parts(const std::vector<FullChain>& chains) {
    for (const FullChain& c : chains) {
        if (c.sides.size() < 2 || !c.sides[0].side->ok) continue;
        const GiNaC::ex head = c.sides[0].side->value;
        if (!is_part(head) || part_value_.count(head)) continue;
        for (std::size_t k = c.sides.size(); k-- > 1;) {
            Prepared p = prepare(c.sides[k], &head);
            if (!p.comparable() || !p.units.empty() || p.value.has(head) || p.has_part) continue;
            part_value_[head] = p.value;
            part_origin_[head] =
                "line " + std::to_string(d_.position(c.sides[k].base + c.sides[k].side->begin).line);
            break;
        }
    }
}

void Checker::check_chain(const FullChain& c, std::vector<EquationCheck>& out) {
    const std::size_t n = c.sides.size();
    std::vector<bool> comparable(n, false);
    for (std::size_t k = 0; k < n; ++k) {
        Prepared p = prepare(c.sides[k]);
        comparable[k] = p.comparable() || is_part(c.sides[k].side->value);
    }
    const std::size_t first = out.size();
    for (std::size_t k = 0; k + 1 < n; ++k) out.push_back(check_link_noting_uses(c, k, k + 1, false));
    // A name written only here where the model has a parameter of the same letter (misspelled_names.cpp).
    add_misspelled_names(c, comparable, first, out);
    // Across sides that cannot be compared (an integral over a region, an unknown function): compare the
    // comparable sides on either side of them, so that a claim is not lost behind a step the checker cannot
    // read.
    std::size_t last = n;
    for (std::size_t k = 0; k < n; ++k) {
        if (!comparable[k]) continue;
        if (last != n && k > last + 1) {
            bool all_equal = true;
            for (std::size_t q = last; q < k; ++q)
                all_equal = all_equal && c.relations[q] != Relation::Inequality && c.relations[q] != Relation::NotEqual;
            if (all_equal) out.push_back(check_link_noting_uses(c, last, k, true));
        }
        last = k;
    }
}

CheckReport Checker::run() {
    CheckReport report;
    report.model_path = model_.path;
    report.model_title = model_.title;
    report.derivation_path = d_.path;
    report.map = options_.map;
    const std::vector<int> selected = select_sections(d_, options_.sections);
    if (!options_.sections.empty() && selected.empty()) {
        std::string list;
        for (const Section& s : d_.sections) list += "\n  " + s.title;
        throw CheckError("no heading of " + d_.path + " contains '" + options_.sections.front() +
                         "'; headings:" + list);
    }
    const bool whole = options_.sections.empty();
    if (!whole)
        for (int k : selected) report.sections.push_back(d_.sections[std::size_t(k)].title);

    setup_names();
    apply_map();
    {  // "with L = m r² θ̇", in a sentence about the angular momentum: L is that from the next line on
        std::vector<const MathRow*> rows;
        for (const MathRow& row : d_.rows)
            if (row_selected(d_, row, selected, whole)) rows.push_back(&row);
        meanings_ = text_meanings(d_, rows);
        for (const TextMeaning& m : meanings_)
            meaning_map_.push_back({m.name, m.value, "the text, line " + std::to_string(m.line), m.line + 1,
                                    std::max(m.line + 1, m.last_line)});
        // "… is conserved; call it $\ell$": ℓ is that quantity from its line on (to the end of the section).
        for (const TextMeaning& m : prose_namings(d_, rows))
            meaning_map_.push_back({m.name, m.value, "the text, line " + std::to_string(m.line), m.line,
                                    std::max(m.line, m.last_line)});
    }

    // Pass 1: parse every selected row; rows that start with "=" continue the chain above them.
    struct Parsed {
        const MathRow* row;
        std::vector<Chain> chains;
    };
    std::vector<Parsed> parsed;
    for (const MathRow& row : d_.rows) {
        if (!row_selected(d_, row, selected, whole)) continue;
        // Entries scoped to some lines of the text apply while their rows are read.
        const std::size_t lead = std::min(row.text.find_first_not_of(" \t\r\n"), row.text.size());
        const int line = d_.position(row.offset + lead).line;
        const auto in_scope = [&](const MapEntry& e) {
            return e.first_line != 0 && line >= e.first_line && line <= e.last_line;
        };
        const bool scoped = std::any_of(options_.map.begin(), options_.map.end(), in_scope) ||
                            std::any_of(meaning_map_.begin(), meaning_map_.end(), in_scope);
        if (!scoped) {
            parsed.push_back({&row, parse_math(row.text, ctx_)});
            continue;
        }
        const auto saved = ctx_.names;
        apply_map(line);
        parsed.push_back({&row, parse_math(row.text, ctx_)});
        ctx_.names = saved;
    }
    // `L = T - V` with a rod's length L: the first side is the Lagrangian there (shadowed_labels.hpp).
    ExSet labels;
    for (const auto& [symbol, value] : truth_) labels.insert(symbol);
    for (Parsed& p : parsed)
        for (Chain& ch : p.chains) {
            if (ch.sides.size() < 2 || !ch.sides[0].ok) continue;
            std::vector<GiNaC::ex> others;
            for (std::size_t k = 1; k < ch.sides.size(); ++k)
                if (ch.sides[k].ok) others.push_back(ch.sides[k].value);
            if (const ShadowedLabel* l =
                    label_on_the_left(ch.sides[0].value, others, shadowed_labels_, labels, model_)) {
                ch.sides[0].notes.push_back(shadowed_label_note(ch.sides[0].value, *l));
                ch.sides[0].value = l->label;
            }
        }
    std::vector<FullChain> chains;
    const MathRow* previous_display = nullptr;
    for (const Parsed& p : parsed) {
        for (std::size_t k = 0; k < p.chains.size(); ++k) {
            const Chain& ch = p.chains[k];
            const bool continues =
                k == 0 && p.row->display && ch.sides.size() >= 2 && ch.sides[0].empty() && previous_display &&
                !chains.empty() && chains.back().display && chains.back().section == p.row->section && [&] {
                    const std::size_t from = previous_display->offset + previous_display->text.size();
                    for (std::size_t q = from; q < p.row->offset && q < d_.text.size(); ++q)
                        if (!std::isspace(static_cast<unsigned char>(d_.text[q])) &&
                            std::string("$\\[]").find(d_.text[q]) == std::string::npos)
                            return false;
                    return true;
                }();
            if (!continues) {
                FullChain f;
                f.section = p.row->section;
                f.display = p.row->display;
                f.sides.push_back({&ch.sides[0], p.row->offset});
                chains.push_back(f);
            }
            FullChain& f = chains.back();
            for (std::size_t s = 1; s < ch.sides.size(); ++s) {
                f.sides.push_back({&ch.sides[s], p.row->offset});
                f.relations.push_back(ch.relations[s - 1]);
                f.relation_offsets.push_back(p.row->offset + ch.relation_offsets[s - 1]);
            }
        }
        if (p.row->display) previous_display = p.row;
    }
    for (const TextProblem& tp : d_.problems) {
        MathRow at;
        at.offset = tp.offset;
        if (row_selected(d_, at, selected, whole)) report.problems.push_back({d_.position(tp.offset), tp.message});
    }
    {
        std::vector<DiscourseLink> links;
        for (const FullChain& c : chains) {
            std::vector<const Side*> sides;
            for (const PSide& s : c.sides) sides.push_back(s.side);
            for (std::size_t k = 0; k + 1 < c.sides.size(); ++k) {
                const std::size_t at = c.relation_offsets[k];
                const std::size_t blank = d_.text.find("\n\n", at);
                links.push_back({c.sides[k].side, c.sides[k + 1].side, c.relations[k], at,
                                 c.section >= 0 ? d_.sections[std::size_t(c.section)].end : d_.text.size(),
                                 blank == std::string::npos ? d_.text.size() : blank, paragraph_end(d_, at),
                                 c.sides[k].base + c.sides[k].side->begin, sides});
            }
        }
        LabelView labels;
        labels.value = [this](const GiNaC::ex& x) -> std::optional<GiNaC::ex> {
            const auto it = truth_.find(x);
            return it == truth_.end() ? std::nullopt : std::optional<GiNaC::ex>(it->second);
        };
        labels.is_momentum = [this](const GiNaC::ex& x) { return hamilton_.is_momentum(x); };
        labels.same = [this](const GiNaC::ex& x, const GiNaC::ex& y) { return equal(x, y, 1e-9) == Tri::Yes; };
        discourse_.emplace(links, model_, ctx_, d_, labels);
        discourse_->read_limits(d_, model_, ctx_, eq_.M);
    }
    for (const FullChain& c : chains) {  // T_0 = 2\pi\sqrt{l/g}: a period, not a part of T
        if (c.sides.size() < 2 || !c.sides[0].side->ok) continue;
        std::string name;
        if (!is_part(c.sides[0].side->value, &name) || name[0] != 'T') continue;
        for (std::size_t k = 1; k < c.sides.size(); ++k) {
            const Side& v = *c.sides[k].side;
            bool constant = v.ok && !v.value.is_zero() && !depends_on_state(v.value) && !has_acceleration(v.value);
            std::vector<GiNaC::ex> stack{v.ok ? v.value : GiNaC::ex(0)};
            while (constant && !stack.empty()) {
                const GiNaC::ex e = stack.back();
                stack.pop_back();
                if (ctx_.free_name_of(e) || truth_.count(e)) constant = false;
                for (std::size_t q = 0; q < e.nops(); ++q) stack.push_back(e.op(q));
            }
            if (constant) not_parts_.insert(name);
        }
    }
    collect_common_values(chains);  // first: the definitions' values may be written in them (`x_1 = l\sin\theta_1`)
    collect_definitions(chains);
    collect_changes_of_variable(chains);
    collect_named_constants(chains);
    for (const FullChain& c : chains)  // stated vectors and eigen-equations, used before and after their line
        for (std::size_t k = 0; k + 1 < c.sides.size(); ++k)
            if (c.relations[k] == Relation::Equal)
                algebra_.note_link(*c.sides[k].side, c.sides[k].base, *c.sides[k + 1].side, c.sides[k + 1].base);
    // Where the text first writes H = (an expression in velocities, without momenta).
    for (const FullChain& c : chains) {
        if (c.sides.size() < 2 || !c.sides[0].side->ok || !hamilton_.is_hamiltonian(c.sides[0].side->value)) continue;
        const Prepared p = prepare(c.sides.back());
        if (!p.comparable() || p.has_momenta || !has_velocity(p.value)) continue;
        velocity_h_at_ = c.relation_offsets.front();
        velocity_h_line_ = d_.position(velocity_h_at_).line;
        break;
    }
    collect_parts(chains);
    collect_positions(chains);
    all_chains_ = &chains;
    for (const FullChain& c : chains) {
        if (c.sides.size() < 2) continue;  // an expression, not an equation
        check_chain(c, report.equations);
    }
    all_chains_ = nullptr;
    apply_blames(report.equations);
    apply_confirmations(report.equations);
    {  // never silent: a row with a relation that gave no equation is "not read", with the reason
        std::vector<const MathRow*> read;
        for (const Parsed& p : parsed) read.push_back(p.row);
        for (EquationCheck& e : unread_rows(d_, read, report.equations)) report.equations.push_back(std::move(e));
    }
    std::stable_sort(report.equations.begin(), report.equations.end(),
                     [](const EquationCheck& x, const EquationCheck& y) {
                         return std::make_pair(x.where.line, x.where.column) <
                                std::make_pair(y.where.line, y.where.column);
                     });
    return report;
}

}  // namespace detail

CheckReport check_derivation(const Model& model, const Equations& eq, const Derivation& derivation,
                             const CheckOptions& options) {
    const latex::TextMacroScope macros(derivation.macros);  // the text's \newcommand's, read as their bodies
    detail::Checker c(model, eq, derivation, options);
    return c.run();
}

}  // namespace eomgen::checker
