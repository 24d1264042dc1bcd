/** @file matrix_latex.cpp  A side's arrays, tuples, determinants and vector names, scanned into terms of
 * factors with their places (what linear_algebra.cpp evaluates). */
#include "checker/matrix_latex.hpp"

#include "checker/latex_parser.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <iterator>

namespace eomgen::checker::matrix_latex {

constexpr const char* kVectorCommands[] = {"\\mathbf",    "\\boldsymbol",     "\\bm", "\\vec",
                                           "\\underline", "\\overrightarrow", "\\hat"};
constexpr const char* kMatrixEnvironments[] = {"array",  "pmatrix",     "bmatrix", "Bmatrix",
                                               "matrix", "smallmatrix", "vmatrix", "Vmatrix"};

static bool starts_command(std::string_view s, std::size_t i, std::string_view cmd) {
    if (s.substr(i, cmd.size()) != cmd) return false;
    const std::size_t k = i + cmd.size();
    return k >= s.size() || !std::isalpha(static_cast<unsigned char>(s[k]));
}

/// A space, a tab or a line break (a display's matrix is often written over several lines).
static bool spacing(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

bool blank(std::string_view s) {
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (std::isspace(static_cast<unsigned char>(c)) || c == '.' || c == ',' || c == '~') continue;
        if (c == '\\' && i + 1 < s.size() &&
            std::string_view(",;:! ").find(s[i + 1]) != std::string_view::npos) {
            ++i;
            continue;
        }
        if (starts_command(s, i, "\\quad")) {
            i += 4;
            continue;
        }
        if (starts_command(s, i, "\\qquad")) {
            i += 5;
            continue;
        }
        return false;
    }
    return true;
}

std::pair<std::size_t, std::size_t> trimmed(std::string_view s, std::size_t b, std::size_t e) {
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return {b, e};
}

/// The end of the bracket group opening at s[i] ('(', '[' or '{'), past its close; npos when it does not
/// close.
static std::size_t group_end(std::string_view s, std::size_t i) {
    int depth = 0;
    for (std::size_t k = i; k < s.size(); ++k) {
        const char c = s[k];
        if (c == '\\' && k + 1 < s.size() && (s[k + 1] == '{' || s[k + 1] == '}')) {
            ++k;
            continue;
        }
        if (c == '(' || c == '[' || c == '{') ++depth;
        if (c == ')' || c == ']' || c == '}') {
            if (--depth == 0) return k + 1;
        }
    }
    return std::string_view::npos;
}

/// The environment's name when s[i] starts `\begin{name}`, else "".
static std::string environment_at(std::string_view s, std::size_t i) {
    if (s.substr(i, 7) != "\\begin{") return "";
    const std::size_t close = s.find('}', i + 7);
    if (close == std::string_view::npos) return "";
    return std::string(s.substr(i + 7, close - i - 7));
}

/// Past the `\end{...}` matching the `\begin` at s[i]; npos when it does not close.
static std::size_t environment_end(std::string_view s, std::size_t i) {
    int depth = 0;
    for (std::size_t k = i; k < s.size(); ++k) {
        if (s.substr(k, 7) == "\\begin{") ++depth;
        if (s.substr(k, 5) == "\\end{") {
            if (--depth == 0) {
                const std::size_t close = s.find('}', k);
                return close == std::string_view::npos ? close : close + 1;
            }
        }
    }
    return std::string_view::npos;
}

static bool is_matrix_environment(const std::string& env) {
    return std::find(std::begin(kMatrixEnvironments), std::end(kMatrixEnvironments), env) !=
           std::end(kMatrixEnvironments);
}

/// The cells of the matrix environment s[b, e) (`\begin{env}` … `\end{env}`), by rows.
static Cells environment_cells(std::string_view s, std::size_t b, std::size_t e) {
    const std::string env = environment_at(s, b);
    std::size_t body = s.find('}', b) + 1;
    if (env == "array" && body < e && s[body] == '{') body = group_end(s, body);
    const std::size_t end = s.rfind("\\end{", e);
    Cells rows(1);
    std::size_t start = body;
    int depth = 0;
    for (std::size_t k = body; k < end; ++k) {
        const char c = s[k];
        if (s.substr(k, 7) == "\\begin{") ++depth;
        if (s.substr(k, 5) == "\\end{") --depth;
        if (c == '{') ++depth;
        if (c == '}') --depth;
        const bool row_break = depth == 0 && c == '\\' && k + 1 < end && s[k + 1] == '\\';
        if (row_break || (depth == 0 && c == '&')) {
            rows.back().push_back(trimmed(s, start, k));
            if (row_break) rows.emplace_back();
            k += row_break ? 1 : 0;
            start = k + 1;
        }
    }
    rows.back().push_back(trimmed(s, start, end));
    if (rows.size() > 1 && rows.back().size() == 1 && rows.back()[0].first == rows.back()[0].second)
        rows.pop_back();
    return rows;
}

/// The top-level commas of s[b, e) split it: a tuple's entries (one piece when there is no comma).
static std::vector<std::pair<std::size_t, std::size_t>> comma_pieces(std::string_view s, std::size_t b,
                                                                     std::size_t e) {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    int depth = 0;
    std::size_t start = b;
    for (std::size_t k = b; k < e; ++k) {
        const char c = s[k];
        if (c == '\\' && k + 1 < e && (s[k + 1] == '{' || s[k + 1] == '}')) {
            ++k;
            continue;
        }
        if (s.substr(k, 7) == "\\begin{") ++depth;
        if (s.substr(k, 5) == "\\end{") --depth;
        if (c == '(' || c == '[' || c == '{') ++depth;
        if (c == ')' || c == ']' || c == '}') --depth;
        if (depth == 0 && c == ',') {
            out.push_back(trimmed(s, start, k));
            start = k + 1;
        }
    }
    out.push_back(trimmed(s, start, e));
    return out;
}

bool mentions_array(std::string_view s) {
    if (s.find("\\begin{") != std::string_view::npos || s.find("\\det") != std::string_view::npos ||
        s.find("operatorname{det}") != std::string_view::npos || s.find("\\text{det}") != std::string_view::npos ||
        s.find("\\mathrm{det}") != std::string_view::npos)
        return true;
    for (std::size_t k = s.find("det"); k != std::string_view::npos; k = s.find("det", k + 1))  // `det\left(`
        if ((k == 0 || !std::isalpha(static_cast<unsigned char>(s[k - 1]))) && s.substr(k + 3, 5) == "\\left")
            return true;
    for (const char* c : kVectorCommands)
        for (std::size_t k = s.find(c); k != std::string_view::npos; k = s.find(c, k + 1))
            if (starts_command(s, k, c)) return true;
    return false;
}

/// The letter inside vector decorations: `\underline{\mathrm{n}}` → "n".
static std::string undecorated(std::string_view arg) {
    std::string s(arg);
    for (bool changed = true; changed;) {
        changed = false;
        const auto t = trimmed(s, 0, s.size());
        s = s.substr(t.first, t.second - t.first);
        if (s.size() >= 2 && s.front() == '{' && group_end(s, 0) == s.size()) {
            s = s.substr(1, s.size() - 2);
            changed = true;
            continue;
        }
        for (const char* c : {"\\mathbf", "\\boldsymbol", "\\bm", "\\vec", "\\underline", "\\overrightarrow",
                              "\\mathrm", "\\mathit", "\\text", "\\mathsf"}) {
            const std::string cmd = c;
            if (s.rfind(cmd, 0) != 0) continue;
            std::size_t k = cmd.size();
            while (k < s.size() && spacing(s[k])) ++k;
            if (k < s.size() && s[k] == '{') {
                const std::size_t e = group_end(s, k);
                if (e == s.size()) {
                    s = s.substr(k + 1, e - k - 2);
                    changed = true;
                }
            } else if (k < s.size() && k > cmd.size()) {
                s = s.substr(k);
                changed = true;
            }
            if (changed) break;
        }
    }
    return s;
}

/// Splits `n_{1x}` into its vector `n_{1}` and the component 0, 1, 2 (x, y, z); false when it is no
/// component.
bool component_of(const std::string& name, std::string* key, int* index) {
    const std::size_t u = name.find("_{");
    if (u == std::string::npos || u == 0 || name.back() != '}') return false;
    const std::string sub = name.substr(u + 2, name.size() - u - 3);
    if (sub.empty()) return false;
    const char c = sub.back();
    if (c != 'x' && c != 'y' && c != 'z') return false;
    std::string rest = sub.substr(0, sub.size() - 1);
    while (!rest.empty() && rest.back() == ' ') rest.pop_back();
    const std::string base = name.substr(0, u);
    if (rest.empty()) {
        *key = base;
    } else {
        *key = canonical_name(base + "_{" + rest + "}");
        if (key->empty()) *key = base + "_{" + rest + "}";
    }
    *index = c - 'x';
    return true;
}

/// What the brackets around s[inner) hold: an array (a determinant between bars), a tuple (where `tuple`
/// brackets may make one), a group with arrays inside; false for a scalar.
static bool bracketed(std::string_view s, std::pair<std::size_t, std::size_t> inner, bool bars, bool tuple,
                      Factor& f) {
    const std::string env = environment_at(s, inner.first);
    if (is_matrix_environment(env) && environment_end(s, inner.first) == inner.second) {
        f.kind = bars ? Factor::DetArray : Factor::Array;
        f.cells = environment_cells(s, inner.first, inner.second);
    } else if (tuple && comma_pieces(s, inner.first, inner.second).size() > 1) {
        f.kind = Factor::Tuple;
        for (const auto& p : comma_pieces(s, inner.first, inner.second)) f.cells.push_back({p});
    } else if (mentions_array(s.substr(inner.first, inner.second - inner.first))) {
        // `\left|\mathbf{V} - \omega^2\mathbf{T}\right|`: the determinant of the matrix expression between the bars
        // (of a vector, |v|, it is not read: linear_algebra_values.cpp says so).
        f.kind = bars ? Factor::Det : Factor::Group;
        f.bars = bars;
        f.inner_begin = inner.first;
        f.inner_end = inner.second;
    } else {
        return false;
    }
    return true;
}

/// One factor starting at s[i] that is not scalar text, or false (i unchanged).
static bool scan_factor(std::string_view s, std::size_t& i, std::size_t e, Factor& f, std::string* why,
                        bool letters = false) {
    const std::size_t start = i;
    f = Factor{};
    f.begin = start;
    // Inside `\det(…)`: a plain M, K, T or V, a letter alone, is the matrix of that name.
    const auto letter = [&](std::size_t k) { return k < e && std::isalpha(static_cast<unsigned char>(s[k])); };
    if (letters && std::string_view("MKTV").find(s[i]) != std::string_view::npos && !letter(i + 1) &&
        (i == 0 || (!std::isalpha(static_cast<unsigned char>(s[i - 1])) && s[i - 1] != '\\'))) {
        f.kind = Factor::Name;
        f.key = std::string(1, s[i]);
        f.end = ++i;
        return true;
    }
    // \left<d> … \right<d>
    if (starts_command(s, i, "\\left")) {
        std::size_t k = i + 5;
        while (k < e && spacing(s[k])) ++k;
        std::string open;
        if (k < e && s[k] == '\\') {
            std::size_t w = k + 1;
            while (w < e && std::isalpha(static_cast<unsigned char>(s[w]))) ++w;
            if (w == k + 1) ++w;
            open = std::string(s.substr(k, w - k));
            k = w;
        } else if (k < e) {
            open = std::string(1, s[k++]);
        }
        int depth = 1;
        std::size_t r = k;
        for (; r < e; ++r) {
            if (starts_command(s, r, "\\left")) ++depth;
            if (starts_command(s, r, "\\right") && --depth == 0) break;
        }
        if (r >= e) return false;
        std::size_t after = r + 6;
        while (after < e && spacing(s[after])) ++after;
        if (after < e && s[after] == '\\') {
            std::size_t w = after + 1;
            while (w < e && std::isalpha(static_cast<unsigned char>(s[w]))) ++w;
            if (w == after + 1) ++w;
            after = w;
        } else if (after < e) {
            ++after;
        }
        const auto inner = trimmed(s, k, r);
        const bool bars = open == "|" || open == "\\vert" || open == "\\lvert" || open == "\\|";
        if (!bracketed(s, inner, bars, open == "(" || open == "[", f)) return false;
        i = after;
        f.end = after;
        return true;
    }
    if (s[i] == '(' || s[i] == '[' || s[i] == '{') {
        const std::size_t end = group_end(s, i);
        if (end == std::string_view::npos || end > e) return false;
        const auto inner = trimmed(s, i + 1, end - 1);
        if (!bracketed(s, inner, false, s[i] != '{', f)) return false;
        i = end;
        f.end = end;
        return true;
    }
    if (s.substr(i, 7) == "\\begin{") {
        const std::string env = environment_at(s, i);
        const std::size_t end = environment_end(s, i);
        if (!is_matrix_environment(env) || end == std::string_view::npos || end > e) {
            *why = "an environment \\begin{" + env + "} is not read as a matrix";
            return false;
        }
        f.kind = env == "vmatrix" ? Factor::DetArray : Factor::Array;
        f.cells = environment_cells(s, i, end);
        i = end;
        f.end = end;
        return true;
    }
    // `\det`, `\operatorname{det}`, `\text{det}`, `\mathrm{det}`, or `det` without its backslash before a bracket
    // (`det\left(…\right)`, as notebooks write it).
    const bool bare_det = s.substr(i, 3) == "det" && (i == 0 || (!std::isalpha(static_cast<unsigned char>(s[i - 1])) &&
                                                                  s[i - 1] != '\\')) &&
                          i + 3 < e && (s[i + 3] == '(' || s[i + 3] == '\\' || s[i + 3] == ' ');
    std::size_t det_length = bare_det ? 3 : starts_command(s, i, "\\det") ? 4 : 0;
    for (const std::string_view word : {"\\operatorname{det}", "\\text{det}", "\\mathrm{det}"})
        if (det_length == 0 && s.substr(i, word.size()) == word) det_length = word.size();
    if (det_length > 0) {
        std::size_t k = i + det_length;
        while (k < e && spacing(s[k])) ++k;
        Factor inner;
        std::size_t j = k;
        if (k >= e || !scan_factor(s, j, e, inner, why)) {
            // `\det(K - \omega^2 M)`: a group of plain letters, the matrices of those names.
            const std::size_t close = k < e && s[k] == '(' ? group_end(s, k) : std::string_view::npos;
            if (!why->empty() || close == std::string_view::npos || close > e) {
                if (why->empty()) *why = "\\det of something that is not a matrix";
                return false;
            }
            const auto held = trimmed(s, k + 1, close - 1);
            f.kind = Factor::Det;
            f.letters = true;
            f.inner_begin = held.first;
            f.inner_end = held.second;
            i = close;
            f.end = close;
            return true;
        }
        f.kind = Factor::Det;
        f.inner_begin = inner.kind == Factor::Group ? inner.inner_begin : inner.begin;
        f.inner_end = inner.kind == Factor::Group ? inner.inner_end : inner.end;
        i = j;
        f.end = j;
        return true;
    }
    for (const char* c : kVectorCommands) {
        if (!starts_command(s, i, c)) continue;
        std::size_t k = i + std::string_view(c).size();
        while (k < e && spacing(s[k])) ++k;
        std::size_t arg_end = k;
        if (k < e && s[k] == '{') {
            arg_end = group_end(s, k);
            if (arg_end == std::string_view::npos || arg_end > e) return false;
        } else if (k < e && s[k] == '\\') {
            arg_end = k + 1;
            while (arg_end < e && std::isalpha(static_cast<unsigned char>(s[arg_end]))) ++arg_end;
        } else if (k < e) {
            arg_end = k + 1;
        }
        std::string letter = undecorated(s.substr(k, arg_end - k));
        if (!letter.empty() && letter.front() == '{' && letter.back() == '}')
            letter = letter.substr(1, letter.size() - 2);
        std::size_t end = arg_end;
        std::string sub;
        std::size_t u = end;
        while (u < e && spacing(s[u])) ++u;
        if (u < e && s[u] == '_') {
            std::size_t v = u + 1;
            while (v < e && spacing(s[v])) ++v;
            if (v < e && s[v] == '{') {
                const std::size_t ge = group_end(s, v);
                if (ge == std::string_view::npos || ge > e) return false;
                sub = std::string(s.substr(v, ge - v));
                end = ge;
            } else if (v < e) {
                sub = "{" + std::string(1, s[v]) + "}";
                end = v + 1;
            }
        }
        // Primes: r' is another vector than r.
        std::string primes;
        for (std::size_t p = end;;) {
            while (p < e && spacing(s[p])) ++p;
            if (p < e && s[p] == '\'') {
                primes += "'";
                end = ++p;
            } else if (s.substr(p, 9) == "^{\\prime}") {
                primes += "'";
                end = p += 9;
            } else if (s.substr(p, 7) == "^\\prime") {
                primes += "'";
                end = p += 7;
            } else {
                break;
            }
        }
        if (std::string_view(c) == "\\hat") letter = "\\hat{" + letter + "}";
        f.kind = Factor::Name;
        f.key = canonical_name(letter + (sub.empty() ? "" : "_" + sub));
        if (f.key.empty()) f.key = letter + (sub.empty() ? "" : "_" + sub);
        f.key += primes;
        i = end;
        f.end = end;
        return true;
    }
    return false;
}

bool scan(std::string_view s, std::size_t b, std::size_t e, std::vector<Term>& terms, std::string* why,
          bool matrix_letters) {
    terms.assign(1, Term{});
    std::size_t pending = std::string_view::npos;  // start of scalar text not yet a factor
    Factor::Op op = Factor::Juxtapose;
    auto flush = [&](std::size_t upto) {
        if (pending == std::string_view::npos) return;
        const auto t = trimmed(s, pending, upto);
        if (!blank(s.substr(t.first, t.second - t.first))) {
            Factor f;
            f.kind = Factor::Scalar;
            f.begin = t.first;
            f.end = t.second;
            terms.back().factors.push_back(f);
        }
        pending = std::string_view::npos;
    };
    for (std::size_t i = b; i < e;) {
        const char c = s[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
            continue;
        }
        if (starts_command(s, i, "\\cdot") || starts_command(s, i, "\\times")) {
            flush(i);
            op = s[i + 1] == 'c' ? Factor::Dot : Factor::Cross;
            i += s[i + 1] == 'c' ? 5 : 6;
            continue;
        }
        if (c == '+' || c == '-') {
            const bool empty = terms.back().factors.empty() &&
                               (pending == std::string_view::npos || blank(s.substr(pending, i - pending)));
            flush(i);
            if (!empty) terms.emplace_back();
            if (c == '-') terms.back().negative = !terms.back().negative;
            op = Factor::Juxtapose;
            ++i;
            continue;
        }
        if ((c == '^' || c == '_') && pending == std::string_view::npos && !terms.back().factors.empty() &&
            terms.back().factors.back().kind != Factor::Scalar) {
            // `^T`, `^{T}`, `^\top`, `^{\mathsf{T}}`, `^\intercal`: the transpose.
            if (c == '^') {
                std::size_t k = i + 1;
                while (k < e && spacing(s[k])) ++k;
                const std::string_view rest = s.substr(k, e - k);
                for (const char* t : {"{\\mathsf{T}}", "{\\mathrm{T}}", "{\\top}", "{\\intercal}", "{T}", "\\top",
                                      "\\intercal", "T"}) {
                    const std::size_t n = std::strlen(t);
                    if (rest.substr(0, n) != t) continue;
                    if (t[0] == '\\' && k + n < e && std::isalpha(static_cast<unsigned char>(s[k + n]))) continue;
                    if (t[0] == 'T' && k + 1 < e && std::isalnum(static_cast<unsigned char>(s[k + 1]))) continue;
                    Factor& f = terms.back().factors.back();
                    f.transpose = !f.transpose;
                    f.end = k + n;
                    i = k + n;
                    break;
                }
                if (i > k) continue;
            }
            *why = "a power or an index of a matrix or vector is not read";
            return false;
        }
        Factor f;
        std::size_t j = i;
        if (scan_factor(s, j, e, f, why, matrix_letters)) {
            flush(i);
            f.op = op;
            op = Factor::Juxtapose;
            terms.back().factors.push_back(f);
            i = j;
            continue;
        }
        if (!why->empty()) return false;
        // Scalar text: a command with its brace arguments, a bracket group, or one character.
        if (pending == std::string_view::npos) pending = i;
        if (c == '\\') {
            std::size_t k = i + 1;
            while (k < e && std::isalpha(static_cast<unsigned char>(s[k]))) ++k;
            if (k == i + 1) ++k;
            while (k < e && (s[k] == '{' || s[k] == '[')) {
                const std::size_t g = group_end(s, k);
                if (g == std::string_view::npos || g > e) break;
                k = g;
            }
            i = k;
        } else if (c == '(' || c == '[' || c == '{') {
            const std::size_t g = group_end(s, i);
            i = g == std::string_view::npos || g > e ? i + 1 : g;
        } else {
            ++i;
        }
    }
    flush(e);
    for (const Term& t : terms)
        if (t.factors.empty()) {
            *why = "an empty term";
            return false;
        }
    return true;
}

/// s without the spaces, spacing commands and `\\cdot` it ends with (what stood before a vector's name).
std::string without_trailing_operators(std::string s) {
    for (bool more = true; more;) {
        more = false;
        for (const std::string tail : {"\\cdot", "\\,", "\\;", "\\!", " "})
            if (s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0) {
                s.resize(s.size() - tail.size());
                more = true;
            }
    }
    const auto t = trimmed(s, 0, s.size());
    return s.substr(t.first, t.second - t.first);
}

/// The one factor of a side's single term that is not scalar, with the scalar factors' text; -1 otherwise.
int single_array(const std::vector<Term>& terms) {
    if (terms.size() != 1 || terms[0].negative) return -1;
    int found = -1;
    for (std::size_t k = 0; k < terms[0].factors.size(); ++k) {
        const Factor& f = terms[0].factors[k];
        if (f.kind == Factor::Scalar) continue;
        if (found >= 0 || (f.kind != Factor::Array && f.kind != Factor::Tuple)) return -1;
        found = int(k);
    }
    return found;
}

}  // namespace eomgen::checker::matrix_latex
