/** @file derivation.hpp  A derivation text (Markdown + LaTeX): its sections and the rows of math in it, with
 * places. */
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace eomgen::checker {

/// 1-based line and column (column counts bytes, as in model-file messages).
struct SourcePos {
    int line = 0;
    int column = 0;
};

/// A Markdown heading and the text it governs: up to the next heading of the same or a higher level.
struct Section {
    std::string title;      ///< heading text without the #'s, e.g. "5-20: A plane physical pendulum"
    int level = 1;          ///< number of #'s
    int line = 0;           ///< line of the heading
    std::size_t begin = 0;  ///< byte range in the file, subsections included
    std::size_t end = 0;
};

/**
 * One row of math: an inline `$...$` or `\(...\)`, or one row of a display block (`$$...$$`, `\[...\]`,
 * or a top-level `\begin{align}`), split at `\\` when the block is an aligned/align/gathered/gather/array/
 * split/eqnarray/alignat/multline environment.
 *
 * `text` is the row's LaTeX with the alignment marks `&`, the environment's `\begin`/`\end` and the row
 * breaks blanked to spaces, so that `offset + i` is the file offset of `text[i]`.
 */
struct MathRow {
    std::size_t offset = 0;
    std::string text;
    bool display = false;
    int block = 0;         ///< index of the math block; the rows of one display block share it
    int row_in_block = 0;  ///< 0 for the first row of its block
    int section = -1;      ///< innermost section containing the row, -1 before the first heading
};

/// A math delimiter that does not pair up: an unclosed `$$`, `$`, `\[`, `\(` or environment, or a `$$`
/// display that holds prose (a `$` or a blank line: the `$$` meant to close it is missing or extra).
struct TextProblem {
    std::size_t offset = 0;  ///< of the delimiter
    std::string message;     ///< e.g. "'$$' is not closed"
};

/// A macro the text defines for itself (`\newcommand{\pl}{\partial}`, `\def\vb#1{\mathbf{#1}}`,
/// `\DeclareMathOperator{\sgn}{sgn}`, `\let\eps\varepsilon`): its uses are read as its body (text_macros.hpp).
struct TextMacro {
    std::string name;       ///< with its backslash: `\pl`
    int arguments = 0;      ///< #1 … #9 in the body
    bool optional_first = false;  ///< `[n][default]`: the first argument is optional, `[...]` where given
    std::string first_default;    ///< ... and this where not
    std::string body;
    std::size_t offset = 0;  ///< of the definition in the file
};

struct Derivation {
    std::string path;
    std::string text;
    /// The text's own macros, in the order defined (a later definition of a name replaces an earlier one).
    std::vector<TextMacro> macros;
    std::vector<std::size_t> line_starts;  ///< byte offset of each line's first character
    std::vector<Section> sections;
    std::vector<MathRow> rows;
    /// Delimiters that do not pair up. The text after each is still read: a stray `$$` is passed over and
    /// the math after it found as if it were not there.
    std::vector<TextProblem> problems;

    /// Line and column of a byte offset in the file.
    SourcePos position(std::size_t offset) const;
};

/// Splits `text` (Markdown + LaTeX) into sections and math rows. Never throws on any input.
Derivation parse_derivation(std::string text, std::string path);

/// Reads the file at `path` and parses it; throws std::runtime_error when it cannot be read.
Derivation read_derivation(const std::string& path);

/**
 * The sections whose title contains one of `patterns` (case-insensitive), as indices into
 * Derivation::sections; all sections when `patterns` is empty. A selected section includes its subsections.
 */
std::vector<int> select_sections(const Derivation& d, const std::vector<std::string>& patterns);

/// True when the row lies inside one of the selected sections (or `selected` is every section and the row
/// precedes the first heading too: an empty `patterns` selects the whole file).
bool row_selected(const Derivation& d, const MathRow& row, const std::vector<int>& selected, bool whole_file);

}  // namespace eomgen::checker
