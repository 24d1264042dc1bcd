/** @file latex_tokens.hpp  The tokens the derivation parser reads (latex_tokens.cpp makes them from the text as
 * published); internal to the checker's LaTeX reading. */
#pragma once

#include <cstddef>
#include <initializer_list>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace eomgen::checker::latex {

/// What a token is: a letter, a digit, a control word (`\frac`, with its backslash), another character, or a
/// character the parser does not know (a UTF-8 sequence, reported where it stands).
enum class Tok { Letter, Digit, Word, Char, Other };

struct Token {
    Tok kind;
    std::string text;        ///< the letter, digit, char, or the control word with its backslash
    std::size_t offset = 0;  ///< byte offset of the token in the row
    std::size_t length = 0;  ///< bytes, including a raw argument
    std::string raw;         ///< \text{...}-like commands: the argument, verbatim
    bool space = false;      ///< spacing (\quad): skipped by the expression parser
};

/// True when `s` is one of `list`.
inline bool is_one_of(const std::string& s, std::initializer_list<const char*> list) {
    for (const char* x : list)
        if (s == x) return true;
    return false;
}

/// The tokens of `s`, with the text's own macros (text_macros.hpp: while a TextMacroScope is active) and the derivative
/// macros (`\pdv`, `\diff`, …) expanded to what they typeset.
std::vector<Token> tokenize(std::string_view s);

/// The tokens of `s` as written, no macro expanded.
std::vector<Token> tokens_as_written(std::string_view s);

/// The end (one past the closing brace) of the brace group that opens at token k, or k when none opens there (or it
/// does not close).
std::size_t group_end(const std::vector<Token>& t, std::size_t k);

/// Commands whose argument is text (`\text`, `\mathrm`, `\operatorname`, …), captured verbatim as a token's raw.
bool takes_raw_argument(const std::string& w);

/// Greek letter names without their backslash (`theta`, `varphi`, `ell`, …).
const std::set<std::string>& greek_letters();

/// A variant letter as its plain one (`varphi` → `phi`), without backslash.
std::string normal_greek(const std::string& w);

}  // namespace eomgen::checker::latex
