/** @file meanings.hpp  The text's own meaning of a letter eomgen reads as a label: "the conservation of angular
 * momentum, with L = m r² θ̇" makes L the angular momentum, not the Lagrangian, for the rest of the section
 * (issue 28). */
#pragma once

#include "checker/derivation.hpp"

#include <string>
#include <vector>

namespace eomgen::checker {

/// A label letter the text gives another meaning, by the row that defines it.
struct TextMeaning {
    std::string name;     ///< the letter as written: "L", "T", "h"
    std::string value;    ///< the LaTeX of its definition: "mr^2\dot{\theta}"
    std::string noun;     ///< what the text makes it: "angular momentum (as its sentence says)", "period (…)"
    std::size_t begin = 0, end = 0;  ///< the defining row's range in the file
    int line = 0;         ///< of the defining row
    int last_line = 0;    ///< the last line of its section (the meaning holds to there)
};

/**
 * Rows `X = value` (one of the labels L, T, H, h, V, U, E; after an implication arrow, a chain's first link)
 * whose sentence calls X something other than what eomgen's label is — the angular momentum (L), the period or
 * a tension (T), a height (h, H) — or, for L, in a text that writes its Lagrangian \mathscr{L} or \mathcal{L};
 * and T = 2π/ω or 2π√(…), a period whatever the sentence says. As TextMeaning, in the order of the text.
 */
std::vector<TextMeaning> text_meanings(const Derivation& d, const std::vector<const MathRow*>& rows);

/**
 * Names the prose gives a quantity: inline math that is a name alone right after "call it", "calling it",
 * "denote it (by)", "denoted (by)", "which we call", "call this", "write … as" … names the left side of the math row
 * before it (`$p_\phi = … $ is conserved; call it $\ell$`: ℓ is p_φ), from the next line to the end of the section.
 * As TextMeaning (noun "the name the text gives it"), in the order of the text.
 */
std::vector<TextMeaning> prose_namings(const Derivation& d, const std::vector<const MathRow*>& rows);

}  // namespace eomgen::checker
