/** @file definitions.cpp  The text's definitions, substituted where the text differentiates a defined name. */
#include "checker/definitions.hpp"

#include "checker/latex_normalize.hpp"
#include "mechanics/lagrangian.hpp"

#include <algorithm>
#include <cstring>

namespace eomgen::checker {

void TextDefinitions::add(const GiNaC::ex& symbol, const std::string& name, const GiNaC::ex& value,
                          std::size_t offset, int line, std::size_t until, const std::string& source,
                          std::size_t head, bool conserved, const GiNaC::ex* value_holding,
                          std::size_t section_begin) {
    // A number (`\phi = 0`, `y' = 0`) is a condition or a particular value rather than an abbreviation: it is
    // used inside derivatives only.
    const bool abbreviation = !GiNaC::is_a<GiNaC::numeric>(value);
    Definition d{name, value, offset, line, abbreviation ? until : offset, source, head};
    d.conserved = conserved;
    d.section_begin = section_begin;
    d.value_holding = value_holding ? *value_holding : value;
    if (conserved) {
        held_values_[d.held] = value;
        held_notes_[d.held] = "holds $" + name + "$ fixed in the derivative by a coordinate: a constant of the motion "
                              "(line " + std::to_string(line) + ")";
    }
    defs_[symbol].push_back(d);
    if (head != std::string::npos && abbreviation)
        heads_.push_back({head, name + " = " + (source.empty() ? name : source)});
}

const TextDefinitions::Definition* TextDefinitions::in_force(const std::vector<Definition>& list, std::size_t at,
                                                            bool in_section) const {
    const Definition* best = nullptr;
    if (!list.empty() && suspended_.count(list.front().name)) return nullptr;
    if (override_active_ && !list.empty() && list.front().name == override_.name) return &override_;
    for (const Definition& d : list)
        if (d.offset < at && (!in_section || at < d.until) && (!best || d.offset > best->offset)) best = &d;
    if (!best && backward_)  // the last abbreviation before `at`, in an earlier section
        for (const Definition& d : list)
            if (d.offset < at && d.until > d.offset && (!best || d.offset > best->offset)) best = &d;
    if (!best && forward_)  // the first abbreviation after `at` in its section
        for (const Definition& d : list)
            if (d.offset > at && at >= d.section_begin && d.until > d.offset && at < d.until &&
                (!best || d.offset < best->offset))
                best = &d;
    return best;
}

GiNaC::ex TextDefinitions::abbreviate(const GiNaC::ex& e, std::size_t at) const {
    GiNaC::ex x = e;
    // `K = ...` again: a new definition of K, not a claim about the old one.
    if (!defined_at(at).empty()) return x;
    for (std::size_t round = 0; round <= defs_.size(); ++round) {  // definitions may use earlier ones
        GiNaC::exmap subs;
        for (const auto& [symbol, list] : defs_) {
            if (!x.has(symbol)) continue;
            const Definition* d = in_force(list, at, true);
            if (!d) continue;
            subs[symbol] = !holding_ ? d->value : (d->conserved ? GiNaC::ex(d->held) : d->value_holding);
            uses_.push_back({d->head, d->value, d->line});
            const std::string note = "using $" + d->name + " = " + (d->source.empty() ? d->name : d->source) +
                                     "$ (line " + std::to_string(d->line) +
                                     (d->corrected ? ", corrected: the text's does not follow" : "") + ")";
            if (std::find(abbreviations_.begin(), abbreviations_.end(), note) == abbreviations_.end())
                abbreviations_.push_back(note);
        }
        if (subs.empty()) break;
        x = x.subs(subs);
    }
    return x;
}

const GiNaC::ex* TextDefinitions::value_at(const GiNaC::ex& symbol, std::size_t at, int* line) const {
    const auto it = defs_.find(symbol);
    if (it == defs_.end()) return nullptr;
    const Definition* d = in_force(it->second, at, true);
    if (!d) return nullptr;
    if (line) *line = d->line;
    return &d->value;
}

bool TextDefinitions::corrected_at(const GiNaC::ex& symbol, std::size_t at) const {
    const auto it = defs_.find(symbol);
    if (it == defs_.end()) return false;
    const Definition* d = in_force(it->second, at, true);
    return d && d->corrected;
}

std::string TextDefinitions::defined_at(std::size_t head) const {
    for (const auto& [offset, shown] : heads_)
        if (offset == head) return shown;
    return "";
}

void TextDefinitions::override_with(const GiNaC::ex& symbol, const GiNaC::ex& value) {
    const auto it = defs_.find(symbol);
    if (it == defs_.end() || it->second.empty()) return;
    override_ = it->second.front();
    override_.value = override_.value_holding = value;
    override_.offset = 0;
    override_.until = std::string::npos;
    override_.conserved = false;
    override_active_ = true;
}

void TextDefinitions::correct(std::size_t head, const GiNaC::ex& value, const std::string& source) {
    for (auto& [symbol, list] : defs_)
        for (Definition& d : list)
            if (d.head == head && !d.conserved) {
                d.value = d.value_holding = value;
                d.source = source;
                d.corrected = true;
            }
}

void TextDefinitions::note_use(const GiNaC::ex& symbol, std::size_t at) const {
    const auto it = defs_.find(symbol);
    if (it == defs_.end()) return;
    if (const Definition* d = in_force(it->second, at, true)) uses_.push_back({d->head, d->value, d->line});
}

std::vector<std::string> TextDefinitions::take_abbreviations() const {
    std::vector<std::string> out;
    out.swap(abbreviations_);
    return out;
}

GiNaC::ex TextDefinitions::expand(const GiNaC::ex& operand, std::size_t at) const {
    return expand_impl(operand, at, nullptr);
}

GiNaC::ex TextDefinitions::expand_holding(const GiNaC::ex& operand, std::size_t at, GiNaC::exmap& held) const {
    return expand_impl(operand, at, &held);
}

GiNaC::ex TextDefinitions::expand_impl(const GiNaC::ex& operand, std::size_t at, GiNaC::exmap* held) const {
    GiNaC::ex e = operand;
    // A definition may use an earlier one: substitute until nothing changes (bounded: definitions come in
    // file order, and one of a name never uses itself).
    for (std::size_t round = 0; round <= defs_.size(); ++round) {
        GiNaC::exmap subs;
        for (const auto& [symbol, list] : defs_) {
            if (!e.has(symbol)) continue;
            const Definition* best = in_force(list, at, false);
            if (!best) continue;
            uses_.push_back({best->head, best->value, best->line});
            const std::string note =
                "uses $" + best->name + "$ as the text defines it at line " + std::to_string(best->line) +
                (best->corrected ? ", corrected (the text's does not follow)" : "");
            if (held && best->conserved) {
                subs[symbol] = best->held;
            } else {
                subs[symbol] = held ? best->value_holding : best->value;
            }
            if (std::find(used_.begin(), used_.end(), note) == used_.end()) used_.push_back(note);
        }
        if (subs.empty()) break;
        e = e.subs(subs);
    }
    if (held)
        for (const auto& [symbol, value] : held_values_)
            if (e.has(symbol)) {
                (*held)[symbol] = value;
                const std::string& note = held_notes_.at(symbol);
                if (std::find(used_.begin(), used_.end(), note) == used_.end()) used_.push_back(note);
            }
    return e;
}

namespace {

/// The first free name of `ctx` in `e` for which `pick` holds, or nullptr.
template <class Pick>
const FreeName* find_free_name(const GiNaC::ex& e, const LatexContext& ctx, Pick pick) {
    std::vector<GiNaC::ex> stack{e};
    while (!stack.empty()) {
        const GiNaC::ex x = stack.back();
        stack.pop_back();
        for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
        const FreeName* f = ctx.free_name_of(x);
        if (f && pick(*f)) return f;
    }
    return nullptr;
}

}  // namespace

bool TextDefinitions::has_vector(const GiNaC::ex& operand, const LatexContext& ctx) {
    return find_free_name(operand, ctx, [](const FreeName& f) { return f.kind == NameKind::Vector; }) != nullptr;
}

void TextDefinitions::require_defined(const GiNaC::ex& operand, const LatexContext& ctx, const std::string& what) {
    const FreeName* f = find_free_name(operand, ctx, [](const FreeName& n) {
        return n.kind != NameKind::Unit && !is_constant_name(n.name);
    });
    if (!f) return;
    throw UndefinedInDerivative(f->name, "the " + what + " of $" + f->name +
                                             "$, which the text does not define and the model does not know: "
                                             "not taken as a constant (its derivative would be 0)");
}

std::vector<std::string> TextDefinitions::take_used() const {
    std::vector<std::string> out;
    out.swap(used_);
    return out;
}

GiNaC::ex dotted_definitions(const TextDefinitions& definitions, const GiNaC::ex& e, std::size_t at,
                             const LatexContext& ctx, const Model& model, std::vector<std::string>& notes) {
    if (definitions.empty()) return e;
    GiNaC::exmap subs;
    std::vector<GiNaC::ex> stack{e};
    while (!stack.empty()) {
        const GiNaC::ex x = stack.back();
        stack.pop_back();
        for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
        if (!GiNaC::is_a<GiNaC::symbol>(x) || subs.count(x)) continue;
        const FreeName* f = ctx.free_name_of(x);
        if (!f || f->kind != NameKind::Unknown) continue;
        int order = 0;
        std::string inner;
        for (const auto& [prefix, k] : {std::pair<const char*, int>{"\\ddot{", 2}, {"\\dot{", 1}})
            if (f->name.rfind(prefix, 0) == 0 && f->name.back() == '}') {
                order = k;
                inner = f->name.substr(std::strlen(prefix), f->name.size() - std::strlen(prefix) - 1);
                break;
            }
        if (order == 0) continue;
        const auto named = ctx.free_names.find(inner);
        if (named == ctx.free_names.end()) continue;
        int line = 0;
        const GiNaC::ex* def = definitions.value_at(named->second.symbol, at, &line);
        if (!def) continue;
        GiNaC::ex value = definitions.abbreviate(*def, at);
        definitions.take_abbreviations();
        bool known = true;  // only a definition in the model's own quantities is differentiated
        for (std::vector<GiNaC::ex> st{value}; !st.empty() && known;) {
            const GiNaC::ex y = st.back();
            st.pop_back();
            if (GiNaC::is_a<GiNaC::symbol>(y) && ctx.free_name_of(y)) known = false;
            for (std::size_t i = 0; i < y.nops(); ++i) st.push_back(y.op(i));
        }
        if (!known) continue;
        for (int k = 0; k < order; ++k) value = time_derivative(value, model);
        subs[x] = value;
        definitions.note_use(named->second.symbol, at);
        notes.push_back("$" + f->name + "$ is the time derivative of $" + inner + "$ as the text defines it at line " +
                        std::to_string(line) +
                        (definitions.corrected_at(named->second.symbol, at)
                             ? ", corrected (the text's does not follow)"
                             : ""));
    }
    return subs.empty() ? e : e.subs(subs);
}


namespace {

bool evidently_nonnegative(const GiNaC::ex& e, const Model& model) {
    const auto parameter = [&](const GiNaC::ex& x) {
        return std::any_of(model.parameters.begin(), model.parameters.end(),
                           [&](const Parameter& p) { return x.is_equal(p.symbol); });
    };
    const auto factor = [&](const GiNaC::ex& f) {
        if (GiNaC::is_a<GiNaC::numeric>(f)) return GiNaC::ex_to<GiNaC::numeric>(f).is_positive();
        if (parameter(f)) return true;
        if (!GiNaC::is_a<GiNaC::power>(f) || !GiNaC::is_a<GiNaC::numeric>(f.op(1))) return false;
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(f.op(1));
        return (n.is_even() && n.is_positive()) || (parameter(f.op(0)) && n.is_rational());
    };
    const auto term = [&](const GiNaC::ex& t) {
        if (!GiNaC::is_a<GiNaC::mul>(t)) return factor(t);
        for (std::size_t i = 0; i < t.nops(); ++i)
            if (!factor(t.op(i))) return false;
        return true;
    };
    if (!GiNaC::is_a<GiNaC::add>(e)) return term(e);
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (!term(e.op(i))) return false;
    return true;
}

}  // namespace

bool speed_squared(const GiNaC::ex& e, const Model& model) {
    if (!evidently_nonnegative(e, model)) return false;
    try {
        // Factored, a sum must remain that is not squared: l^2(\dot\theta^2 + \sin^2\theta\,\dot\phi^2), not (l\dot\theta)^2.
        const GiNaC::ex f = GiNaC::factor(GiNaC::expand(e));
        const auto unsquared_sum = [](const GiNaC::ex& x) { return GiNaC::is_a<GiNaC::add>(x); };
        if (unsquared_sum(f)) return true;
        if (!GiNaC::is_a<GiNaC::mul>(f)) return false;
        for (std::size_t i = 0; i < f.nops(); ++i)
            if (unsquared_sum(f.op(i))) return true;
    } catch (const std::exception&) {
    }
    return false;
}

}  // namespace eomgen::checker
