/** @file stated_names.cpp  Names whose value is stated outside the text's own definitions: a symbol-map entry
 * (`--map I='m k^2'`, against which the text's `I = m(kR)^2` is compared), and the common value an assumption
 * names (`m` in `m_1 = m_2 = m`, which discourse.cpp pins). */
#include "checker/checker_internals.hpp"

namespace eomgen::checker::detail {

bool Checker::names_common_value(const FullChain& c, std::size_t j) const {
    const auto parameter = [&](const PSide& x) {
        return x.side->ok && std::any_of(model_.parameters.begin(), model_.parameters.end(),
                                         [&](const Parameter& p) { return x.side->value.is_equal(p.symbol); });
    };
    const PSide& last = c.sides[j];
    const bool new_name = last.side->ok && GiNaC::is_a<GiNaC::symbol>(last.side->value) &&
                          ctx_.free_name_of(last.side->value) != nullptr;
    return j + 1 == c.sides.size() && j >= 2 && new_name &&
           std::all_of(c.sides.begin(), c.sides.begin() + std::ptrdiff_t(j), parameter) &&
           discourse_->states_assumption(c.relation_offsets[j - 1]);
}

GiNaC::exmap Checker::parameter_assumptions(std::size_t at) const {
    GiNaC::exmap assumed;
    for (const auto& [symbol, stated] : discourse_->conditions_at(at))
        if (std::any_of(model_.parameters.begin(), model_.parameters.end(),
                        [&](const Parameter& q) { return symbol.is_equal(q.symbol); }))
            assumed[symbol] = stated.first;
    return assumed;
}

void Checker::collect_common_values(const std::vector<FullChain>& chains) {
    // A name the text wrote before the assumption is its own notation there (or a slip: misspelled_names.cpp).
    const auto used_before = [&](const std::string& name, std::size_t at) {
        for (const FullChain& c : chains)
            for (const PSide& s : c.sides)
                for (const NameUse& u : s.side->uses)
                    if (u.name == name && s.base + u.offset < at) return true;
        return false;
    };
    for (const Discourse::Condition& k : discourse_->conditions()) {
        // (A case the text looks at, "with $m_1 = m_2 = m$", keeps its common value a name of its paragraph, which
        // a line may still solve for: implication.cpp.)
        if (!k.setting || !discourse_->states_assumption(k.from) || !GiNaC::is_a<GiNaC::symbol>(k.value)) continue;
        const FreeName* f = ctx_.free_name_of(k.value);
        if (!f || f->kind != NameKind::Unknown || definitions_.value_at(k.value, k.from + 1)) continue;
        if (used_before(f->name, k.from)) continue;
        const auto p = std::find_if(model_.parameters.begin(), model_.parameters.end(),
                                    [&](const Parameter& q) { return k.symbol.is_equal(q.symbol); });
        if (p == model_.parameters.end()) continue;
        definitions_.add(k.value, f->name, p->symbol, k.from, k.line, k.until, p->latex.empty() ? p->name : p->latex);
        common_values_.push_back({k.value, p->symbol, k.from, k.until});
    }
}

Side Checker::with_common_values(const Side& side, std::size_t at) const {
    Side out = side;
    if (!out.ok) return out;
    for (const CommonValue& v : common_values_)
        if (v.from < at && at < v.until) out.value = out.value.subs(v.name == v.parameter);
    return out;
}

const MapEntry* Checker::map_entry_for(const PSide& s) const {
    const std::string name = canonical_name(trimmed(s.side->source));
    if (name.empty()) return nullptr;
    const int line = d_.position(s.base + s.side->begin).line;
    for (const MapEntry& e : options_.map)
        if (canonical_name(e.name) == name && (e.first_line == 0 || (line >= e.first_line && line <= e.last_line)))
            return &e;
    return nullptr;
}

bool Checker::check_against_map(const PSide& L, const PSide& R, const Prepared& a, const Prepared& b, double tol,
                                EquationCheck& r) {
    // As a definition of a name the model knows is (not a condition on the parameters).
    for (const bool left : {true, false}) {
        const PSide& named = left ? L : R;
        const Prepared& other = left ? b : a;
        const MapEntry* entry = map_entry_for(named);
        const GiNaC::ex mapped = left ? a.value : b.value;
        // (Not a value at an instant, `\phi = 0` at t = 0 with φ mapped to αt, nor a number the text picks.)
        if (!entry || depends_on_state(other.value) || has_acceleration(other.value) || other.value.has(model_.t) ||
            mapped.has(model_.t) || GiNaC::is_a<GiNaC::numeric>(other.value))
            continue;
        r.verdict = Verdict::Disagrees;
        r.compared_with = "the symbol map's " + m(entry->name + " = " + entry->value) + " (" + entry->origin + ")";
        r.reason = "the text's " + m(trimmed(named.side->source)) + " is not what the symbol map says it stands for";
        const Diagnosis dg = compare_to(other.value, mapped, tol);
        r.difference = dg.difference;
        r.wrong_terms = dg.lines;
        r.corrected = left ? L.side->source + " = " + latex(mapped) : latex(mapped) + " = " + R.side->source;
        return true;
    }
    return false;
}

}  // namespace eomgen::checker::detail
