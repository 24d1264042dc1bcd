/** @file authors_form.cpp  A correction in the author's own form: when flipping the sign of one term the text
 * wrote, or leaving it out, makes the link agree, that edit of the text is the correction printed
 * (`I\ddot\theta = … - I_3\omega_3\dot\phi\sin\theta …` in the text's I and ω₃), not the reference's expanded
 * value. */
#include "checker/checker_internals.hpp"
#include "checker/correction_check.hpp"

#include <algorithm>

namespace eomgen::checker::detail {

bool Checker::correct_in_authors_form(const FullChain& c, std::size_t i, std::size_t j, EquationCheck& r) {
    const std::string left = trimmed(c.sides[i].side->source), right = trimmed(c.sides[j].side->source);
    // The edits the diagnosis points to: a term whose sign is flipped, a term that should not be there. (A
    // term off by a factor, a term missing, is corrected from the reference.) Leaving a term out of an
    // approximation would change the order it keeps.
    const auto says = [&](const char* what) {
        return std::any_of(r.wrong_terms.begin(), r.wrong_terms.end(),
                           [&](const std::string& l) { return l.find(what) != std::string::npos; });
    };
    const bool flips = says("a flipped sign");
    const bool drops = says("should not be there") && c.relations[j - 1] == Relation::Equal;
    if (!flips && !drops) return false;
    const std::string relation = c.relations[j - 1] == Relation::Approx ? " \\approx " : " = ";
    const std::vector<TermEdit> left_edits = one_term_edits(left), right_edits = one_term_edits(right);
    if (left_edits.empty() && right_edits.empty()) return false;
    const std::size_t at = c.relation_offsets[j - 1];
    const auto saved_names = ctx_.names;
    const auto saved_free = ctx_.free_names;
    const bool was = verifying_;
    verifying_ = true;
    apply_map(d_.position(at).line);
    const auto agrees = [&](const std::string& candidate) {
        try {
            return correction_problem(candidate, ctx_,
                                      [&](const Chain& ch, std::size_t a, std::size_t b) {
                                          return check_parsed_link(c, at, ch, a, b);
                                      })
                .empty();
        } catch (const std::exception&) {
            return false;
        }
    };
    // Flips first, then terms left out: the first kind of edit that some edit makes agree decides, and only
    // one edit of that kind may (two would leave the slip's place open).
    std::string found, what;
    for (const bool dropped : {false, true}) {
        if (dropped ? !drops : !flips) continue;
        int count = 0;
        for (const bool on_left : {true, false})
            for (const TermEdit& e : on_left ? left_edits : right_edits) {
                if (e.dropped != dropped) continue;
                const std::string candidate = on_left ? e.side + relation + right : left + relation + e.side;
                if (!agrees(candidate)) continue;
                if (++count > 1) break;
                found = candidate;
                what = e.term;
            }
        if (count == 1) break;
        found.clear();
        if (count > 1) break;
    }
    verifying_ = was;
    ctx_.names = saved_names;
    ctx_.free_names = saved_free;
    if (found.empty()) return false;
    r.corrected = found;
    r.notes.push_back("the correction is the text's own line with one term changed: $" + what + "$");
    return true;
}

}  // namespace eomgen::checker::detail
