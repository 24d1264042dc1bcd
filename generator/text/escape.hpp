/**
 * @file escape.hpp  One escaping function per output language, for text that comes from a model file or a
 * derivation (strangers' text: see docs/security.md). Every place that writes such text into C++, LaTeX,
 * Markdown, JSON or CSV goes through one of these; none of them can produce code, markup or a command.
 *
 * Each takes arbitrary bytes (invalid UTF-8 included) and returns text for its language:
 * - cpp_comment:  the inside of a `//` line or a `/ * ... * /` block comment (no line break of any kind,
 *                 no `* /` or `/ *`, no line-ending backslash, no `??` trigraph, control characters shown as
 *                 `\xNN`);
 * - cpp_string:   a complete C++ string literal with its quotes (only printable ASCII inside; everything
 *                 else as octal escapes; `?` escaped so that no trigraph forms);
 * - latex_text:   text-mode LaTeX (the ten special characters as their commands, line breaks as spaces);
 * - markdown_text: Markdown text on one line (HTML's `<`, `>`, `&` as entities, Markdown's inline
 *                 punctuation backslash-escaped, `|` too so that it stays in its table cell);
 * - json_string:  a complete JSON string with its quotes, valid UTF-8 (invalid bytes become U+FFFD),
 *                 control characters and U+2028/U+2029 as \u escapes;
 * - csv_field:    a CSV field quoted as RFC 4180 says when it needs to be (runtime/eomgen/output.hpp).
 */
#pragma once

#include <string>
#include <string_view>

namespace eomgen::text {

std::string cpp_comment(std::string_view s);
std::string cpp_string(std::string_view s);
std::string latex_text(std::string_view s);
std::string markdown_text(std::string_view s);
/// The inside of Markdown `$...$` or `$$...$$` math (no `$`, `<`, `>`, `|`, line break or backquote raw).
std::string markdown_math(std::string_view s);
/// Text with `$...$` math in it, as eomgen's own messages are: each part escaped as what it is.
std::string markdown_mixed(std::string_view s);
std::string json_string(std::string_view s);
std::string csv_field(std::string_view s);

/// `s` with every invalid UTF-8 sequence replaced by U+FFFD (each maximal invalid subpart once).
std::string valid_utf8(std::string_view s);

/**
 * The first code point of `s` from byte `i`: its value and length in bytes; an invalid or truncated sequence
 * (overlong forms, surrogates and values past U+10FFFF included) gives value -1 and length 1.
 */
struct CodePoint {
    long value;
    std::size_t length;
};
CodePoint decode_utf8(std::string_view s, std::size_t i);

/// Appends the UTF-8 encoding of a code point (at most U+10FFFF) to `out`.
void append_utf8(std::string& out, long code_point);

/// True for the control characters: C0 (U+0000–U+001F), DEL and C1 (U+0080–U+009F).
bool is_control(long code_point);

/// True for the characters that end a line somewhere: \n, \r, \v, \f, U+0085, U+2028, U+2029.
bool is_line_break(long code_point);

}  // namespace eomgen::text
