/** @file latex_name.hpp  The LaTeX a model file may give a name (`latex = '...'`): a documented safe set. */
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace eomgen {

/// Why a `latex` field cannot be used, with the byte offset in the field it is about.
struct LatexNameProblem {
    std::size_t offset = 0;
    std::string message;  ///< empty: the field is fine
};

/**
 * Checks a user's LaTeX for a name against the safe set (docs/model_files.md, "LaTeX names"): letters,
 * digits, spaces and `_ ^ { } ( ) [ ] ' , . : ; + - * / | = < > !`; the commands of Greek letters, of
 * accents (\dot, \hat, \bar, \vec, ...), of math alphabets (\mathrm, \mathbf, ...), and a few symbols
 * (\ell, \hbar, \prime, \infty, ...); the spacing and escaped-brace control symbols (\, \; \! \{ \});
 * braces balanced, at most 200 bytes. Anything else (\input, \write18, \catcode, $, %, #, &, ~, ...) is
 * refused, so that no text a model file gives a name can become a TeX command in what eomgen writes.
 */
LatexNameProblem latex_name_problem(std::string_view latex);

}  // namespace eomgen
