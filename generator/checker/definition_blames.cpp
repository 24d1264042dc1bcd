/** @file definition_blames.cpp  A definition its uses make wrong: a link that disagrees where one side is eomgen's (a
 * label: `T = \frac12 m v^2`) says what the text's defined name must be there; when the other uses agree with that
 * value too, the definition is what disagrees, corrected to it, and its uses are said to hold with it (issue 28:
 * "a wrong definition is flagged, not adopted silently"). */
#include "checker/checker_internals.hpp"

namespace eomgen::checker::detail {

void Checker::blame_definition(const FullChain& c, std::size_t i, std::size_t j, const EquationCheck& r) {
    const PSide* sides[2] = {&c.sides[i], &c.sides[j]};
    // The one defined name the link uses, on one side only.
    int text_side = -1;
    const FreeName* name = nullptr;
    int line = 0;
    GiNaC::ex definition;
    for (int k = 0; k < 2; ++k) {
        const PSide& s = *sides[k];
        if (!s.side->ok) return;
        std::vector<GiNaC::ex> stack{s.side->value};
        while (!stack.empty()) {
            const GiNaC::ex e = stack.back();
            stack.pop_back();
            for (std::size_t q = 0; q < e.nops(); ++q) stack.push_back(e.op(q));
            const FreeName* f = ctx_.free_name_of(e);
            int at_line = 0;
            const GiNaC::ex* value = f ? definitions_.value_at(e, s.base + s.side->begin, &at_line) : nullptr;
            if (!value) continue;
            if (name && (name != f || text_side != k)) return;  // two names, or on both sides
            name = f;
            text_side = k;
            line = at_line;
            definition = *value;
        }
    }
    if (!name) return;
    // The other side is eomgen's value: a label, or the chain's right side that equals what the chain is about.
    const Prepared trusted = prepare(*sides[1 - text_side]);
    const bool right_is_right = std::any_of(r.notes.begin(), r.notes.end(), [](const std::string& n) {
        return n.rfind("the right side is right", 0) == 0;
    });
    if (!trusted.comparable() || !(trusted.has_truth_label || (right_is_right && text_side == 0))) return;
    definitions_.suspend(name->name);
    const Prepared free = prepare(*sides[text_side]);
    definitions_.resume();
    if (!free.ok) return;
    try {
        const GiNaC::ex e = (free.value - trusted.value).expand();
        const GiNaC::ex& v = name->symbol;
        // `T = \frac12 m v^2` after `v^2 = …`: a use in the square of a speed says what the square must be.
        const bool squared = e.degree(v) == 2 && e.ldegree(v) == 0 && e.coeff(v, 1).is_zero();
        if (e.degree(v) != 1 && !squared) return;
        const GiNaC::ex needed = squared ? GiNaC::sqrt(GiNaC::normal(-e.coeff(v, 0) / e.coeff(v, 2)))
                                         : GiNaC::normal(-e.coeff(v, 0) / e.coeff(v, 1));
        if (needed.has(v) || equal(needed, definition, 1e-9) == Tri::Yes) return;
        Blame b{name->name, needed, line, r.where, r.equation};
        b.squared = squared;
        blames_.push_back(std::move(b));
    } catch (...) {
    }
}

void Checker::note_disagreeing_uses(const FullChain& c, std::size_t i, std::size_t j, const EquationCheck& r) {
    std::set<std::string> seen;
    for (const std::size_t k : {i, j}) {
        const PSide& s = c.sides[k];
        if (!s.side->ok) continue;
        for (std::vector<GiNaC::ex> stack{s.side->value}; !stack.empty();) {
            const GiNaC::ex e = stack.back();
            stack.pop_back();
            for (std::size_t q = 0; q < e.nops(); ++q) stack.push_back(e.op(q));
            const FreeName* f = ctx_.free_name_of(e);
            if (!f || seen.count(f->name) || !definitions_.value_at(e, s.base + s.side->begin)) continue;
            seen.insert(f->name);
            disagreeing_uses_.push_back({f->name, e, c, i, j, r.where, r.equation});
        }
    }
}

void Checker::apply_blames(std::vector<EquationCheck>& equations) {
    std::set<std::string> names;
    for (const Blame& b : blames_) names.insert(b.name);
    for (const std::string& name : names) {
        std::vector<const Blame*> these;
        for (const Blame& b : blames_)
            if (b.name == name) these.push_back(&b);
        // One bare use that says what the name must be, and other disagreeing uses (inside ∂/∂q, say) that agree
        // once the name is that: they blame it alike.
        std::vector<const DisagreeingUse*> confirming;
        if (these.size() == 1) {
            const Blame& only = *these.front();
            bool all = false;
            for (const DisagreeingUse& u : disagreeing_uses_) {
                if (u.name != name || (u.where.line == only.where.line && u.where.column == only.where.column)) continue;
                definitions_.override_with(u.symbol, only.needed);
                const bool was = verifying_;
                verifying_ = true;
                const EquationCheck again = safe_check_link(u.chain, u.i, u.j, false);
                verifying_ = was;
                definitions_.reset_override();
                all = again.verdict == Verdict::Agrees && (confirming.empty() || all);
                if (!all) break;
                confirming.push_back(&u);
            }
            if (!all || confirming.empty()) continue;
        } else if (these.size() < 2) {
            continue;
        }
        bool alike = true;
        for (const Blame* b : these) alike = alike && equal(b->needed, these.front()->needed, 1e-9) == Tri::Yes;
        if (!alike) continue;
        const Blame& first = *these.front();
        const std::string prefix = "a definition: the text's abbreviation $" + name + " = ";
        EquationCheck* def = nullptr;
        for (EquationCheck& e : equations)
            if (e.where.line == first.definition_line && e.reason.find(prefix) != std::string::npos) def = &e;
        if (!def) continue;
        std::string lines;
        struct Use {
            SourcePos where;
            std::string equation;
            bool forward;
        };
        std::vector<Use> uses;
        for (const Blame* b : these) uses.push_back({b->where, b->equation, b->forward});
        for (const DisagreeingUse* u : confirming) uses.push_back({u->where, u->equation, u->forward});
        for (const auto& [where, equation, forward] : uses) {
            const std::string l = std::to_string(where.line);
            if (lines.find(l) == std::string::npos) lines += (lines.empty() ? "" : ", ") + l;
        }
        // (A speed squared is said as the text writes it, `v^2 = …`.)
        const std::string needed = latex(first.needed), named = first.squared ? name + "^2" : name,
                          named_value = first.squared ? latex(GiNaC::normal(GiNaC::pow(first.needed, 2))) : needed;
        def->verdict = Verdict::Disagrees;
        def->reason = "the text's definition of $" + name + "$, which its uses make wrong";
        def->compared_with = "what its uses on line " + lines + " need, where the other side is eomgen's";
        def->wrong_terms = {"with this $" + name + "$ the lines that use it disagree with eomgen; they hold with $" +
                            named + " = " + named_value + "$"};
        def->corrected = named + " = " + named_value;
        // (A use before a later definition was not comparable: it is said so too.)
        for (const auto& [where, equation, forward] : uses)
            for (EquationCheck& e : equations)
                if (e.where.line == where.line && e.where.column == where.column && e.equation == equation &&
                    (e.verdict == Verdict::Disagrees || (forward && e.verdict == Verdict::NotComparable))) {
                    e.verdict = Verdict::NotComparable;
                    e.reason = "it holds with $" + named + " = " + named_value + "$: the text's $" + name + "$ of line " +
                               std::to_string(first.definition_line) + " is what disagrees (see there)";
                    e.difference.clear();
                    e.wrong_terms.clear();
                    e.corrected.clear();
                }
    }
}

}  // namespace eomgen::checker::detail
