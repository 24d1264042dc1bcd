/** @file implication.cpp  A definition the text derives with "⇒" from the relation before it:
 * `\frac{1}{2}(y_1+y_2) = l_2-y_3 \Rightarrow y_3 = l_2 - \frac{1}{2}(y_1 - y_2)`. The new name is in that relation
 * with a constant coefficient, so the relation solved for it is what the definition must say: it agrees when it
 * is that, and disagrees (with the solved value as its correction) when the algebra slipped. A definition that
 * follows no relation stays a definition, not judged. */
#include "checker/checker_internals.hpp"

#include <cstring>

namespace eomgen::checker::detail {

namespace {

/// Whether text[from, to) is only an implication sign between two pieces of math: `$ $\Rightarrow$ $`,
/// ` \implies `, `⇒`.
bool only_implication(const std::string& text, std::size_t from, std::size_t to) {
    if (from >= to || to > text.size() || to - from > 80) return false;
    std::string rest = text.substr(from, to - from);
    bool sign = false;
    for (const char* arrow : {"\\Rightarrow", "\\implies", "\\Longrightarrow", "\\therefore", "\xE2\x87\x92"})
        for (std::size_t k = rest.find(arrow); k != std::string::npos; k = rest.find(arrow)) {
            rest.erase(k, std::strlen(arrow));
            sign = true;
        }
    if (!sign) return false;
    for (const char ch : rest)
        if (!std::isspace(static_cast<unsigned char>(ch)) && ch != '$' && ch != '\\' && ch != ',' && ch != ';' &&
            ch != '&' && ch != '{' && ch != '}' && ch != '(' && ch != ')' && ch != '[' && ch != ']')
            return false;
    return true;
}

}  // namespace

const FullChain* Checker::chain_before(const FullChain& c) const {
    if (!all_chains_) return nullptr;
    const FullChain* before = nullptr;
    for (const FullChain& other : *all_chains_) {
        if (&other == &c) return before;
        before = &other;
    }
    return nullptr;  // not one of the text's chains
}

bool Checker::after_implication(const FullChain& c) const {
    const FullChain* before = chain_before(c);
    if (!before || before->sides.empty() || c.sides.empty()) return false;
    return only_implication(d_.text, before->sides.back().base + before->sides.back().side->end,
                            c.sides.front().base + c.sides.front().side->begin);
}

bool Checker::check_implied_definition(const FullChain& c, std::size_t i, std::size_t j, const GiNaC::ex& name,
                                       const std::string& name_latex, const GiNaC::ex& value, EquationCheck& r) {
    if (i != 0 || !after_implication(c)) return false;
    const FullChain* before = chain_before(c);
    if (!before || before->sides.size() < 2) return false;
    // The relation before, first side = last side, in which the name must stand with a constant coefficient.
    for (std::size_t k = 0; k + 1 < before->relations.size() + 1; ++k)
        if (k < before->relations.size() && before->relations[k] != Relation::Equal) return false;
    const Prepared a = prepare(before->sides.front()), b = prepare(before->sides.back());
    if (!a.ok || !b.ok || !a.vectors.empty() || !b.vectors.empty()) return false;
    GiNaC::ex solved, coefficient;
    try {
        const GiNaC::ex e = (a.value - b.value).expand();
        if (e.degree(name) != 1 || e.ldegree(name) != 0) return false;
        coefficient = GiNaC::factor(e.coeff(name, 1));
        if (coefficient.is_zero()) return false;
        solved = GiNaC::normal(-e.coeff(name, 0) / coefficient);
    } catch (const std::exception&) {
        return false;
    }
    const int line = d_.position(before->relation_offsets.front()).line;
    const std::string relation = m(before->sides.front().side->source + " = " + before->sides.back().side->source);
    if (depends_on_state(coefficient) || has_acceleration(coefficient)) {
        // `m(\ddot y_1 - \ddot y_2) = -\frac{m_3}{4}(\ddot y_1 - \ddot y_2) \Rightarrow m = -\frac{m_3}{4}`: solving
        // divides by the name's coefficient, a quantity of the motion; where that vanishes on the motion (a
        // combination of the equations of motion, under the text's assumptions), the step divides by zero.
        if (!has_acceleration(coefficient) || !equation_of_motion(coefficient, 1e-9)) return false;
        r.compared_with = "the relation it follows from (line " + std::to_string(line) + ")";
        r.verdict = Verdict::Disagrees;
        r.reason = "it divides " + relation + " by " + m(latex(coefficient)) +
                   ", which is 0 on the motion (the equations of motion make it so" +
                   (numbers_.pinned().empty() ? "" : ", with the text's assumptions") + "): the relation says only " +
                   m(latex(coefficient) + " = 0") + ", nothing about " + m(name_latex);
        r.wrong_terms = {"a division by " + m(latex(coefficient)) + ", which vanishes on the motion"};
        r.corrected = latex(coefficient) + " = 0";
        return true;
    }
    r.compared_with = "the relation it follows from (line " + std::to_string(line) + "), solved for " +
                      m(name_latex);
    if (equal(value, solved, 1e-9) == Tri::Yes) {
        r.verdict = Verdict::Agrees;
        r.reason = "it is " + relation + " solved for " + m(name_latex);
        return true;
    }
    r.verdict = Verdict::Disagrees;
    r.reason = "it does not follow from " + relation + " (line " + std::to_string(line) + "): solved for " +
               m(name_latex) + " that gives " + m(name_latex + " = " + latex(solved));
    r.difference = latex((value - solved).expand());
    r.corrected = c.sides[i].side->source + " = " + latex(solved);
    solved_corrections_.insert({r.where.line, r.where.column});
    // The lines after it are read with the name as the relation makes it: a later slip of their own is found, and
    // one that only carries this one forward is not counted twice.
    definitions_.correct(c.sides[i].base + c.sides[i].side->begin, solved, latex(solved));
    return true;
}

}  // namespace eomgen::checker::detail
