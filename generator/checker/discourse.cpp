/** @file discourse.cpp  The conditions, namings, trial solutions and stated frequencies of a text. */
#include "checker/discourse.hpp"
#include "checker/conditions.hpp"
#include "checker/state_symbols.hpp"

#include "checker/prose.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <utility>

namespace eomgen::checker {

namespace {

/// Whether e holds a name the text uses without a known meaning.
bool has_free_name(const GiNaC::ex& e, const LatexContext& ctx) {
    if (ctx.free_name_of(e)) return true;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (has_free_name(e.op(i), ctx)) return true;
    return false;
}

/// e with `from` replaced by `to`, except inside ∂·/∂· (where a letter keeps the meaning the derivative gives it:
/// ∂L/∂q̇ differentiates the Lagrangian whatever else the text calls L).
GiNaC::ex replace_outside_partials(const GiNaC::ex& e, const GiNaC::ex& from, const GiNaC::ex& to) {
    if (is_ex_the_function(e, pdiff)) return e;
    if (e.is_equal(from)) return to;
    if (e.nops() == 0) return e;
    struct Each : GiNaC::map_function {
        const GiNaC::ex &from, &to;
        Each(const GiNaC::ex& f, const GiNaC::ex& t) : from(f), to(t) {}
        GiNaC::ex operator()(const GiNaC::ex& x) override { return replace_outside_partials(x, from, to); }
    } each(from, to);
    return e.map(each);
}

/// Whether e holds a label (T, H, p_θ: its value depends on the state) or an operator left for the checker (∂, d/dt).
bool has_label_or_operator(const GiNaC::ex& e, const LabelView& labels) {
    if (is_ex_the_function(e, pdiff) || is_ex_the_function(e, ddt) || is_ex_the_function(e, pbracket)) return true;
    if (GiNaC::is_a<GiNaC::symbol>(e)) return labels.value(e).has_value();
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (has_label_or_operator(e.op(i), labels)) return true;
    return false;
}

/// Words of a sentence about a motion whose accelerations vanish or are set (lower case).
constexpr const char* kSteady[] = {"equilibrium", "equilibria", "at rest", "steady", "stationary", "uniform",
                                   "conical", "circular orbit", "constant speed", "constant rate"};

}  // namespace

std::string condition_of(const GiNaC::ex& a, const GiNaC::ex& b, const Model& model, GiNaC::ex* symbol,
                         GiNaC::ex* value) {
    for (const auto& [x, y] : {std::pair(a, b), std::pair(b, a)})
        for (const Coordinate& c : model.coordinates)
            if ((x.is_equal(c.q) || x.is_equal(c.qd)) && !holds_state(y, model) && !y.has(model.t)) {
                if (symbol) *symbol = x;
                if (value) *value = y;
                return x.is_equal(c.q) ? c.latex : "\\dot{" + c.latex + "}";
            }
    return "";
}

Discourse::Discourse(const std::vector<DiscourseLink>& links, const Model& model, LatexContext& ctx,
                     const Derivation& d, const LabelView& labels) {
    const std::vector<std::string> letters{"L", "H", "h", "E", "T", "V"};
    for (const DiscourseLink& link : links) {
        const Side &x = *link.left, &y = *link.right;
        if (!x.ok || !y.ok || link.relation != Relation::Equal) continue;
        const int line = d.position(link.at).line;
        // A condition: `s = \frac{1}{2h}` "halfway along the first turn".
        GiNaC::ex q, v;
        if (!has_free_name(x.value, ctx) && !has_free_name(y.value, ctx) && !has_label_or_operator(x.value, labels) &&
            !has_label_or_operator(y.value, labels)) {
            // "linearizing about $\theta = 0$", "expanding around $x = 0$": the point of an expansion, not a condition
            // the equations after it hold at.
            const bool expansion_point = !lead_in_ends_with(d, link.at, {"about", "around", "near"}).empty();
            if (!expansion_point && !condition_of(x.value, y.value, model, &q, &v).empty()) {
                bool position = false;
                for (const Coordinate& c : model.coordinates) position = position || q.is_equal(c.q);
                conditions_.push_back({q, v, link.at, link.paragraph, line, position});
            }
            // θ̈ = 0 after θ̇ = 0 (or θ = θ₀) in its paragraph, or in a sentence about an equilibrium or a steady
            // motion ("at equilibrium $\ddot x = 0$"): the acceleration of the motion the text considers.
            // ("Equilibria: $\ddot\alpha = 0$ gives …": a heading with a colon is the sentence's subject.)
            std::string sentence = lead_in(d, link.at, 1);
            if (std::none_of(sentence.begin(), sentence.end(), [](char ch) { return std::isalpha(static_cast<unsigned char>(ch)); }))
                sentence = lead_in(d, link.at, 2);
            // "Setting θ̈ = 0 and θ̇ = 0": an acceleration the words right before set is a condition too (not
            // "putting (1) into (2) and simplifying: …").
            const bool steady = std::any_of(std::begin(kSteady), std::end(kSteady), [&](const char* w) {
                                    return sentence.find(w) != std::string::npos;
                                }) ||
                                !lead_in_ends_with(d, link.at, {"setting", "putting", "we set", "set", "put"}).empty();
            auto acceleration_set = [&](const GiNaC::ex& a, const GiNaC::ex& b) {
                for (const Coordinate& c : model.coordinates)
                    if (a.is_equal(c.qdd) && !holds_state(b, model) && !b.has(model.t) &&
                        (steady || std::any_of(conditions_.begin(), conditions_.end(), [&](const Condition& k) {
                             return (k.symbol.is_equal(c.q) || k.symbol.is_equal(c.qd)) && k.from < link.at &&
                                    link.at < k.until;
                         })))
                        return true;
                return false;
            };
            for (const auto& [a, b] : {std::pair(x.value, y.value), std::pair(y.value, x.value)})
                if (acceleration_set(a, b)) conditions_.push_back({a, b, link.at, link.paragraph, line, false});
            // `\dot r = \dot	heta = 0`, `\ddot r = \ddot	heta = 0`: a chain of the state's quantities ending in a
            // value sets each of them to it; its links between two of them are conditions too, not equations.
            const Side* end = link.chain.empty() ? nullptr : link.chain.back();
            const bool both_state = state_symbol(x.value, model) && state_symbol(y.value, model);
            if (both_state && end && end->ok && end != &y && !holds_state(end->value, model) && !end->value.has(model.t) &&
                !has_free_name(end->value, ctx) && !has_label_or_operator(end->value, labels) &&
                std::all_of(link.chain.begin(), link.chain.end() - 1,
                            [&](const Side* s) { return s->ok && state_symbol(s->value, model); }))
                for (const GiNaC::ex& a : {x.value, y.value}) {
                    GiNaC::ex q, v;
                    if (!condition_of(a, end->value, model, &q, &v).empty()) {
                        bool position = false;
                        for (const Coordinate& c : model.coordinates) position = position || q.is_equal(c.q);
                        conditions_.push_back({q, v, link.at, link.paragraph, line, position});
                    } else if (acceleration_set(a, end->value)) {
                        conditions_.push_back({a, end->value, link.at, link.paragraph, line, false});
                    }
                }
        }
        // `m_1 = m_2`, `m_1 = m_2 = m`: an assumption on the parameters, for the rest of the paragraph (a
        // parameter set to a number is a value the text chooses: printed_numbers.hpp).
        for (const auto& [p, w] : {std::pair(&x, &y), std::pair(&y, &x)}) {
            const bool parameter = std::any_of(model.parameters.begin(), model.parameters.end(),
                                               [&](const Parameter& q) { return p->value.is_equal(q.symbol); });
            if (!parameter || w->value.has(p->value) || GiNaC::is_a<GiNaC::numeric>(w->value) ||
                holds_state(w->value, model) || w->value.has(model.t) || has_label_or_operator(w->value, labels))
                continue;
            // "Take $m_1 = m_2 = m$", "assume", "let", "suppose": the problem's setting, for the rest of the section;
            // "with $m_1 = m_2$ …" (a case it looks at) for its paragraph.
            const std::string cue = condition_cue(d, link.at);
            const bool setting = cue == "take" || cue == "taking" || cue == "let" || cue == "assume" ||
                                 cue == "assuming" || cue == "suppose" || cue == "set" || cue == "setting";
            conditions_.push_back({p->value, w->value, link.at, setting ? link.until : link.paragraph, line, false});
            conditions_.back().setting = setting;
            assumptions_.insert(link.at);
            break;
        }
        // `p_\theta = L`: a momentum set equal to a one-letter label of another quantity names it with that letter
        // (L the angular momentum about P): two of eomgen's quantities equal as a claim is not what such a line says.
        for (const auto& [p, l] : {std::pair(&x, &y), std::pair(&y, &x)}) {
            if (!labels.is_momentum(p->value)) continue;
            const std::optional<GiNaC::ex> pv = labels.value(p->value);
            if (!pv) continue;
            for (const std::string& name : letters) {
                const auto it = ctx.names.find(name);
                if (it == ctx.names.end() || !l->value.is_equal(it->second)) continue;
                const std::optional<GiNaC::ex> lv = labels.value(it->second);
                if (!lv || labels.same(*pv, *lv)) continue;
                namings_.push_back({it->second, p->value, name, p->source, link.at, link.until, line});
            }
        }
        // `\omega_3^2 = …`, `\omega_2 = \sqrt{k/M}`: a frequency of the text set to a value in the parameters.
        for (const auto& [f, w] : {std::pair(&x, &y), std::pair(&y, &x)}) {
            GiNaC::ex base = f->value;
            const bool squared = GiNaC::is_a<GiNaC::power>(base) && base.op(1).is_equal(2);
            if (squared) base = base.op(0);
            const FreeName* fn = ctx.free_name_of(base);
            if (!fn || fn->name.rfind("\\omega", 0) != 0) continue;
            if (holds_state(w->value, model) || w->value.has(model.t) || has_free_name(w->value, ctx)) continue;
            stated_.push_back({link.at, link.until, squared ? w->value : w->value * w->value, base});
        }
        // `\varphi = e^{\lambda t}`: the exponent's equation follows (characteristic_equation.hpp).
        if (std::optional<ExponentialTrial> e = exponential_trial(x.value, y.value, model, ctx)) {
            e->from = link.at;
            e->until = link.until;
            e->line = line;
            exponentials_.push_back(*e);
            trial_links_.insert(link.at);
            continue;
        }
        // A trial solution; those of one coordinate each with one frequency are one. With a frequency the text has
        // stated (`\omega^2 = g/l`, then `\theta(t) = \theta_0\cos(\omega t)`) it is a solution it claims instead.
        std::optional<TrialSolution> t = trial_solution(x.value, y.value, model, ctx);
        if (!t || stated_frequencies(link.at).count(t->omega)) continue;
        t->from = link.at;
        t->until = link.until;
        t->line = line;
        t->source = x.source + " = " + y.source;
        trial_links_.insert(link.at);
        if (!trials_.empty() && trials_.back().omega.is_equal(t->omega) && trials_.back().until == t->until) {
            TrialSolution& last = trials_.back();
            for (std::size_t k = 0; k < t->amplitude.size(); ++k)
                if (last.amplitude[k].is_zero()) last.amplitude[k] = t->amplitude[k];
            continue;
        }
        trials_.push_back(*t);
    }
    // The conditions of a steady motion or an equilibrium (an acceleration set, with the state conditions of its
    // paragraph) hold for the displays the paragraph runs on into; an initial state or an assumption holds in its
    // paragraph only ("In the initial position, $\psi = 0$. Since the energy is conserved," then E(ψ, ψ̇) = E(0)).
    std::map<std::size_t, std::size_t> runs_on;
    for (const DiscourseLink& link : links) runs_on[link.at] = std::max(link.runs_on, link.paragraph);
    std::set<std::size_t> steady;
    for (const Condition& k : conditions_)
        for (const Coordinate& c : model.coordinates)
            if (k.symbol.is_equal(c.qdd)) steady.insert(k.until);
    for (Condition& k : conditions_)
        if (steady.count(k.until) && !k.limit && state_symbol(k.symbol, model)) k.until = runs_on[k.from];
}

std::map<GiNaC::ex, std::pair<GiNaC::ex, int>, GiNaC::ex_is_less> Discourse::conditions_at(std::size_t at) const {
    std::map<GiNaC::ex, std::pair<GiNaC::ex, int>, GiNaC::ex_is_less> out;
    for (const Condition& k : conditions_)  // in file order: a later one replaces an earlier one
        if (k.from < at && at < k.until) {
            const auto it = out.find(k.symbol);
            if (it == out.end() || !it->second.first.is_equal(k.value)) out[k.symbol] = {k.value, k.line};
        }
    return out;
}

std::size_t Discourse::condition_paragraph(std::size_t at) const {
    std::size_t end = 0;
    for (const Condition& k : conditions_)
        if (k.from < at && at < k.until && k.is_position) end = std::max(end, k.until);
    return end;
}

GiNaC::exmap Discourse::stated_frequencies(std::size_t at) const {
    GiNaC::exmap out;
    for (const Stated& s : stated_)
        if (s.at < at && at < s.until) out[s.symbol] = GiNaC::sqrt(s.omega2);
    return out;
}

const Discourse::Naming* Discourse::naming_at(std::size_t at) const {
    for (const Naming& n : namings_)
        if (n.from == at) return &n;
    return nullptr;
}

GiNaC::ex Discourse::renamed(const GiNaC::ex& e, std::size_t at, std::vector<std::string>& notes) const {
    GiNaC::ex v = e;
    for (const Naming& n : namings_)
        if (n.from < at && at < n.until && v.has(n.letter)) {
            const GiNaC::ex w = replace_outside_partials(v, n.letter, n.quantity);
            if (w.is_equal(v)) continue;
            v = w;
            notes.push_back("reads $" + n.letter_latex + "$ as $" + n.quantity_latex +
                            "$, as the text names it on line " + std::to_string(n.line));
        }
    return v;
}

const TrialSolution* Discourse::trial_at(std::size_t at) const {
    const TrialSolution* found = nullptr;
    for (const TrialSolution& t : trials_)
        if (t.from < at && at < t.until) found = &t;
    return found;
}

const ExponentialTrial* Discourse::exponential_at(std::size_t at) const {
    const ExponentialTrial* found = nullptr;
    for (const ExponentialTrial& t : exponentials_)
        if (t.from < at && at < t.until) found = &t;
    return found;
}

std::optional<GiNaC::ex> Discourse::stated_frequency(std::size_t at) const {
    std::optional<GiNaC::ex> last;
    for (const Stated& s : stated_)
        if (s.at < at && at < s.until) last = s.omega2;
    return last;
}

}  // namespace eomgen::checker
