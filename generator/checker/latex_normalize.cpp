/** @file latex_normalize.cpp  HTML entities, Unicode letters, equation numbers and continued displays. */
#include "checker/latex_normalize.hpp"

#include "checker/latex_parser.hpp"

#include <cctype>
#include <map>

namespace eomgen::checker {
namespace {

using Tokens = std::vector<std::string>;

/// Unicode code points people paste into Markdown math, as LaTeX tokens.
const std::map<char32_t, Tokens>& unicode_table() {
    static const std::map<char32_t, Tokens> t = [] {
        std::map<char32_t, Tokens> m;
        const char* const lower[] = {"alpha", "beta", "gamma", "delta",   "epsilon", "zeta", "eta", "theta",
                                     "iota",  "kappa", "lambda", "mu",    "nu",      "xi",   "omicron", "pi",
                                     "rho",   "varsigma", "sigma", "tau", "upsilon", "phi",  "chi", "psi",
                                     "omega"};
        for (char32_t k = 0; k < 25; ++k) m[0x03B1 + k] = {std::string("\\") + lower[k]};
        m[0x03BF] = {"o"};  // omicron
        // Capitals: those LaTeX has as commands, the rest are Latin letters.
        const char* const upper[] = {"A", "B", "\\Gamma", "\\Delta", "E", "Z", "H", "\\Theta", "I",
                                     "K", "\\Lambda", "M", "N", "\\Xi", "O", "\\Pi", "P", "",
                                     "\\Sigma", "T", "\\Upsilon", "\\Phi", "X", "\\Psi", "\\Omega"};
        for (char32_t k = 0; k < 25; ++k)
            if (*upper[k]) m[0x0391 + k] = {upper[k]};
        m[0x03D1] = {"\\vartheta"};
        m[0x03D5] = {"\\phi"};
        m[0x03F5] = {"\\epsilon"};
        m[0x03F1] = {"\\rho"};
        m[0x03D6] = {"\\varpi"};
        m[0x2113] = {"\\ell"};
        m[0x2202] = {"\\partial"};
        m[0x2212] = {"-"};
        m[0x2013] = {"-"};  // an en dash, as some editors turn a minus into
        m[0x00B7] = {"\\cdot"};
        m[0x22C5] = {"\\cdot"};
        m[0x2219] = {"\\cdot"};
        m[0x00D7] = {"\\times"};
        m[0x00F7] = {"\\div"};
        m[0x2248] = {"\\approx"};
        m[0x2243] = {"\\simeq"};
        m[0x2261] = {"\\equiv"};
        m[0x2264] = {"\\le"};
        m[0x2265] = {"\\ge"};
        m[0x2260] = {"\\neq"};
        m[0x221D] = {"\\propto"};
        m[0x2192] = {"\\rightarrow"};
        m[0x21D2] = {"\\Rightarrow"};
        m[0x27F9] = {"\\Longrightarrow"};
        m[0x21D4] = {"\\iff"};
        m[0x221A] = {"\\sqrt"};
        m[0x222B] = {"\\int"};
        m[0x221E] = {"\\infty"};
        m[0x2026] = {"\\ldots"};
        m[0x00B1] = {"\\pm"};
        m[0x2032] = {"'"};
        m[0x2033] = {"'", "'"};
        m[0x00B2] = {"^", "2"};
        m[0x00B3] = {"^", "3"};
        m[0x00B9] = {"^", "1"};
        m[0x00BD] = {"\\frac", "1", "2"};
        m[0x00BC] = {"\\frac", "1", "4"};
        m[0x00BE] = {"\\frac", "3", "4"};
        m[0x2153] = {"\\frac", "1", "3"};
        m[0x2154] = {"\\frac", "2", "3"};
        m[0x00B0] = {"^", "\\circ"};
        m[0x00BA] = {"^", "\\circ"};  // º, the ordinal sign, typed for the degree sign (`120º`)
        // Spaces: no token.
        for (char32_t sp : {0x00A0, 0x2009, 0x200A, 0x202F, 0x2002, 0x2003, 0x2005, 0x2006, 0x200B})
            m[sp] = {};
        // Precomposed dotted letters.
        m[0x1E8B] = {"\\dot", "x"};
        m[0x1E8F] = {"\\dot", "y"};
        m[0x017C] = {"\\dot", "z"};
        m[0x1E59] = {"\\dot", "r"};
        m[0x1E57] = {"\\dot", "p"};
        m[0x1E8D] = {"\\ddot", "x"};
        m[0x00FF] = {"\\ddot", "y"};
        return m;
    }();
    return t;
}

/// HTML entity names (without & and ;) that are not Greek letters.
const std::map<std::string, Tokens>& entity_table() {
    static const std::map<std::string, Tokens> t = {
        {"lt", {"<"}},           {"gt", {">"}},          {"le", {"\\le"}},         {"ge", {"\\ge"}},
        {"ne", {"\\neq"}},       {"asymp", {"\\approx"}}, {"equiv", {"\\equiv"}},  {"minus", {"-"}},
        {"times", {"\\times"}},  {"middot", {"\\cdot"}}, {"sdot", {"\\cdot"}},     {"divide", {"\\div"}},
        {"nbsp", {}},            {"thinsp", {}},         {"ensp", {}},             {"emsp", {}},
        {"part", {"\\partial"}}, {"radic", {"\\sqrt"}},  {"sup2", {"^", "2"}},     {"sup3", {"^", "3"}},
        {"frac12", {"\\frac", "1", "2"}}, {"frac14", {"\\frac", "1", "4"}},        {"frac34", {"\\frac", "3", "4"}},
        {"rarr", {"\\rightarrow"}},       {"rArr", {"\\Rightarrow"}},              {"hArr", {"\\iff"}},
        {"prime", {"'"}},        {"Prime", {"'", "'"}},  {"infin", {"\\infty"}},   {"hellip", {"\\ldots"}},
        {"plusmn", {"\\pm"}},    {"int", {"\\int"}},     {"prop", {"\\propto"}},   {"deg", {"^", "\\circ"}},
        {"thetasym", {"\\vartheta"}}, {"piv", {"\\varpi"}}, {"sigmaf", {"\\varsigma"}}, {"ell", {"\\ell"}},
    };
    return t;
}

bool is_greek_name(const std::string& n) {
    static const char* const names[] = {
        "alpha", "beta",  "gamma", "delta", "epsilon", "zeta", "eta",     "theta", "iota",   "kappa",
        "lambda", "mu",   "nu",    "xi",    "omicron", "pi",   "rho",     "sigma", "tau",    "upsilon",
        "phi",   "chi",   "psi",   "omega", "Gamma",   "Delta", "Theta",  "Lambda", "Xi",    "Pi",
        "Sigma", "Upsilon", "Phi", "Psi",   "Omega"};
    for (const char* g : names)
        if (n == g) return true;
    return false;
}

/// Decodes one UTF-8 sequence at i; returns its length (0 when it is not valid UTF-8).
std::size_t decode_utf8(std::string_view s, std::size_t i, char32_t* cp) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    std::size_t n = 0;
    char32_t v = 0;
    if (c < 0x80) {
        *cp = c;
        return 1;
    }
    if ((c & 0xE0) == 0xC0) {
        n = 2;
        v = c & 0x1F;
    } else if ((c & 0xF0) == 0xE0) {
        n = 3;
        v = c & 0x0F;
    } else if ((c & 0xF8) == 0xF0) {
        n = 4;
        v = c & 0x07;
    } else {
        return 0;
    }
    if (i + n > s.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        const unsigned char d = static_cast<unsigned char>(s[i + k]);
        if ((d & 0xC0) != 0x80) return 0;
        v = (v << 6) | (d & 0x3F);
    }
    *cp = v;
    return n;
}

/// The entity at i (`&name;`, `&#952;`, `&#x3B8;`): its length and tokens.
std::optional<Spelling> entity(std::string_view s, std::size_t i) {
    if (i >= s.size() || s[i] != '&') return std::nullopt;
    const std::size_t semi = s.find(';', i + 1);
    if (semi == std::string_view::npos || semi - i > 12 || semi == i + 1) return std::nullopt;
    const std::string name(s.substr(i + 1, semi - i - 1));
    Spelling sp;
    sp.length = semi + 1 - i;
    if (name[0] == '#') {
        char32_t cp = 0;
        const bool hex = name.size() > 1 && (name[1] == 'x' || name[1] == 'X');
        const std::string digits = name.substr(hex ? 2 : 1);
        if (digits.empty() || digits.size() > 6) return std::nullopt;
        for (char c : digits) {
            const int d = std::isdigit(static_cast<unsigned char>(c))
                              ? c - '0'
                              : (hex && std::isxdigit(static_cast<unsigned char>(c))
                                     ? std::tolower(static_cast<unsigned char>(c)) - 'a' + 10
                                     : -1);
            if (d < 0) return std::nullopt;
            cp = cp * (hex ? 16 : 10) + char32_t(d);
        }
        if (cp < 0x80) {
            if (std::isalnum(static_cast<int>(cp)) || std::string("+-=<>()[]/*^_',.").find(char(cp)) != std::string::npos)
                sp.tokens = {std::string(1, char(cp))};
            else if (cp != ' ')
                return std::nullopt;
            return sp;
        }
        auto it = unicode_table().find(cp);
        if (it == unicode_table().end()) return std::nullopt;
        sp.tokens = it->second;
        return sp;
    }
    if (is_greek_name(name)) {
        sp.tokens = {"\\" + name};
        return sp;
    }
    auto it = entity_table().find(name);
    if (it == entity_table().end()) return std::nullopt;
    sp.tokens = it->second;
    return sp;
}

/// Combining dots after a base letter at j: U+0307 (one dot), U+0308 (two). Adds them to `dots`.
/// Also written as entities: `&#775;`, `&#x307;`, `&#776;`, `&#x308;`.
std::size_t combining_dots(std::string_view s, std::size_t j, int* dots) {
    while (j < s.size()) {
        if (j + 1 < s.size() && static_cast<unsigned char>(s[j]) == 0xCC &&
            (static_cast<unsigned char>(s[j + 1]) == 0x87 || static_cast<unsigned char>(s[j + 1]) == 0x88)) {
            *dots += static_cast<unsigned char>(s[j + 1]) == 0x87 ? 1 : 2;
            j += 2;
            continue;
        }
        bool found = false;
        for (const auto& [spelled, n] : {std::pair<const char*, int>{"&#775;", 1}, {"&#x307;", 1}, {"&#X307;", 1},
                                         {"&#776;", 2}, {"&#x308;", 2}, {"&#X308;", 2}})
            if (s.substr(j, std::string_view(spelled).size()) == spelled) {
                *dots += n;
                j += std::string_view(spelled).size();
                found = true;
                break;
            }
        if (!found) break;
    }
    return j;
}

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

bool ends_with_word(const std::string& s, std::size_t end, const char* w, std::size_t* start) {
    const std::string_view v(w);
    if (end < v.size() || s.compare(end - v.size(), v.size(), v) != 0) return false;
    *start = end - v.size();
    return true;
}

/// Blanks an equation number at the end of a row: `\quad (1)`, `\qquad (2.14)`, `\eqno(3)`, `\quad \text{(4)}`.
void blank_equation_number(std::string& t) {
    std::size_t e = t.size();
    while (e > 0 && (is_space(t[e - 1]) || t[e - 1] == '.' || t[e - 1] == ',')) --e;
    std::size_t b = e;
    // `\text{(1)}` / `\mbox{(1)}`
    bool wrapped = false;
    if (b > 0 && t[b - 1] == '}') {
        const std::size_t open = t.rfind('{', b - 1);
        if (open != std::string::npos) {
            std::size_t cmd = open;
            while (cmd > 0 && std::isalpha(static_cast<unsigned char>(t[cmd - 1]))) --cmd;
            const std::string word = cmd > 0 && t[cmd - 1] == '\\' ? t.substr(cmd, open - cmd) : "";
            if (word == "text" || word == "mbox" || word == "textrm" || word == "mathrm") {
                std::string inner = t.substr(open + 1, b - 1 - open - 1);
                while (!inner.empty() && is_space(inner.back())) inner.pop_back();
                while (!inner.empty() && is_space(inner.front())) inner.erase(inner.begin());
                if (inner.size() >= 3 && inner.front() == '(' && inner.back() == ')') {
                    b = cmd - 1;
                    wrapped = true;
                }
            }
        }
    }
    if (!wrapped) {
        if (b == 0 || t[b - 1] != ')') return;
        const std::size_t open = t.rfind('(', b - 1);
        if (open == std::string::npos) return;
        const std::string inner = t.substr(open + 1, b - 1 - open - 1);
        bool digit = false;
        if (inner.empty() || inner.size() > 12) return;
        for (char c : inner) {
            if (std::isdigit(static_cast<unsigned char>(c))) digit = true;
            if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == ' ' || c == '*'))
                return;
        }
        if (!digit) return;
        b = open;
    }
    std::size_t k = b;
    while (k > 0 && is_space(t[k - 1])) --k;
    std::size_t start = 0;
    bool marked = false;
    for (const char* w : {"\\qquad", "\\quad", "\\hfill", "\\eqno", "\\leqno"})
        if (ends_with_word(t, k, w, &start)) {
            marked = true;
            break;
        }
    if (!marked && k > 0 && t[k - 1] == '}') {  // \hspace{2cm}
        const std::size_t open = t.rfind('{', k - 1);
        if (open != std::string::npos && ends_with_word(t, open, "\\hspace", &start)) marked = true;
    }
    if (!marked) return;
    for (std::size_t q = start; q < e; ++q)
        if (t[q] != '\n') t[q] = ' ';
}


/// The row ends with an operator that needs a right operand: `=`, `+`, `-`, `\cdot`, `\times`.
bool ends_open(const std::string& row) {
    const std::string t = trimmed(row);
    if (t.empty()) return false;
    const char c = t.back();
    if ((c == '=' || c == '+' || c == '-') && !(t.size() >= 2 && t[t.size() - 2] == '\\')) return true;
    std::size_t s = 0;
    return ends_with_word(t, t.size(), "\\cdot", &s) || ends_with_word(t, t.size(), "\\times", &s);
}

/// The row starts with `+` or `-` (a continued sum).
bool starts_with_sign(const std::string& row) {
    const std::string t = trimmed(row);
    return !t.empty() && (t[0] == '+' || t[0] == '-');
}

/// Only display delimiters, row breaks, alignment marks and space between file offsets [from, to).
bool only_breaks_between(const std::string& file, std::size_t from, std::size_t to) {
    if (from > to || to > file.size()) return false;
    for (std::size_t q = from; q < to; ++q) {
        const char c = file[q];
        if (is_space(c) || c == '$' || c == '&') continue;
        if (c == '\\' && q + 1 < to && (file[q + 1] == '[' || file[q + 1] == ']' || file[q + 1] == '\\')) {
            ++q;
            continue;
        }
        return false;
    }
    return true;
}

}  // namespace

std::string trimmed(const std::string& s) {
    std::size_t a = 0, b = s.size();
    while (a < b && (is_space(s[a]) || s[a] == '~')) ++a;
    while (b > a && (is_space(s[b - 1]) || s[b - 1] == '~')) --b;
    return s.substr(a, b - a);
}

std::optional<Spelling> spelled_as_latex(std::string_view s, std::size_t i) {
    if (i >= s.size()) return std::nullopt;
    Spelling sp;
    std::size_t j = i;
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c == '&') {
        auto e = entity(s, i);
        if (!e) return std::nullopt;
        sp = *e;
        j = i + sp.length;
    } else if (c >= 0x80) {
        char32_t cp = 0;
        const std::size_t n = decode_utf8(s, i, &cp);
        if (n == 0) return std::nullopt;
        auto it = unicode_table().find(cp);
        if (it == unicode_table().end()) return std::nullopt;
        sp.tokens = it->second;
        j = i + n;
    } else if (std::isalpha(c)) {
        sp.tokens = {std::string(1, char(c))};
        j = i + 1;
        if (j >= s.size() || !(static_cast<unsigned char>(s[j]) == 0xCC || s[j] == '&')) return std::nullopt;
    } else {
        return std::nullopt;
    }
    int dots = 0;
    j = combining_dots(s, j, &dots);
    if (c < 0x80 && c != '&' && dots == 0) return std::nullopt;  // a plain letter: the tokenizer's own
    if (dots > 0) {
        // The dots go before the letter: `\dot \phi`. Only a single letter takes them.
        if (sp.tokens.size() != 1) return std::nullopt;
        Tokens t;
        for (int left = dots; left > 0; left -= 2) t.push_back(left >= 2 ? "\\ddot" : "\\dot");
        t.push_back(sp.tokens[0]);
        // \ddot \dot x is read by the parser as nested accents: fine, but nesting needs braces for \ddot{\dot x}.
        if (t.size() > 2) return std::nullopt;
        sp.tokens = t;
    }
    sp.length = j - i;
    return sp;
}

bool entity_at(std::string_view s, std::size_t i) {
    return entity(s, i).has_value();
}

bool is_constant_name(const std::string& n) {
    return n == "const" || n == "constant" || n == "Const" || n == "cst";
}

/// `(E_1):& …`, `(ii): …`: an equation's label before it, a parenthesis of a few characters without a relation
/// followed by a colon at the start of a row, is blanked.
void blank_leading_label(std::string& row) {
    const std::size_t open = row.find_first_not_of(" \t\n");
    if (open == std::string::npos || row[open] != '(') return;
    const std::size_t close = row.find(')', open);
    if (close == std::string::npos || close - open > 12) return;
    const std::string inside = row.substr(open + 1, close - open - 1);
    if (inside.empty() || inside.find_first_of("=<>") != std::string::npos) return;
    std::size_t colon = close + 1;
    while (colon < row.size() && (row[colon] == ' ' || row[colon] == '\t')) ++colon;
    if (colon < row.size() && row[colon] == ':') {
        for (std::size_t k = open; k <= colon; ++k) row[k] = ' ';
        return;
    }
    // `(i) \quad \frac{d}{dt} …`, `(2)\qquad …`: a numeral (roman, or digits with a letter) before a space command,
    // a label as well, not a factor (a parenthesis of a formula is not a numeral: `(x) \quad` is kept).
    static const char* const kSpaces[] = {"\\qquad", "\\quad", "\\;", "\\,", "~"};
    const auto numeral = [](const std::string& x) {
        static const char* const kRoman[] = {"i", "ii", "iii", "iv", "v", "vi", "vii", "viii", "ix", "x",
                                             "I", "II", "III", "IV", "V", "VI", "VII", "VIII", "IX", "X"};
        for (const char* r : kRoman)
            if (x == r) return true;
        std::size_t digits = 0;
        while (digits < x.size() && (std::isdigit(static_cast<unsigned char>(x[digits])) || x[digits] == '.')) ++digits;
        return digits > 0 && std::isdigit(static_cast<unsigned char>(x[0])) &&
               (digits == x.size() || (digits + 1 == x.size() && std::isalpha(static_cast<unsigned char>(x.back()))));
    };
    if (!numeral(inside)) return;
    for (const char* space : kSpaces)
        if (row.compare(colon, std::string(space).size(), space) == 0) {
            for (std::size_t k = open; k < colon + std::string(space).size(); ++k) row[k] = ' ';
            return;
        }
}

void normalize_rows(Derivation& d) {
    for (MathRow& r : d.rows) {
        // &amp; is the alignment mark of a page written in HTML.
        for (std::size_t k = r.text.find("&amp;"); k != std::string::npos; k = r.text.find("&amp;", k + 1))
            for (std::size_t q = k; q < k + 5; ++q) r.text[q] = ' ';
        blank_equation_number(r.text);
        blank_leading_label(r.text);
    }
    std::vector<MathRow> out;
    for (MathRow& r : d.rows) {
        if (!out.empty()) {
            MathRow& p = out.back();
            const std::size_t p_end = p.offset + p.text.size();
            const bool joinable = p.display && r.display && p.section == r.section && r.offset >= p_end &&
                                  only_breaks_between(d.text, p_end, r.offset);
            const bool continued = joinable && (ends_open(p.text) || (starts_with_sign(r.text) &&
                                                                      (!has_relation(r.text) || !has_relation(p.text))));
            if (continued) {
                std::string gap = d.text.substr(p_end, r.offset - p_end);
                for (char& ch : gap)
                    if (ch != '\n') ch = ' ';
                std::string next = r.text;
                // `a =` then `= b`: one relation, not two; `a +` then `+ b` (the sign repeated on the next
                // line, as typesetters do) is one sign, and `a +` then `- b` is a - b.
                // Either row may be blank: a row of only a sign continues an empty display (found by fuzz_latex).
                const std::string p_trim = trimmed(p.text), next_trim = trimmed(next);
                const char last = p_trim.empty() ? ' ' : p_trim.back(), first = next_trim.empty() ? ' ' : next_trim[0];
                const bool sign_last = last == '+' || last == '-', sign_first = first == '+' || first == '-';
                if ((last == '=' && first == '=') || (sign_last && sign_first && last == first))
                    next[next.find(first)] = ' ';
                else if (sign_last && sign_first)
                    p.text[p.text.find_last_of(last)] = ' ';
                p.text += gap + next;
                continue;
            }
        }
        out.push_back(std::move(r));
    }
    d.rows = std::move(out);
}

}  // namespace eomgen::checker
