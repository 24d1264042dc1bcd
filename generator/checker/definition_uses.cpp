/** @file definition_uses.cpp  The text's definitions of quantities of the motion (`x_1 = l_1\sin\theta_1`, the
 * positions of the masses) confirmed by the rows that use them: a definition is not a claim by itself, but once a
 * row that puts it in agrees with eomgen's T, V, L or an equation of motion, the definition is consistent with the
 * model, and the report says so at its row. (One that makes its uses disagree is blamed instead: checker.cpp.)
 * Here too the link's second readings when the first could not compare it: a generic coordinate
 * (generic_coordinate.cpp) and a value the text gives a name only later in its section. */
#include "checker/checker_internals.hpp"

namespace eomgen::checker::detail {

namespace {

/// Compared with one of eomgen's quantities (T, an Euler–Lagrange equation, ...), not with the text's own sides.
bool compared_with_model(const EquationCheck& r) {
    return r.verdict == Verdict::Agrees && !r.compared_with.empty() && r.compared_with.rfind("an identity", 0) != 0;
}

}  // namespace

EquationCheck Checker::check_link_noting_uses(const FullChain& c, std::size_t i, std::size_t j, bool bridge) {
    definitions_.take_uses();
    EquationCheck r = safe_check_link(c, i, j, bridge);
    if (r.verdict == Verdict::NotComparable && r.reason.rfind("a partial derivative with respect to", 0) == 0)
        check_generic_coordinate(c, i, j, bridge, r);
    // A name the text gives a value only later in the section: taken so where that makes the link agree, and only
    // there (a later wrong value is the definition's slip, not this link's: blamed at the definition when its uses
    // need another value alike, apply_blames).
    if (r.verdict == Verdict::NotComparable && (r.reason.rfind("unknown symbol", 0) == 0 ||
                                               r.reason.rfind("the partial derivative of", 0) == 0 ||
                                               r.reason.rfind("the time derivative of", 0) == 0)) {
        // (Then one an earlier section gave it, taken only where the link then agrees.)
        for (const bool later_in_section : {true, false}) {
            const std::size_t blames = blames_.size(), disagreeing = disagreeing_uses_.size();
            const int sign = multiplier_sign_, sign_line = multiplier_sign_line_;
            const std::string sign_section = multiplier_sign_section_;
            (later_in_section ? definitions_.set_forward(true) : definitions_.set_backward(true));
            EquationCheck other = safe_check_link(c, i, j, bridge);
            definitions_.set_forward(false);
            definitions_.set_backward(false);
            if (other.verdict == Verdict::Agrees) {
                other.notes.push_back(later_in_section
                                          ? "with a value the text gives the name only later in its section"
                                          : "with a value an earlier section gives the name");
                r = std::move(other);
                break;
            }
            // What the attempt set up is undone, but for what the later value is blamed for (apply_blames).
            for (std::size_t k = blames; k < blames_.size(); ++k) blames_[k].forward = later_in_section;
            if (!later_in_section) blames_.erase(blames_.begin() + std::ptrdiff_t(blames), blames_.end());
            for (std::size_t k = disagreeing; k < disagreeing_uses_.size(); ++k)
                disagreeing_uses_[k].forward = later_in_section;
            if (!later_in_section)
                disagreeing_uses_.erase(disagreeing_uses_.begin() + std::ptrdiff_t(disagreeing),
                                        disagreeing_uses_.end());
            multiplier_sign_ = sign;
            multiplier_sign_line_ = sign_line;
            multiplier_sign_section_ = sign_section;
        }
    }
    if (r.verdict == Verdict::NotComparable && r.reason.rfind("unknown symbol", 0) == 0)
        check_cartesian_reading(c, i, j, bridge, r);
    const std::vector<TextDefinitions::Use> uses = definitions_.take_uses();
    const std::size_t head = c.sides[i].base + c.sides[i].side->begin;
    if (r.verdict == Verdict::Agrees && r.compared_with.rfind("an identity", 0) == 0 && !bridge &&
        !definitions_.defined_at(head).empty())
        for (const TextDefinitions::Use& u : uses)
            if (u.head != std::string::npos && u.head != head) derived_from_[head].insert(u.head);
    if (!compared_with_model(r)) return r;
    for (const TextDefinitions::Use& u : uses)
        if (u.head != std::string::npos &&
            (depends_on_state(u.value) ||
             (u.value.has(model_.t) && GiNaC::normal(u.value / model_.t).has(model_.t))))  // not a new time τ = c t
            confirmed_by_[u.head].insert(r.where.line);
    return r;
}

bool Checker::check_derivative_of_definition(const FullChain& c, std::size_t i, std::size_t j, EquationCheck& r) {
    // One side is a dotted name alone whose undotted name the text defined in the model's quantities (the note
    // dotted_definitions leaves): the row states that derivative, and it is compared with it.
    for (const bool left : {true, false}) {
        const PSide& named = c.sides[left ? i : j];
        const FreeName* f = named.side->ok ? ctx_.free_name_of(named.side->value) : nullptr;
        if (!f) continue;
        const Prepared p = prepare(named), other = prepare(c.sides[left ? j : i]);
        if (!p.comparable() || !other.comparable()) return false;
        const std::string prefix = m(f->name) + " is the time derivative of ";
        const auto note = std::find_if(p.notes.begin(), p.notes.end(),
                                       [&](const std::string& n) { return n.rfind(prefix, 0) == 0; });
        if (note == p.notes.end() || equal(p.value, other.value, 1e-9) != Tri::No) continue;
        r.verdict = Verdict::Disagrees;
        r.compared_with = note->substr(prefix.size() - std::string("the time derivative of ").size());
        r.reason = "the text's " + m(f->name) + " is not the time derivative of its definition";
        const Diagnosis dg = compare_to(other.value, p.value, 1e-9);
        r.difference = dg.difference;
        r.wrong_terms = dg.lines;
        r.corrected = left ? named.side->source + " = " + latex(p.value) : latex(p.value) + " = " + named.side->source;
        return true;
    }
    return false;
}

void Checker::apply_confirmations(std::vector<EquationCheck>& equations) const {
    // Through the definitions derived from others: the lines that confirm ẋ confirm x.
    std::map<std::size_t, std::set<int>> confirmed = confirmed_by_;
    for (bool more = true; more;) {
        more = false;
        for (const auto& [head, sources] : derived_from_) {
            const auto c = confirmed.find(head);
            if (c == confirmed.end()) continue;
            const std::set<int> lines = c->second;
            for (const std::size_t s : sources)
                for (const int l : lines) more = confirmed[s].insert(l).second || more;
        }
    }
    for (const auto& [head, lines] : confirmed) {
        const auto row = definition_rows_.find(head);
        if (row == definition_rows_.end()) continue;
        for (EquationCheck& e : equations) {
            if (e.where.line != row->second.line || e.where.column != row->second.column ||
                e.verdict != Verdict::NotJudged || e.role != Role::Definition)
                continue;
            std::string list;
            for (const int l : lines) list += (list.empty() ? "" : ", ") + std::to_string(l);
            e.verdict = Verdict::Agrees;
            e.compared_with = "its use" + std::string(lines.size() > 1 ? "s on lines " : " on line ") + list;
            e.reason = "a definition of a quantity of the motion, consistent with the model: put into line" +
                       std::string(lines.size() > 1 ? "s " : " ") + list + ", it gives what eomgen derives there";
        }
    }
}

}  // namespace eomgen::checker::detail
