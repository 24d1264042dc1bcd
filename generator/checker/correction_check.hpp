/** @file correction_check.hpp  A correction the checker prints is itself checked before it is printed: parsed
 * back with the text's names and compared link by link by the same machinery; one that does not agree is
 * withheld (a correction that fails its own check is a bug, never output). */
#pragma once

#include "checker/checker.hpp"
#include "checker/latex_parser.hpp"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace eomgen::checker {

/// Checks the link between sides i and j of a chain parsed from a correction.
using LinkCheck = std::function<EquationCheck(const Chain& chain, std::size_t i, std::size_t j)>;

/**
 * Why `corrected` cannot be printed, or "" when it may: it is parsed with `context` (the names of the line it
 * corrects) into one chain `a = b [= c ...]` whose every link must agree under `check`. Also refused: a
 * multiple of zero `0 \left(...\right)` and a subtracted zero `- \left(0\right)`.
 */
std::string correction_problem(const std::string& corrected, LatexContext& context, const LinkCheck& check);

/// `left = k (right)` for a chain step whose left side is k times the right one; `left = -\left(right\right)`
/// for k = "-", `left = right` for k = "1"; "" for k = "0" or "" (no such form: the caller prints the value).
std::string scaled_step(const std::string& left, const std::string& k, const std::string& right);

/// `\frac{d}{dt}\left(P\right) - \left(Q\right) = 0`, without the `- (Q)` when Q is "0".
std::string lagrange_form(const std::string& p, const std::string& q);

/// One edit of a side as the text writes it: one top-level term's sign flipped, or the term left out.
struct TermEdit {
    std::string side;         ///< the side's LaTeX after the edit
    std::string term;         ///< the term edited, as written (without its sign)
    bool dropped = false;     ///< left out, else its sign flipped
};

/**
 * The edits of `side` (LaTeX) that change one top-level term of its sum: each term's sign flipped (the first
 * term's too), then each term left out (when there are two or more). Terms are split at `+` and `-` outside
 * braces, brackets and parentheses, and not where the sign is unary (after `(`, `^`, `=` …). Empty for a side
 * with `\pm`, `\mp`, `&` or a line break, or with more than `max_terms` terms.
 */
std::vector<TermEdit> one_term_edits(const std::string& side, std::size_t max_terms = 12);

}  // namespace eomgen::checker
