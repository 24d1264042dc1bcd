/**
 * @file text_macros.hpp  The macros a derivation defines for itself, read as their bodies: a LaTeX document or a
 * notebook's first cell often opens with `\newcommand{\pl}{\partial}`, `\newcommand{\vb}[1]{\mathbf{#1}}`,
 * `\def\dd{\mathrm{d}}` or `\DeclareMathOperator{\sgn}{sgn}`, and writes `\frac{\pl L}{\pl \dot r}` after it.
 *
 * The document stage reads the definitions (read_text_macros, anywhere in the file: `\newcommand`,
 * `\renewcommand`, `\providecommand` with or without `*`, `[n]` arguments and an optional first one `[n][default]`;
 * `\def` with `#1…#9`; `\let` and `\DeclareMathOperator`). While a derivation is checked, a TextMacroScope makes
 * them the tokenizer's: each use is replaced by its body's tokens with the arguments put in for #1…#9, at the use's
 * place in the row, so that messages and corrections point at what the text wrote. Expansion is bounded (a macro
 * that uses itself, or a body that doubles at each level, stops at a fixed depth and size and is left as written).
 */
#pragma once

#include "checker/derivation.hpp"
#include "checker/latex_tokens.hpp"

#include <string_view>
#include <vector>

namespace eomgen::checker {

/// The macro definitions in `text`, in order.
std::vector<TextMacro> read_text_macros(std::string_view text);

namespace latex {

/// Makes `macros` the tokenizer's for its lifetime on this thread (scopes nest; the innermost wins).
class TextMacroScope {
  public:
    explicit TextMacroScope(const std::vector<TextMacro>& macros);
    ~TextMacroScope();
    TextMacroScope(const TextMacroScope&) = delete;
    TextMacroScope& operator=(const TextMacroScope&) = delete;

  private:
    const std::vector<TextMacro>* previous_;
};

/// `t` with the uses of the current scope's macros replaced by their bodies (t itself where no scope is active).
std::vector<Token> expand_text_macros(std::vector<Token> t);

}  // namespace latex
}  // namespace eomgen::checker
