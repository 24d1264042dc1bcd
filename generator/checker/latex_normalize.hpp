/** @file latex_normalize.hpp  The LaTeX people publish, read as the parser's LaTeX: HTML entities and Unicode
 * letters in Markdown math, equation numbers, and displays continued across `$$` blocks or `\\` rows. */
#pragma once

#include "checker/derivation.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace eomgen::checker {

/// A stretch of text that stands for LaTeX tokens: `θ` is `\theta`, `φ̇` is `\dot \phi`, `&theta;` is
/// `\theta`, `²` is `^ 2`, `&nbsp;` is nothing.
struct Spelling {
    std::size_t length = 0;           ///< bytes of the text it replaces
    std::vector<std::string> tokens;  ///< LaTeX tokens, each a control word (`\dot`), a letter, a digit or a sign
};

/**
 * What the text at `i` spells, when it is an HTML entity (`&theta;`, `&#952;`, `&#x3B8;`, `&lt;`), a UTF-8
 * letter or sign the table knows (Greek letters, `ℓ`, `∂`, `−`, `·`, `×`, `≈`, `≤`, `⇒`, `²`, `½`, …), or
 * either of them or an ASCII letter followed by combining dots (U+0307 one dot, U+0308 two: `φ̇`, `ẍ`).
 * std::nullopt otherwise (a plain ASCII character, an unknown entity or character).
 */
std::optional<Spelling> spelled_as_latex(std::string_view s, std::size_t i);

/// True when `s[i]` is the `&` of an HTML entity (`&theta;`, `&#952;`), which an alignment mark is not;
/// `&amp;` is the alignment mark written for HTML, and is not an entity here.
bool entity_at(std::string_view s, std::size_t i);

/// True for the names of an arbitrary additive constant: `\text{const}`, `\mathrm{const.}`, `\text{constant}`.
bool is_constant_name(const std::string& canonical_name);

/// `s` without the spaces, tabs, line ends and `~` (LaTeX's tie) at its two ends.
std::string trimmed(const std::string& s);

/**
 * Rewrites the math rows of `d` as the parser reads them, keeping `offset + i` the file offset of `text[i]`:
 * - an equation number at the end of a row (`\quad (1)`, `\qquad (2.14)`, `\hfill (3)`, `\eqno(4)`,
 *   `\quad \text{(5)}`) is blanked (`\tag`, `\label`, `\nonumber` the parser skips itself);
 * - `&amp;` (an alignment mark in HTML) is blanked;
 * - a display row that ends with `=`, `+`, `-`, `\cdot` or `\times` is joined with the next display row,
 *   and a display row that starts with `+` or `-` is joined with the one before when one of the two has no
 *   relation (a sum broken over rows: `m l^2 \ddot\theta \\ + m g l \sin\theta = 0`), when only `$$`, `\[`, `\]`, `\\` and space lie between them (one display split over several, a
 *   sum broken over `\\` rows). The joined row keeps the first row's place; what lay between is blanked.
 */
void normalize_rows(Derivation& d);

}  // namespace eomgen::checker
