/** @file text_macros.cpp  A derivation's own macros, read and expanded (text_macros.hpp). */
#include "checker/text_macros.hpp"

#include <cctype>
#include <optional>
#include <string>

namespace eomgen::checker {
namespace {

bool letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

void skip_space(std::string_view s, std::size_t& i) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
}

/// A control sequence at i (`\name`, or `\` and one other character), advancing i; "" when none.
std::string control_sequence(std::string_view s, std::size_t& i) {
    if (i >= s.size() || s[i] != '\\' || i + 1 >= s.size()) return "";
    std::size_t j = i + 1;
    if (letter(s[j]))
        while (j < s.size() && letter(s[j])) ++j;
    else
        ++j;
    std::string name(s.substr(i, j - i));
    i = j;
    return name;
}

/// The brace group at i without its braces, advancing past it; nothing when none opens at i (or it does not close).
std::optional<std::string> group(std::string_view s, std::size_t& i) {
    if (i >= s.size() || s[i] != '{') return std::nullopt;
    int depth = 0;
    for (std::size_t j = i; j < s.size(); ++j) {
        if (s[j] == '\\') {
            ++j;
            continue;
        }
        if (s[j] == '{') ++depth;
        if (s[j] == '}' && --depth == 0) {
            std::string inner(s.substr(i + 1, j - i - 1));
            i = j + 1;
            return inner;
        }
    }
    return std::nullopt;
}

/// `[...]` at i without its brackets (no nesting), advancing past it.
std::optional<std::string> bracket(std::string_view s, std::size_t& i) {
    if (i >= s.size() || s[i] != '[') return std::nullopt;
    const std::size_t close = s.find(']', i);
    if (close == std::string_view::npos) return std::nullopt;
    std::string inner(s.substr(i + 1, close - i - 1));
    i = close + 1;
    return inner;
}

/// The macro's name after `\newcommand`: `{\name}` or `\name`.
std::string defined_name(std::string_view s, std::size_t& i) {
    skip_space(s, i);
    if (i < s.size() && s[i] == '{') {
        std::size_t j = i;
        const auto g = group(s, j);
        if (!g) return "";
        const std::string_view inner = *g;
        std::size_t p = 0;
        while (p < inner.size() && std::isspace(static_cast<unsigned char>(inner[p]))) ++p;
        std::string name = control_sequence(inner, p);
        while (p < inner.size() && std::isspace(static_cast<unsigned char>(inner[p]))) ++p;
        if (p != inner.size()) return "";
        i = j;
        return name;
    }
    return control_sequence(s, i);
}

}  // namespace

std::vector<TextMacro> read_text_macros(std::string_view s) {
    std::vector<TextMacro> out;
    for (std::size_t i = s.find('\\'); i != std::string_view::npos && i < s.size(); i = s.find('\\', i)) {
        const std::size_t at = i;
        std::size_t j = i;
        const std::string command = control_sequence(s, j);
        if (command.empty()) {
            i = at + 1;
            continue;
        }
        i = j;
        TextMacro m;
        m.offset = at;
        if (command == "\\newcommand" || command == "\\renewcommand" || command == "\\providecommand") {
            if (j < s.size() && s[j] == '*') ++j;
            m.name = defined_name(s, j);
            skip_space(s, j);
            if (const auto n = bracket(s, j)) {
                try {
                    m.arguments = std::stoi(*n);
                } catch (...) {
                    continue;
                }
                skip_space(s, j);
                if (const auto d = bracket(s, j)) {
                    m.optional_first = true;
                    m.first_default = *d;
                }
            }
            skip_space(s, j);
            const auto body = group(s, j);
            if (m.name.empty() || !body || m.arguments < 0 || m.arguments > 9) continue;
            m.body = *body;
        } else if (command == "\\def") {
            m.name = control_sequence(s, j);
            while (j + 1 < s.size() && s[j] == '#' && s[j + 1] >= '1' && s[j + 1] <= '9') {  // #1#2...
                ++m.arguments;
                j += 2;
            }
            const auto body = group(s, j);
            if (m.name.empty() || !body) continue;
            m.body = *body;
        } else if (command == "\\let") {
            m.name = control_sequence(s, j);
            skip_space(s, j);
            if (j < s.size() && s[j] == '=') ++j;
            skip_space(s, j);
            m.body = control_sequence(s, j);
            if (m.name.empty() || m.body.empty()) continue;
        } else if (command == "\\DeclareMathOperator") {
            if (j < s.size() && s[j] == '*') ++j;
            m.name = defined_name(s, j);
            skip_space(s, j);
            const auto text = group(s, j);
            if (m.name.empty() || !text) continue;
            m.body = "\\operatorname{" + *text + "}";
        } else {
            continue;
        }
        i = j;
        out.push_back(std::move(m));
    }
    return out;
}

namespace latex {
namespace {

thread_local const std::vector<TextMacro>* g_macros = nullptr;

/// Bounds of expansion: passes over a row (a macro in a macro's body needs one more), and tokens in all.
constexpr int kMaxPasses = 8;
constexpr std::size_t kMaxTokens = 20000;

const TextMacro* find(const std::string& name) {
    const TextMacro* found = nullptr;
    for (const TextMacro& m : *g_macros)
        if (m.name == name) found = &m;  // the last definition wins
    return found;
}

/// The end of the argument at k: a brace group (one past its `}`), or one token; k when there is none.
std::size_t argument_end(const std::vector<Token>& t, std::size_t k) {
    while (k < t.size() && t[k].space) ++k;
    if (k >= t.size()) return k;
    if (t[k].kind == Tok::Char && t[k].text == "{") return group_end(t, k);
    if (t[k].kind == Tok::Char && (t[k].text == "}" || t[k].text == "#")) return k;
    return k + 1;
}

/// The tokens of an argument [from, to): a group's inside, or the one token.
std::vector<Token> argument(const std::vector<Token>& t, std::size_t from, std::size_t to) {
    while (from < to && t[from].space) ++from;
    if (to - from >= 2 && t[from].kind == Tok::Char && t[from].text == "{")
        return {t.begin() + std::ptrdiff_t(from) + 1, t.begin() + std::ptrdiff_t(to) - 1};
    return {t.begin() + std::ptrdiff_t(from), t.begin() + std::ptrdiff_t(to)};
}

/// One pass; `changed` says whether a macro was replaced.
std::vector<Token> expand_once(const std::vector<Token>& in, bool& changed) {
    std::vector<Token> out;
    out.reserve(in.size());
    for (std::size_t k = 0; k < in.size(); ++k) {
        const Token& use = in[k];
        const TextMacro* m = use.kind == Tok::Word ? find(use.text) : nullptr;
        if (!m) {
            out.push_back(use);
            continue;
        }
        std::vector<std::vector<Token>> args;
        std::size_t next = k + 1;
        bool complete = true;
        for (int a = 0; a < m->arguments; ++a) {
            if (a == 0 && m->optional_first) {
                std::size_t q = next;
                while (q < in.size() && in[q].space) ++q;
                if (q < in.size() && in[q].kind == Tok::Char && in[q].text == "[") {
                    std::size_t close = q + 1;
                    while (close < in.size() && !(in[close].kind == Tok::Char && in[close].text == "]")) ++close;
                    if (close == in.size()) {
                        complete = false;
                        break;
                    }
                    args.emplace_back(in.begin() + std::ptrdiff_t(q) + 1, in.begin() + std::ptrdiff_t(close));
                    next = close + 1;
                } else {
                    args.push_back(tokens_as_written(m->first_default));
                }
                continue;
            }
            const std::size_t end = argument_end(in, next);
            if (end == next) {
                complete = false;
                break;
            }
            args.push_back(argument(in, next, end));
            next = end;
        }
        if (!complete) {  // a use without its arguments: left as written
            out.push_back(use);
            continue;
        }
        // The body at the use's place; #k is the k-th argument's own tokens, which keep theirs.
        const std::vector<Token> body = tokens_as_written(m->body);
        for (std::size_t b = 0; b < body.size(); ++b) {
            if (body[b].kind == Tok::Char && body[b].text == "#" && b + 1 < body.size() && body[b + 1].kind == Tok::Digit) {
                const int a = body[b + 1].text[0] - '1';
                if (a >= 0 && a < static_cast<int>(args.size())) {
                    out.insert(out.end(), args[std::size_t(a)].begin(), args[std::size_t(a)].end());
                    ++b;
                    continue;
                }
            }
            Token made = body[b];
            made.offset = use.offset;
            made.length = use.length;
            out.push_back(std::move(made));
        }
        changed = true;
        k = next - 1;
    }
    return out;
}

}  // namespace

TextMacroScope::TextMacroScope(const std::vector<TextMacro>& macros) : previous_(g_macros) { g_macros = &macros; }

TextMacroScope::~TextMacroScope() { g_macros = previous_; }

std::vector<Token> expand_text_macros(std::vector<Token> t) {
    if (!g_macros || g_macros->empty()) return t;
    for (int pass = 0; pass < kMaxPasses; ++pass) {
        bool changed = false;
        std::vector<Token> next = expand_once(t, changed);
        if (!changed || next.size() > kMaxTokens) return changed && next.size() > kMaxTokens ? t : next;
        t = std::move(next);
    }
    return t;
}

}  // namespace latex
}  // namespace eomgen::checker
