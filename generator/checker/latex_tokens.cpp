/** @file latex_tokens.cpp  LaTeX as published (notes, notebooks, Q&A posts, pasted text) into the parser's tokens:
 * control words and their spellings, raw arguments, ignored commands, plain-text derivatives (`d/dt`, `dx/dt`),
 * functions without their backslash, Unicode and HTML entities (latex_normalize), and the physics package's
 * derivative macros. Every notation variant the parser reads is decided here, in one place. */
#include "checker/latex_tokens.hpp"

#include "checker/latex_normalize.hpp"
#include "checker/text_macros.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <map>

namespace eomgen::checker::latex {

namespace {


// Commands that only change spacing or size: dropped.
bool is_ignored_word(const std::string& w) {
    return is_one_of(
        w, {"\\displaystyle", "\\ds", "\\textstyle",  "\\scriptstyle", "\\limits", "\\nolimits", "\\big",
            "\\Big",          "\\bigg",       "\\Bigg",        "\\bigl",   "\\bigr",     "\\Bigl",
            "\\Bigr",         "\\biggl",      "\\biggr",       "\\Biggl",  "\\Biggr",    "\\bigm",
            "\\Bigm",         "\\nonumber",   "\\notag",       "\\middle", "\\mathopen", "\\mathclose",
            "\\strut",        "\\allowbreak", "\\nobreak",
            // Plain TeX's font switches (`{\rm const}`): the letters after them are read as they are.
            "\\rm", "\\it", "\\bf", "\\sf", "\\tt",
            // Struck-out factors the text shows cancelling (`\cancel{m}\ddot q = \cancel{m} g`): the factor is
            // still there, in its group.
            "\\cancel", "\\bcancel", "\\xcancel"});
}

/// Another spelling of a command the parser reads: `\Ddot` (physics notes' macro) is `\ddot`, `\Vec` and
/// `\vect` are `\vec`, `\vb` (the physics package's bold vector) is `\mathbf`. The command itself otherwise.
std::string canonical_word(const std::string& w) {
    static const std::map<std::string, std::string> alias = {
        {"\\Ddot", "\\ddot"}, {"\\Dot", "\\dot"}, {"\\Vec", "\\vec"}, {"\\vect", "\\vec"}, {"\\vb", "\\mathbf"}};
    const auto it = alias.find(w);
    return it == alias.end() ? w : it->second;
}

/// `\overbrace{…}^{note}` and `\underbrace{…}_{note}`: the braced part is read, the note is not.
bool is_annotating_brace(const std::string& w) { return w == "\\overbrace" || w == "\\underbrace"; }

// Commands dropped together with their brace argument.
bool is_ignored_with_argument(const std::string& w) {
    return is_one_of(w, {"\\label", "\\tag", "\\hspace", "\\vspace", "\\phantom", "\\hphantom", "\\vphantom",
                         "\\color", "\\textcolor"});
}

/// Skips a balanced {...} starting at i (which must be '{'); returns the index after it, or the end.
std::size_t skip_braces(std::string_view s, std::size_t i) {
    int depth = 0;
    for (; i < s.size(); ++i) {
        if (s[i] == '\\' && i + 1 < s.size()) {
            ++i;
            continue;
        }
        if (s[i] == '{') ++depth;
        if (s[i] == '}' && --depth == 0) return i + 1;
    }
    return s.size();
}

std::vector<Token> tokenize_text(std::string_view s);


/**
 * The derivative macros of the physics package and of course notes, as the fraction they typeset, in tokens at
 * the macro's place (the arguments keep theirs): `\pdv{L}{\theta}`, `\pdiff{L}{\theta}` are
 * `\frac{\partial L}{\partial \theta}`; `\dv{x}{t}`, `\diff{x}{t}` are `\frac{d x}{d t}`; with one argument
 * (`\dv{t}`, `\diff{}{t}` with an empty first one) the operator `\frac{d}{d t}`. `\Lagr` and `\Lagrangian`
 * are `\mathcal{L}`. A third argument (the order, as `\pdv[2]{f}{x}` writes it) is not expanded.
 */
std::vector<Token> expand_macros(std::vector<Token> in) {
    std::vector<Token> out;
    out.reserve(in.size());
    for (std::size_t k = 0; k < in.size(); ++k) {
        const Token& m = in[k];
        if (m.kind != Tok::Word) {
            out.push_back(m);
            continue;
        }
        // Made tokens lie at the macro or at a brace of its own, so that a side's extent is still the text's.
        auto made = [&](Tok kind, const char* text, const Token& at) {
            return Token{kind, text, at.offset, at.length, "", false};
        };
        if (m.text == "\\Lagr" || m.text == "\\Lagrangian") {
            out.push_back(made(Tok::Word, "\\mathcal", m));
            out.push_back(made(Tok::Char, "{", m));
            out.push_back(made(Tok::Letter, "L", m));
            out.push_back(made(Tok::Char, "}", m));
            continue;
        }
        const bool partial = is_one_of(m.text, {"\\pdv", "\\pdiff", "\\pderiv", "\\partialderivative", "\\pd"});
        const bool total = is_one_of(m.text, {"\\dv", "\\diff", "\\deriv", "\\derivative", "\\od", "\\tdiff"});
        const std::size_t a = k + 1, a_end = group_end(in, a), b_end = group_end(in, a_end);
        if (!(partial || total) || a_end == a) {
            out.push_back(m);
            continue;
        }
        auto d = [&](const Token& at) {
            return partial ? made(Tok::Word, "\\partial", at) : made(Tok::Letter, "d", at);
        };
        auto copy = [&](std::size_t from, std::size_t to) {  // the tokens inside the group [from, to), expanded
            const std::vector<Token> inner =
                expand_macros({in.begin() + std::ptrdiff_t(from) + 1, in.begin() + std::ptrdiff_t(to) - 1});
            out.insert(out.end(), inner.begin(), inner.end());
        };
        out.push_back(made(Tok::Word, "\\frac", m));
        if (b_end != a_end) {  // \pdv{f}{x}: f over x; \diff{}{t}: the operator
            out.push_back(in[a]);
            out.push_back(d(in[a]));
            copy(a, a_end);
            out.push_back(in[a_end - 1]);
            out.push_back(in[a_end]);
            out.push_back(d(in[a_end]));
            copy(a_end, b_end);
            out.push_back(in[b_end - 1]);
            k = b_end - 1;
        } else {  // \dv{t}: the operator d/dt
            out.push_back(made(Tok::Char, "{", m));
            out.push_back(d(m));
            out.push_back(made(Tok::Char, "}", m));
            out.push_back(in[a]);
            out.push_back(d(in[a]));
            copy(a, a_end);
            out.push_back(in[a_end - 1]);
            k = a_end - 1;
        }
    }
    return out;
}


std::vector<Token> tokenize_text(std::string_view s) {
    std::vector<Token> out;
    std::size_t i = 0;
    // The notes of \overbrace and \underbrace: [from, to) ranges the loop steps over.
    std::vector<std::pair<std::size_t, std::size_t>> skipped;
    while (i < s.size()) {
        if (const auto sk = std::find_if(skipped.begin(), skipped.end(), [i](const auto& r) { return r.first == i; });
            sk != skipped.end()) {
            i = sk->second;
            continue;
        }
        const unsigned char c = static_cast<unsigned char>(s[i]);
        if (std::isspace(c)) {
            ++i;
            continue;
        }
        if (c == '%') {  // a LaTeX comment, to the end of the line
            while (i < s.size() && s[i] != '\n') ++i;
            continue;
        }
        if (c == '~') {
            ++i;
            continue;
        }
        // `d/dt` and `(d/dt)` as plain text writes the operator: \frac{d}{dt}.
        {
            const std::size_t open = c == '(' ? 1 : 0;
            if (s.compare(i + open, 4, "d/dt") == 0 && (i == 0 || !std::isalpha(static_cast<unsigned char>(s[i - 1]))) &&
                (open == 0 || (i + 5 < s.size() && s[i + 5] == ')')) &&
                (i + open + 4 >= s.size() || !std::isalpha(static_cast<unsigned char>(s[i + open + 4])))) {
                const std::size_t n = open ? 6 : 4;
                for (const char* w : {"\\frac", "{", "d", "}", "{", "d", "t", "}"}) {
                    const unsigned char w0 = static_cast<unsigned char>(w[0]);
                    out.push_back({w0 == '\\' ? Tok::Word : (std::isalpha(w0) ? Tok::Letter : Tok::Char), w, i, n, "", false});
                }
                i += n;
                continue;
            }
        }
        // `dx/dt`, `d\theta/dt`, `d^2x/dt^2` as plain text writes a derivative: \frac{d x}{dt}, \frac{d^2 x}{dt^2}.
        // A letter may come right before it (`gxd\theta/dt`, as pasted text runs a product together), but not
        // the rest of a control word.
        std::size_t word_start = i;
        while (word_start > 0 && std::isalpha(static_cast<unsigned char>(s[word_start - 1]))) --word_start;
        if (c == 'd' && (word_start == 0 || s[word_start - 1] != '\\')) {
            std::size_t k = i + 1;
            const bool second = s.compare(k, 2, "^2") == 0;
            if (second) k += 2;
            std::size_t name_end = k;
            if (k < s.size() && std::isalpha(static_cast<unsigned char>(s[k])) && s[k] != 'd' && s[k] != 't') {
                name_end = k + 1;
            } else if (k < s.size() && s[k] == '\\') {
                name_end = k + 1;
                while (name_end < s.size() && std::isalpha(static_cast<unsigned char>(s[name_end]))) ++name_end;
                if (!greek_letters().count(std::string(s.substr(k + 1, name_end - k - 1)))) name_end = k;
            }
            const std::string_view tail = second ? "/dt^2" : "/dt";
            if (name_end > k && s.compare(name_end, tail.size(), tail) == 0 &&
                (name_end + tail.size() >= s.size() ||
                 !std::isalnum(static_cast<unsigned char>(s[name_end + tail.size()])))) {
                const std::size_t n = name_end + tail.size() - i;
                const std::string name(s.substr(k, name_end - k));
                std::vector<std::string> words{"\\frac", "{", "d"};
                if (second) words.insert(words.end(), {"^", "2"});
                words.push_back(name);
                words.insert(words.end(), {"}", "{", "d", "t"});
                if (second) words.insert(words.end(), {"^", "2"});
                words.push_back("}");
                for (const std::string& w : words) {
                    const unsigned char w0 = static_cast<unsigned char>(w[0]);
                    const Tok kind = w.size() > 1 && w0 == '\\' ? Tok::Word
                                     : std::isalpha(w0)          ? Tok::Letter
                                     : std::isdigit(w0)          ? Tok::Digit
                                                                 : Tok::Char;
                    out.push_back({kind, w, i, n, "", false});
                }
                i += n;
                continue;
            }
        }
        // A combining dot (U+0307) or two (U+0308) after a space, on the letter before it (`x ̈` as a word
        // processor pastes ẍ): that letter dotted.
        if (c == 0xCC && i + 1 < s.size() && (static_cast<unsigned char>(s[i + 1]) == 0x87 ||
                                              static_cast<unsigned char>(s[i + 1]) == 0x88) &&
            !out.empty() && (out.back().kind == Tok::Letter || (out.back().kind == Tok::Word && out.back().raw.empty())) &&
            s.find_first_not_of(" \t", out.back().offset + out.back().length) == i) {
            const Token letter = out.back();
            out.back() = {Tok::Word, static_cast<unsigned char>(s[i + 1]) == 0x87 ? "\\dot" : "\\ddot", letter.offset,
                          0, "", false};
            out.push_back({letter.kind, letter.text, letter.offset, i + 2 - letter.offset, "", false});
            i += 2;
            continue;
        }
        // The same after a bracketed power, `(x^2 ) ̇` as a word processor writes ẋ²: the dot on the power's base.
        if (c == 0xCC && i + 1 < s.size() && (static_cast<unsigned char>(s[i + 1]) == 0x87 ||
                                              static_cast<unsigned char>(s[i + 1]) == 0x88) &&
            !out.empty() && out.back().kind == Tok::Char && out.back().text == ")" &&
            s.find_first_not_of(" \t", out.back().offset + out.back().length) == i) {
            std::size_t open = out.size() - 1;
            bool matched = false;
            for (int depth = 0; open > 0 && !matched;) {
                --open;
                if (out[open].kind == Tok::Char && out[open].text == ")") ++depth;
                if (out[open].kind == Tok::Char && out[open].text == "(") matched = depth-- == 0;
            }
            const bool power_of_a_name =
                matched && open + 3 < out.size() && out[open].kind == Tok::Char && out[open].text == "(" &&
                (out[open + 1].kind == Tok::Letter || (out[open + 1].kind == Tok::Word && out[open + 1].raw.empty())) &&
                out[open + 2].kind == Tok::Char && out[open + 2].text == "^";
            if (power_of_a_name) {
                const Token base = out[open + 1];
                out.insert(out.begin() + std::ptrdiff_t(open + 1),
                           Token{Tok::Word, static_cast<unsigned char>(s[i + 1]) == 0x87 ? "\\dot" : "\\ddot",
                                 base.offset, 0, "", false});
                out.back().length = i + 2 - out.back().offset;
                i += 2;
                continue;
            }
        }
        // HTML entities, Unicode letters and signs, combining dots (latex_normalize): their LaTeX tokens.
        if (c >= 0x80 || c == '&' ||
            (std::isalpha(c) && i + 1 < s.size() && (static_cast<unsigned char>(s[i + 1]) == 0xCC || s[i + 1] == '&'))) {
            if (const auto sp = spelled_as_latex(s, i)) {
                for (const std::string& w : sp->tokens) {
                    const unsigned char w0 = static_cast<unsigned char>(w[0]);
                    const Tok kind = w.size() > 1 && w0 == '\\' ? Tok::Word
                                     : std::isalpha(w0)          ? Tok::Letter
                                     : std::isdigit(w0)          ? Tok::Digit
                                                                 : Tok::Char;
                    out.push_back({kind, w, i, sp->length, "", false});
                }
                i += sp->length;
                continue;
            }
        }
        if (c == '\\') {
            std::size_t j = i + 1;
            if (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) {
                while (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) ++j;
                std::string w = canonical_word(std::string(s.substr(i, j - i)));
                if (j < s.size() && s[j] == '*') ++j;  // \operatorname*, \text*
                if (is_annotating_brace(w)) {
                    std::size_t k = j;
                    while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
                    if (k < s.size() && s[k] == '{') {
                        // The group is read where it stands; a ^ or _ note after it is stepped over.
                        const std::size_t e = skip_braces(s, k);
                        std::size_t n = e;
                        while (n < s.size() && std::isspace(static_cast<unsigned char>(s[n]))) ++n;
                        if (n < s.size() && s[n] == (w == "\\overbrace" ? '^' : '_')) {
                            std::size_t a = n + 1;
                            while (a < s.size() && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
                            const std::size_t to = a < s.size() && s[a] == '{'    ? skip_braces(s, a)
                                                   : a < s.size() && s[a] == '\\' ? a + 2
                                                                                  : std::min(s.size(), a + 1);
                            skipped.emplace_back(n, to);
                        }
                        i = k;
                        continue;
                    }
                }
                if (is_one_of(w, {"\\boxed", "\\fbox", "\\framebox"})) {
                    // A boxed result (`\boxed{m\ddot x = F}`, `\fbox{$...$}`): read as if unboxed, so its relation
                    // is between two sides and not inside a group.
                    std::size_t k = j;
                    while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
                    if (k < s.size() && s[k] == '{') {
                        const std::size_t e = skip_braces(s, k);
                        if (e > k + 1 && s[e - 1] == '}') {
                            skipped.emplace_back(k, k + 1);
                            skipped.emplace_back(e - 1, e);
                            // \fbox's argument is text: the math in it between $ signs.
                            const std::size_t first = s.find_first_not_of(" \t\n", k + 1);
                            const std::size_t last = s.find_last_not_of(" \t\n", e - 2);
                            if (first != std::string_view::npos && last != std::string_view::npos && first < last &&
                                s[first] == '$' && s[last] == '$') {
                                skipped.emplace_back(first, first + 1);
                                skipped.emplace_back(last, last + 1);
                            }
                            i = k;
                            continue;
                        }
                    }
                }
                if (is_ignored_word(w)) {
                    i = j;
                    continue;
                }
                if (is_ignored_with_argument(w)) {
                    std::size_t k = j;
                    while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
                    i = (k < s.size() && s[k] == '{') ? skip_braces(s, k) : j;
                    continue;
                }
                // `\lvert x \rvert`, `\Vert \dot p \Vert`, `\arrowvert`: bars, as `|` (a norm of a scalar is its absolute
                // value; a vector's is refused where the vector is).
                if (is_one_of(w, {"\\vert", "\\lvert", "\\rvert", "\\Vert", "\\lVert", "\\rVert", "\\arrowvert",
                                  "\\Arrowvert"})) {
                    out.push_back({Tok::Char, "|", i, j - i, "", false});
                    i = j;
                    continue;
                }
                Token t{Tok::Word, w, i, j - i, "", false};
                if (w == "\\quad" || w == "\\qquad") t.space = true;
                if (takes_raw_argument(w)) {
                    std::size_t k = j;
                    while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
                    if (k < s.size() && s[k] == '{') {
                        const std::size_t e = skip_braces(s, k);
                        t.raw = std::string(s.substr(k + 1, e > k + 1 ? e - k - 2 : 0));
                        j = e;
                    } else if (k < s.size()) {
                        t.raw = std::string(1, s[k]);
                        j = k + 1;
                    }
                    t.length = j - i;
                }
                out.push_back(std::move(t));
                i = j;
                continue;
            }
            if (j < s.size()) {
                const char d = s[j];
                // Spacing commands: \, \; \: \! and "\ " (also a backslash at the end of a line: a space too).
                if (d == ',' || d == ';' || d == ':' || d == '!' || d == ' ' || d == '>' || d == '\n' || d == '\t' ||
                    d == '\r') {
                    i = j + 1;
                    continue;
                }
                // `m\_1`: Markdown's escaped underscore, a subscript in the math it renders.
                if (d == '_') {
                    out.push_back({Tok::Char, "_", i, 2, "", false});
                    i = j + 1;
                    continue;
                }
                // `\|\dot p\|`: a norm's bars, as `|`.
                if (d == '|') {
                    out.push_back({Tok::Char, "|", i, 2, "", false});
                    i = j + 1;
                    continue;
                }
                out.push_back({Tok::Word, std::string(s.substr(i, 2)), i, 2, "", false});
                i = j + 1;
                continue;
            }
            out.push_back({Tok::Char, "\\", i, 1, "", false});
            ++i;
            continue;
        }
        if (std::isalpha(c)) {
            // A function written without its backslash (`mglsin\theta`, `cos(\phi)`, as pages pasted from a word
            // processor write it): the function, when what follows cannot continue a word.
            static const char* const kBare[] = {"arcsin", "arccos", "arctan", "sinh", "cosh", "tanh", "sin", "cos",
                                                "tan",    "cot",    "sec",    "csc",  "exp",  "ln"};
            bool bare = false;
            for (const char* f : kBare) {
                const std::size_t n = std::strlen(f);
                if (s.compare(i, n, f) != 0 || i + n >= s.size()) continue;
                const unsigned char next = static_cast<unsigned char>(s[i + n]);
                const bool opens = next == '(' || next == '\\' || next == '{' || next == '^' || next == '_';
                if (!(opens || ((next == ' ' || next >= 0x80) && std::strcmp(f, "ln") != 0))) continue;
                out.push_back({Tok::Word, std::string("\\") + f, i, n, "", false});
                i += n;
                bare = true;
                break;
            }
            if (bare) continue;
            // `const`, `constant` without a backslash (`+ const.`): the additive constant, as `\text{const}` is.
            for (const char* word : {"constant", "const"}) {
                const std::size_t n = std::strlen(word);
                if (s.compare(i, n, word) != 0 || (i > 0 && (std::isalpha(static_cast<unsigned char>(s[i - 1])) ||
                                                             s[i - 1] == '\\')))
                    continue;
                if (i + n < s.size() && std::isalpha(static_cast<unsigned char>(s[i + n]))) continue;
                out.push_back({Tok::Word, "\\mathrm", i, n, word, false});
                i += n;
                bare = true;
                break;
            }
            if (bare) continue;
            // `KE`, `PE`: the kinetic and potential energy as blogs and notes abbreviate them, a name (as
            // `\mathrm{KE}` is), not K times E.
            if ((s.compare(i, 2, "KE") == 0 || s.compare(i, 2, "PE") == 0) &&
                (i == 0 || (!std::isalpha(static_cast<unsigned char>(s[i - 1])) && s[i - 1] != '\\')) &&
                (i + 2 >= s.size() || !std::isalpha(static_cast<unsigned char>(s[i + 2])))) {
                out.push_back({Tok::Word, "\\mathrm", i, 2, std::string(s.substr(i, 2)), false});
                i += 2;
                continue;
            }
            // `K.E.`, `P.E.` (the last dot may end the formula): the same names.
            if ((s.compare(i, 3, "K.E") == 0 || s.compare(i, 3, "P.E") == 0) &&
                (i == 0 || (!std::isalpha(static_cast<unsigned char>(s[i - 1])) && s[i - 1] != '\\')) &&
                (i + 3 >= s.size() || !std::isalpha(static_cast<unsigned char>(s[i + 3])))) {
                const std::size_t n = i + 3 < s.size() && s[i + 3] == '.' ? 4 : 3;
                out.push_back({Tok::Word, "\\mathrm", i, n, std::string(1, s[i]) + "E", false});
                i += n;
                continue;
            }
            // `frac{…}{…}`, `sqrt{…}` without their backslash (math pasted from a word processor).
            for (const char* word : {"dfrac", "frac", "sqrt"}) {
                const std::size_t n = std::strlen(word);
                if (s.compare(i, n, word) != 0 || i + n >= s.size() || s[i + n] != '{' ||
                    (i > 0 && (std::isalpha(static_cast<unsigned char>(s[i - 1])) || s[i - 1] == '\\')))
                    continue;
                out.push_back({Tok::Word, std::string("\\") + word, i, n, "", false});
                i += n;
                bare = true;
                break;
            }
            if (bare) continue;
            out.push_back({Tok::Letter, std::string(1, char(c)), i, 1, "", false});
            ++i;
            continue;
        }
        if (std::isdigit(c)) {
            out.push_back({Tok::Digit, std::string(1, char(c)), i, 1, "", false});
            ++i;
            continue;
        }
        if (c >= 0x80) {  // a UTF-8 sequence: one token, reported as unexpected
            std::size_t j = i + 1;
            while (j < s.size() && (static_cast<unsigned char>(s[j]) & 0xC0) == 0x80) ++j;
            out.push_back({Tok::Other, std::string(s.substr(i, j - i)), i, j - i, "", false});
            i = j;
            continue;
        }
        // A full stop ending the formula (`\frac{m_1 m_2}{m_1 + m_2 \,. }`): the sentence's, not a delimiter
        // (`\left.`) or a decimal point (`2.`, a digit right before it: after a space, `m_2 \,.`, it is not).
        if (c == '.' && s.find_first_not_of(" \t\n}", i + 1) == std::string_view::npos &&
            (i == 0 || !std::isdigit(static_cast<unsigned char>(s[i - 1]))) &&
            (out.empty() || !(out.back().kind == Tok::Word && is_one_of(out.back().text, {"\\left", "\\right"})))) {
            ++i;
            continue;
        }
        out.push_back({Tok::Char, std::string(1, char(c)), i, 1, "", false});
        ++i;
    }
    // `\frac{{\partial}{L}}{\partial{\dot{y}}}`: a ∂ in braces of its own is the ∂ (the braces dropped).
    for (std::size_t k = 0; k + 2 < out.size(); ++k)
        if (out[k].kind == Tok::Char && out[k].text == "{" && out[k + 1].kind == Tok::Word &&
            out[k + 1].text == "\\partial" && out[k + 2].kind == Tok::Char && out[k + 2].text == "}")
            out.erase(out.begin() + std::ptrdiff_t(k + 2)), out.erase(out.begin() + std::ptrdiff_t(k));
    return out;
}

}  // namespace

std::vector<Token> tokenize(std::string_view s) { return expand_macros(expand_text_macros(tokenize_text(s))); }

std::vector<Token> tokens_as_written(std::string_view s) { return tokenize_text(s); }

std::size_t group_end(const std::vector<Token>& t, std::size_t k) {
    if (k >= t.size() || t[k].kind != Tok::Char || t[k].text != "{") return k;
    int depth = 0;
    for (std::size_t q = k; q < t.size(); ++q) {
        if (t[q].kind != Tok::Char) continue;
        if (t[q].text == "{") ++depth;
        if (t[q].text == "}" && --depth == 0) return q + 1;
    }
    return k;
}


bool takes_raw_argument(const std::string& w) {
    return is_one_of(w, {"\\text", "\\textrm", "\\textit", "\\textbf", "\\mathrm", "\\mathit",
                         "\\operatorname", "\\mbox", "\\textnormal", "\\mathsf", "\\mathtt", "\\textsf"});
}

const std::set<std::string>& greek_letters() {
    static const std::set<std::string> g = {
        "alpha",    "beta",  "gamma",   "delta",    "epsilon",    "zeta",   "eta",      "theta",
        "iota",     "kappa", "lambda",  "mu",       "nu",         "xi",     "omicron",  "rho",
        "sigma",    "tau",   "upsilon", "phi",      "chi",        "psi",    "omega",    "Gamma",
        "Delta",    "Theta", "Lambda",  "Xi",       "Pi",         "Sigma",  "Upsilon",  "Phi",
        "Psi",      "Omega", "varphi",  "vartheta", "varepsilon", "varrho", "varsigma", "varpi",
        "varkappa", "ell",   "hbar",    "imath",    "jmath",      "digamma"};
    return g;
}

std::string normal_greek(const std::string& w) {  // w without backslash
    if (w == "varphi") return "phi";
    if (w == "vartheta") return "theta";
    if (w == "varepsilon") return "epsilon";
    if (w == "varrho") return "rho";
    if (w == "varsigma") return "sigma";
    if (w == "varkappa") return "kappa";
    return w;
}

}  // namespace eomgen::checker::latex
