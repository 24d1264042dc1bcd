/** @file derivation.cpp  Finding headings, display and inline math, and the rows of aligned environments. */
#include "checker/derivation.hpp"

#include "checker/latex_normalize.hpp"
#include "checker/text_macros.hpp"
#include "checker/latex_parser.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace eomgen::checker {
namespace {

bool starts_with(const std::string& s, std::size_t i, const char* p) {
    const std::string_view v(p);
    return s.compare(i, v.size(), v) == 0;
}

/// Environments whose rows are equations of their own.
bool is_row_environment(const std::string& name) {
    static const char* const names[] = {"aligned", "align",    "align*",    "gathered", "gather",
                                        "gather*", "array",    "split",     "eqnarray", "eqnarray*",
                                        "alignat", "alignat*", "alignedat", "multline", "multline*",
                                        "flalign", "flalign*"};
    for (const char* n : names)
        if (name == n) return true;
    return false;
}

bool is_display_environment(const std::string& name) {
    return is_row_environment(name) || name == "equation" || name == "equation*" || name == "displaymath" ||
           name == "math";
}

/// Reads `\begin{name}` or `\end{name}` at i; returns the name and sets `after`, or "" when there is none.
std::string environment_at(const std::string& s, std::size_t i, const char* cmd, std::size_t& after) {
    if (!starts_with(s, i, cmd)) return "";
    std::size_t j = i + std::string_view(cmd).size();
    while (j < s.size() && s[j] == ' ') ++j;
    if (j >= s.size() || s[j] != '{') return "";
    const std::size_t close = s.find('}', j);
    if (close == std::string::npos) return "";
    after = close + 1;
    return s.substr(j + 1, close - j - 1);
}

/// Skips a balanced {...} at i (s[i] == '{'); returns the index after it.
std::size_t skip_group(const std::string& s, std::size_t i) {
    int depth = 0;
    for (; i < s.size(); ++i) {
        if (s[i] == '\\') {
            ++i;
            continue;
        }
        if (s[i] == '{') ++depth;
        if (s[i] == '}' && --depth == 0) return i + 1;
    }
    return s.size();
}

void blank(std::string& s, std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to && i < s.size(); ++i)
        if (s[i] != '\n') s[i] = ' ';
}

struct Block {
    std::size_t begin, end;  ///< content, without the delimiters
    bool display;
};

/// Splits the content of a display block into rows (file offsets), blanking what is not math.
/// True when s[from, to) has a `\\` outside braces and environments (a row break of a display without one).
bool has_top_level_row_break(const std::string& s, std::size_t from, std::size_t to) {
    int brace = 0, envs = 0;
    for (std::size_t k = from; k < to; ++k) {
        std::size_t a = 0;
        if (s[k] == '%') {
            while (k < to && s[k] != '\n') ++k;
            continue;
        }
        if (s[k] == '\\' && !environment_at(s, k, "\\begin", a).empty()) {
            ++envs;
            k = a - 1;
            continue;
        }
        if (s[k] == '\\' && !environment_at(s, k, "\\end", a).empty()) {
            if (envs > 0) --envs;
            k = a - 1;
            continue;
        }
        if (s[k] == '\\' && k + 1 < to) {
            if (s[k + 1] == '\\' && brace == 0 && envs == 0) return true;
            ++k;
            continue;
        }
        if (s[k] == '{') ++brace;
        if (s[k] == '}' && brace > 0) --brace;
    }
    return false;
}

void split_display(const std::string& file, const Block& b, int block, std::vector<MathRow>& rows) {
    std::string s = file.substr(b.begin, b.end - b.begin);
    // The outermost environment, if the block is one (text around it, like a final '.', is kept).
    std::size_t i = 0;
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    std::size_t body_begin = 0, body_end = s.size();
    bool rows_env = false;
    std::size_t after = 0;
    std::string env;
    // Descend through environments that only wrap another (`\begin{equation}\begin{aligned}…`) and through
    // `\left\{ \begin{array}…\end{array} \right.` (a system of equations), to the one whose rows are equations.
    for (int depth = 0; depth < 4; ++depth) {
        std::size_t k = i;
        // Plain TeX's `\cases{T_1 = … \\ U_1 = …}` and `\eqalign{…}`: rows, as a cases environment's.
        bool plain = false;
        for (const char* cmd : {"\\cases", "\\eqalign"}) {
            const std::size_t n = std::string_view(cmd).size();
            if (!starts_with(s, k, cmd) || (k + n < s.size() && std::isalpha(static_cast<unsigned char>(s[k + n]))))
                continue;
            std::size_t w = k + n;
            while (w < body_end && std::isspace(static_cast<unsigned char>(s[w]))) ++w;
            if (w >= body_end || s[w] != '{') break;
            const std::size_t e = skip_group(s, w);
            if (e > body_end || e < w + 2 || s[e - 1] != '}') break;
            blank(s, k, w + 1);
            blank(s, e - 1, e);
            body_begin = w + 1;
            body_end = e - 1;
            rows_env = plain = true;
            env = "cases";
            break;
        }
        if (plain) break;
        bool wrapped = false;
        for (const char* wrap : {"\\left\\{", "\\left\\lbrace", "\\left."})
            if (starts_with(s, k, wrap)) {
                std::size_t w = k + std::string_view(wrap).size();
                while (w < body_end && std::isspace(static_cast<unsigned char>(s[w]))) ++w;
                std::size_t a = 0;
                const std::string inner = environment_at(s, w, "\\begin", a);
                if (inner == "array" || inner == "cases" || inner == "aligned") {
                    blank(s, k, w);
                    k = w;
                    wrapped = true;
                }
                break;
            }
        env = environment_at(s, k, "\\begin", after);
        if (env.empty() || !(is_display_environment(env) || env == "cases")) {
            env = depth == 0 ? env : "";
            break;
        }
        i = k;
        // Find the matching \end{env}, counting nested environments of the same name.
        int level = 0;
        std::size_t end_at = std::string::npos, end_after = 0;
        for (std::size_t q = i; q < body_end; ++q) {
            std::size_t a = 0;
            if (environment_at(s, q, "\\begin", a) == env) ++level;
            if (environment_at(s, q, "\\end", a) == env && --level == 0) {
                end_at = q;
                end_after = a;
                break;
            }
        }
        if (end_at == std::string::npos) break;
        blank(s, i, after);
        std::size_t body = after;
        if ((env == "array" || env.rfind("alignat", 0) == 0 || env == "alignedat") && body < s.size()) {
            std::size_t q = body;
            while (q < s.size() && s[q] == ' ') ++q;
            if (q < s.size() && s[q] == '{') {
                const std::size_t e = skip_group(s, q);
                blank(s, body, e);
                body = e;
            }
        }
        blank(s, end_at, end_after);
        // ... and the `\right.` that closes the wrap, or the last row would end with it.
        if (wrapped) {
            std::size_t r = end_after;
            while (r < s.size() && std::isspace(static_cast<unsigned char>(s[r]))) ++r;
            for (const char* close : {"\\right.", "\\right\\}", "\\right\\rbrace"})
                if (starts_with(s, r, close)) {
                    blank(s, r, r + std::string_view(close).size());
                    break;
                }
        }
        body_begin = body;
        body_end = end_at;
        rows_env = is_row_environment(env) || env == "cases";
        if (rows_env) break;
        i = body;  // an environment that wraps another: look inside it
        while (i < body_end && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    }
    // `$$ a = b \\ c = d $$` without an environment: its rows all the same (MathJax breaks the line there).
    if (env.empty()) rows_env = has_top_level_row_break(s, body_begin, body_end);
    // Split at top-level \\ (outside braces and nested environments) and blank top-level &.
    std::vector<std::pair<std::size_t, std::size_t>> pieces;
    std::size_t start = 0;
    int brace = 0, envs = 0;
    std::vector<std::size_t> cells;  // where the rows' `&` were
    for (std::size_t k = body_begin; k < body_end; ++k) {
        const char c = s[k];
        std::size_t a = 0;
        if (c == '\\' && !environment_at(s, k, "\\begin", a).empty()) {
            ++envs;
            k = a - 1;
            continue;
        }
        if (c == '\\' && !environment_at(s, k, "\\end", a).empty()) {
            if (envs > 0) --envs;
            k = a - 1;
            continue;
        }
        if (c == '%') {  // a LaTeX comment: its \\ and & do not count
            while (k < body_end && s[k] != '\n') ++k;
            continue;
        }
        if (c == '\\' && k + 1 < body_end && s[k + 1] == '\\') {
            if (brace == 0 && envs == 0 && rows_env) {
                pieces.push_back({start, k});
                std::size_t e = k + 2;
                // \\[2pt]
                std::size_t q = e;
                while (q < body_end && s[q] == ' ') ++q;
                if (q < body_end && s[q] == '[') {
                    const std::size_t close = s.find(']', q);
                    if (close != std::string::npos && close < body_end) e = close + 1;
                }
                blank(s, k, e);
                start = e;
                k = e - 1;
            } else {
                ++k;
            }
            continue;
        }
        if (c == '\\') {
            ++k;
            continue;
        }
        if (c == '{') ++brace;
        if (c == '}' && brace > 0) --brace;
        if (c == '&' && brace == 0 && envs == 0 && rows_env) {
            // `&amp;` is the alignment mark of a page written in HTML; `&theta;` is a letter.
            if (s.compare(k, 5, "&amp;") == 0) {
                blank(s, k, k + 5);
                cells.push_back(k);
            } else if (!entity_at(s, k)) {
                s[k] = ' ';
                cells.push_back(k);
            }
        }
    }
    pieces.push_back({start, s.size()});
    int n = 0;
    const auto add_row = [&](std::size_t pb, std::size_t pe) {
        const std::string text = s.substr(pb, pe - pb);
        if (text.find_first_not_of(" \t\r\n.,;") == std::string::npos) return;
        MathRow r;
        r.offset = b.begin + pb;
        r.text = text;
        r.display = true;
        r.block = block;
        r.row_in_block = n++;
        rows.push_back(std::move(r));
    };
    for (const auto& [pb, pe] : pieces) {
        // An array whose cells are equations each (`x_1 = x & y_1 = 0`): one row per cell. (In `a &= b` the cell
        // before `&` holds no relation: the row stays whole, its `&` an alignment mark.)
        std::vector<std::pair<std::size_t, std::size_t>> row_cells;
        std::size_t from = pb;
        for (const std::size_t k : cells)
            if (k >= pb && k < pe) {
                row_cells.push_back({from, k});
                from = k + 1;
            }
        row_cells.push_back({from, pe});
        const bool equations = env == "array" && row_cells.size() >= 2 &&
                               std::all_of(row_cells.begin(), row_cells.end(), [&](const auto& cell) {
                                   return has_relation(s.substr(cell.first, cell.second - cell.first));
                               });
        if (!equations) {
            add_row(pb, pe);
            continue;
        }
        for (const auto& [cb, ce] : row_cells) add_row(cb, ce);
    }
}

/// What in s[begin, end) (a `$$` display's content) cannot be math: a '$' outside braces (`\text{$x$}` is
/// math) or a blank line, described with its place; empty when there is neither.
std::string prose_in_display(const Derivation& d, std::size_t begin, std::size_t end) {
    const std::string& s = d.text;
    int brace = 0;
    for (std::size_t k = begin; k < end; ++k) {
        const char c = s[k];
        if (c == '\\') {
            ++k;
            continue;
        }
        if (c == '%') {  // a comment, to the end of its line
            while (k + 1 < end && s[k + 1] != '\n') ++k;
            continue;
        }
        if (c == '{') ++brace;
        if (c == '}' && brace > 0) --brace;
        const auto at = [&](std::size_t o) {
            const SourcePos p = d.position(o);
            return std::to_string(p.line) + ":" + std::to_string(p.column);
        };
        if (c == '$' && brace == 0) return "a '$' at " + at(k);
        if (c == '\n') {
            std::size_t j = k + 1;
            while (j < end && (s[j] == ' ' || s[j] == '\t' || s[j] == '\r')) ++j;
            // (Blank lines between the formula and a delimiter are space: `$$ a = b` then a blank line, `$$`.)
            const auto blank = [&](std::size_t from, std::size_t to) {
                for (std::size_t q = from; q < to; ++q)
                    if (!std::isspace(static_cast<unsigned char>(s[q]))) return false;
                return true;
            };
            if (j < end && s[j] == '\n' && !blank(j, end) && !blank(begin, k))
                return "a blank line at " + at(k + 1);
        }
    }
    return "";
}

}  // namespace

SourcePos Derivation::position(std::size_t offset) const {
    if (line_starts.empty()) return {1, int(offset) + 1};
    auto it = std::upper_bound(line_starts.begin(), line_starts.end(), offset);
    const std::size_t line = std::size_t(it - line_starts.begin());  // 1-based
    const std::size_t start = line_starts[line - 1];
    return {int(line), int(offset - start) + 1};
}

Derivation parse_derivation(std::string text, std::string path) {
    Derivation d;
    d.path = std::move(path);
    d.text = std::move(text);
    const std::string& s = d.text;
    d.line_starts.push_back(0);
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s[i] == '\n') d.line_starts.push_back(i + 1);

    std::vector<Block> blocks;
    bool fence = false;
    std::size_t i = 0;
    while (i < s.size()) {
        const bool line_start = i == 0 || s[i - 1] == '\n';
        if (line_start) {
            std::size_t k = i;
            while (k < s.size() && k - i < 4 && s[k] == ' ') ++k;
            if (starts_with(s, k, "```") || starts_with(s, k, "~~~")) {
                fence = !fence;
                i = s.find('\n', k);
                if (i == std::string::npos) break;
                ++i;
                continue;
            }
            if (!fence && k < s.size() && s[k] == '#' && k - i < 4) {
                std::size_t h = k;
                while (h < s.size() && s[h] == '#') ++h;
                const int level = int(h - k);
                if (level <= 6 && (h >= s.size() || s[h] == ' ' || s[h] == '\t' || s[h] == '\n')) {
                    std::size_t e = s.find('\n', h);
                    if (e == std::string::npos) e = s.size();
                    std::string title = s.substr(h, e - h);
                    while (!title.empty() &&
                           (title.back() == ' ' || title.back() == '#' || title.back() == '\r'))
                        title.pop_back();
                    std::size_t f = title.find_first_not_of(" \t");
                    title = f == std::string::npos ? "" : title.substr(f);
                    d.sections.push_back({title, level, d.position(i).line, i, s.size()});
                    i = h;  // the heading's own math (`## The Lagrangian $L = T - V$`) is read too
                    continue;
                }
            }
        }
        if (fence) {
            const std::size_t e = s.find('\n', i);
            if (e == std::string::npos) break;
            i = e + 1;
            continue;
        }
        const char c = s[i];
        if (c == '`') {  // inline code
            const std::size_t e = s.find('`', i + 1);
            const std::size_t nl = s.find("\n\n", i + 1);
            if (e != std::string::npos && (nl == std::string::npos || e < nl)) {
                i = e + 1;
                continue;
            }
            ++i;
            continue;
        }
        if (c == '\\' && i + 1 < s.size() && s[i + 1] == '$') {
            i += 2;
            continue;
        }
        if (starts_with(s, i, "$$")) {
            const std::size_t e = s.find("$$", i + 2);
            if (e == std::string::npos) {
                d.problems.push_back({i, "'$$' is not closed: no '$$' after it"});
                i += 2;
                continue;
            }
            if (const std::string prose = prose_in_display(d, i + 2, e); !prose.empty()) {
                d.problems.push_back({i, "the display opened by this '$$' holds " + prose +
                                             ": a '$$' is missing or extra; the text after it is read as prose"});
                i += 2;
                continue;
            }
            blocks.push_back({i + 2, e, true});
            i = e + 2;
            continue;
        }
        if (starts_with(s, i, "\\[")) {
            const std::size_t e = s.find("\\]", i + 2);
            if (e != std::string::npos) {
                blocks.push_back({i + 2, e, true});
                i = e + 2;
                continue;
            }
            d.problems.push_back({i, "'\\[' is not closed: no '\\]' after it"});
            i += 2;
            continue;
        }
        std::size_t after = 0;
        const std::string env = environment_at(s, i, "\\begin", after);
        if (!env.empty() && is_display_environment(env) && env != "array" && env != "aligned" &&
            env != "gathered") {
            const std::string closing = "\\end{" + env + "}";
            const std::size_t e = s.find(closing, after);
            if (e != std::string::npos) {
                blocks.push_back({i, e + closing.size(), true});
                i = e + closing.size();
                continue;
            }
            d.problems.push_back({i, "'\\begin{" + env + "}' is not closed: no '" + closing + "' after it"});
            i = after;
            continue;
        }
        // Forums' delimiters: `##…##` (inline, Physics Forums' MathJax), `[itex]…[/itex]`, `[tex]…[/tex]`,
        // `[latex]…[/latex]` (a display, or inline for itex).
        if (starts_with(s, i, "##") && !(i + 2 < s.size() && (s[i + 2] == ' ' || s[i + 2] == '#'))) {
            const std::size_t e = s.find("##", i + 2);
            const std::size_t para = s.find("\n\n", i + 2);
            if (e != std::string::npos && e > i + 2 && (para == std::string::npos || e < para)) {
                blocks.push_back({i + 2, e, false});
                i = e + 2;
                continue;
            }
        }
        {
            bool taken = false;
            struct ForumDelimiter {
                const char* open;
                const char* close;
                bool display;
            };
            static constexpr ForumDelimiter kForum[] = {
                {"[itex]", "[/itex]", false}, {"[tex]", "[/tex]", true}, {"[latex]", "[/latex]", true}};
            for (const ForumDelimiter& fd : kForum) {
                const char* open = fd.open;
                const char* close = fd.close;
                const bool display = fd.display;
                if (!starts_with(s, i, open)) continue;
                const std::size_t from = i + std::string_view(open).size();
                const std::size_t e = s.find(close, from);
                if (e == std::string::npos) {
                    d.problems.push_back(TextProblem{i, std::string("'") + open + "' is not closed: no '" + close + "' after it"});
                    i = from;
                } else {
                    blocks.push_back({from, e, display});
                    i = e + std::string_view(close).size();
                }
                taken = true;
                break;
            }
            if (taken) continue;
        }
        if (c == '$' || starts_with(s, i, "\\(")) {
            const bool dollar = c == '$';
            const std::size_t from = i + (dollar ? 1 : 2);
            std::size_t e = from;
            const std::size_t para = s.find("\n\n", from);
            while (true) {
                e = dollar ? s.find('$', e) : s.find("\\)", e);
                if (e == std::string::npos || (para != std::string::npos && e > para)) {
                    e = std::string::npos;
                    break;
                }
                if (dollar && e > 0 && s[e - 1] == '\\') {
                    ++e;
                    continue;
                }
                break;
            }
            if (e == std::string::npos || e == from) {
                // "$5" or "costs $" in prose is a dollar; "$x" up to a blank line is an unclosed formula.
                if (e == std::string::npos && from < s.size() && !std::isspace(static_cast<unsigned char>(s[from])) &&
                    !std::isdigit(static_cast<unsigned char>(s[from])))
                    d.problems.push_back({i, dollar ? "'$' is not closed in its paragraph"
                                                    : "'\\(' is not closed in its paragraph"});
                i = from;
                continue;
            }
            // `$\begin{align} … \end{align}$`, as notebooks write a display: its rows, as in a display.
            std::size_t lead = from;
            while (lead < e && std::isspace(static_cast<unsigned char>(s[lead]))) ++lead;
            std::size_t env_after = 0;
            const std::string inner = environment_at(s, lead, "\\begin", env_after);
            blocks.push_back({from, e, !inner.empty() && is_display_environment(inner)});
            i = e + (dollar ? 1 : 2);
            continue;
        }
        ++i;
    }

    // Section ends: the next heading of the same or a higher level.
    for (std::size_t k = 0; k < d.sections.size(); ++k)
        for (std::size_t j = k + 1; j < d.sections.size(); ++j)
            if (d.sections[j].level <= d.sections[k].level) {
                d.sections[k].end = d.sections[j].begin;
                break;
            }

    int block = 0;
    for (const Block& b : blocks) {
        if (b.display) {
            split_display(s, b, block, d.rows);
        } else {
            MathRow r;
            r.offset = b.begin;
            r.text = s.substr(b.begin, b.end - b.begin);
            r.display = false;
            r.block = block;
            d.rows.push_back(std::move(r));
        }
        ++block;
    }
    for (MathRow& r : d.rows) {
        // Innermost section: the last heading before the row whose range contains it.
        for (std::size_t k = 0; k < d.sections.size(); ++k)
            if (d.sections[k].begin <= r.offset && r.offset < d.sections[k].end) r.section = int(k);
    }
    normalize_rows(d);  // equation numbers, HTML's &amp;, displays continued over several rows
    d.macros = read_text_macros(d.text);  // \newcommand and the like: the tokenizer reads their uses as their bodies
    return d;
}

Derivation read_derivation(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::stringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw std::runtime_error("cannot read " + path);
    return parse_derivation(ss.str(), path);
}

std::vector<int> select_sections(const Derivation& d, const std::vector<std::string>& patterns) {
    auto lower = [](std::string x) {
        for (char& c : x) c = char(std::tolower(static_cast<unsigned char>(c)));
        return x;
    };
    std::vector<int> out;
    for (std::size_t k = 0; k < d.sections.size(); ++k) {
        bool match = patterns.empty();
        for (const std::string& p : patterns)
            if (lower(d.sections[k].title).find(lower(p)) != std::string::npos) match = true;
        if (match) out.push_back(int(k));
    }
    return out;
}

bool row_selected(const Derivation& d, const MathRow& row, const std::vector<int>& selected,
                  bool whole_file) {
    if (whole_file) return true;
    for (int k : selected) {
        const Section& s = d.sections[std::size_t(k)];
        if (s.begin <= row.offset && row.offset < s.end) return true;
    }
    return false;
}

}  // namespace eomgen::checker
