/** @file latex_parser.cpp  Tokenizer, chain splitter and recursive-descent parser for derivation LaTeX. */
#include "checker/latex_parser.hpp"

#include "model/nonsmooth.hpp"

#include "checker/latex_normalize.hpp"
#include "checker/latex_tokens.hpp"
#include "checker/units.hpp"

#include <algorithm>
#include <cstring>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

namespace eomgen::checker {

REGISTER_FUNCTION(ddt, dummy().latex_name("\\frac{d}{dt}"))
REGISTER_FUNCTION(pdiff, dummy().latex_name("\\partial"))
REGISTER_FUNCTION(pbracket, dummy().latex_name("\\{\\}"))

const FreeName* LatexContext::free_name_of(const GiNaC::ex& symbol) const {
    if (!GiNaC::is_a<GiNaC::symbol>(symbol)) return nullptr;
    for (const auto& [name, free] : free_names)
        if (GiNaC::ex(free.symbol).is_equal(symbol)) return &free;
    return nullptr;
}

GiNaC::symbol LatexContext::free_symbol(const std::string& name, NameKind kind) {
    auto it = free_names.find(name);
    if (it != free_names.end()) return it->second.symbol;
    FreeName f{name, kind, GiNaC::symbol(name, name)};
    free_names.emplace(name, f);
    return f.symbol;
}

namespace {

using latex::greek_letters;
using latex::is_one_of;
using latex::normal_greek;
using latex::takes_raw_argument;
using latex::Tok;
using latex::Token;
using latex::tokenize;

// --------------------------------------------------------------------------------------------- names


std::string trim(std::string_view s) {
    std::size_t a = 0, b = s.size();
    while (a < b && (std::isspace(static_cast<unsigned char>(s[a])) || s[a] == '~')) ++a;
    while (b > a && (std::isspace(static_cast<unsigned char>(s[b - 1])) || s[b - 1] == '~')) --b;
    return std::string(s.substr(a, b - a));
}

bool is_plain_word(const std::string& s) {
    if (s.empty()) return false;
    for (char c : s)
        if (!std::isalpha(static_cast<unsigned char>(c))) return false;
    return true;
}

bool is_function_name(const std::string& f) {
    return is_one_of(f, {"sin", "cos", "tan", "cot", "sec", "csc", "exp", "ln", "log", "sinh", "cosh", "tanh",
                         "coth", "arcsin", "arccos", "arctan", "asin", "acos", "atan", "sgn", "sign"});
}

bool is_relation_word(const std::string& w) {
    return is_one_of(
        w, {"\\approx", "\\simeq", "\\equiv", "\\neq", "\\ne", "\\le", "\\leq", "\\ge", "\\geq", "\\leqslant",
            "\\geqslant", "\\ll", "\\gg", "\\sim", "\\propto", "\\cong", "\\lt", "\\gt", "\\doteq"});
}

bool is_hard_breaker(const std::string& w) {
    return is_one_of(w, {"\\rightarrow", "\\Rightarrow", "\\Longrightarrow", "\\longrightarrow", "\\implies",
                         "\\iff", "\\Leftrightarrow", "\\leftrightarrow", "\\to", "\\mapsto", "\\therefore",
                         "\\Longleftrightarrow"});
}

/// Failure inside the parser: where and why. Caught per side.
struct ParseFailure {
    std::size_t offset;
    std::string reason;
};

/// A name as read: accents, base, subscript, primes.
struct NameParts {
    int dots = 0;
    std::string base;
    std::string sub;
    int primes = 0;
    NameKind kind = NameKind::Unknown;
    std::string canonical(bool with_dots = true) const {
        std::string core = base;
        if (!sub.empty()) core += "_{" + sub + "}";
        core += std::string(static_cast<std::size_t>(primes), '\'');
        if (!with_dots || dots == 0) return core;
        static const char* const accents[] = {"\\dot{", "\\ddot{", "\\dddot{"};
        for (int left = dots; left > 0; left -= 3)
            core = std::string(accents[std::min(left, 3) - 1]) + core + "}";
        return core;
    }
};

// ---------------------------------------------------------------------------------------------- parser

struct IntegralFrame {
    bool found = false;
    std::string var;      ///< canonical name of the variable of integration
    GiNaC::ex var_value;  ///< what that name resolved to in the integrand
    std::size_t var_offset = 0;
};

class Parser {
  public:
    Parser(const std::vector<Token>& toks, std::size_t begin, std::size_t end, LatexContext& ctx, Side& side)
        : t_(toks), pos_(begin), end_(end), ctx_(ctx), side_(side) {}

    GiNaC::ex parse_all() {
        GiNaC::ex e = expr();
        skip_spaces();
        if (pos_ < end_) fail(pos_, "unexpected " + describe(pos_));
        return e;
    }

    /// Reads exactly one name from the whole range (for canonical_name).
    std::string read_name_only() {
        skip_spaces();
        if (pos_ >= end_) return "";
        NameParts n;
        if (!read_name(n)) return "";
        skip_spaces();
        if (pos_ < end_) return "";
        return n.canonical();
    }

  private:
    // ----- token access
    void skip_spaces() {
        while (pos_ < end_ && t_[pos_].space) ++pos_;
    }
    bool at_end() {
        skip_spaces();
        return pos_ >= end_;
    }
    const Token* peek() {
        skip_spaces();
        return pos_ < end_ ? &t_[pos_] : nullptr;
    }
    const Token* peek_at(std::size_t k) {
        std::size_t p = pos_;
        std::size_t seen = 0;
        while (p < end_) {
            if (!t_[p].space) {
                if (seen == k) return &t_[p];
                ++seen;
            }
            ++p;
        }
        return nullptr;
    }
    bool is_char(const Token* t, const char* c) const { return t && t->kind == Tok::Char && t->text == c; }
    bool is_word(const Token* t, const char* w) const { return t && t->kind == Tok::Word && t->text == w; }
    std::size_t offset_of(std::size_t p) const {
        if (p < t_.size()) return t_[p].offset;
        return t_.empty() ? 0 : t_.back().offset + t_.back().length;
    }
    std::string describe(std::size_t p) const {
        if (p >= t_.size()) return "end of the formula";
        const Token& t = t_[p];
        return "'" + t.text + (t.raw.empty() ? "" : "{" + t.raw + "}") + "'";
    }
    [[noreturn]] void fail(std::size_t p, const std::string& why) const {
        throw ParseFailure{offset_of(p), why};
    }

    /// Index of the '}' matching the '{' at p, or fail.
    std::size_t match_brace(std::size_t p) const {
        int depth = 0;
        for (std::size_t q = p; q < end_; ++q) {
            if (t_[q].kind != Tok::Char) continue;
            if (t_[q].text == "{") ++depth;
            if (t_[q].text == "}" && --depth == 0) return q;
        }
        fail(p, "missing '}' for this '{'");
    }

    /// The token range of a macro argument at pos_: a {group} (without braces) or one token. Advances pos_.
    std::pair<std::size_t, std::size_t> argument_range(const std::string& what) {
        skip_spaces();
        if (pos_ >= end_) fail(pos_, what + " needs an argument");
        if (is_char(&t_[pos_], "{")) {
            const std::size_t close = match_brace(pos_);
            const std::pair<std::size_t, std::size_t> r{pos_ + 1, close};
            pos_ = close + 1;
            return r;
        }
        if (is_char(&t_[pos_], "}")) fail(pos_, what + " needs an argument");
        const std::pair<std::size_t, std::size_t> r{pos_, pos_ + 1};
        ++pos_;
        return r;
    }

    /// Runs f with the parser restricted to [begin, end), requiring it to use the whole range.
    template <class F>
    auto within(std::size_t begin, std::size_t end, F f, const char* what) {
        const std::size_t saved_pos = pos_, saved_end = end_;
        pos_ = begin;
        end_ = end;
        auto result = f();
        skip_spaces();
        if (pos_ < end_) fail(pos_, std::string("unexpected ") + describe(pos_) + " in " + what);
        pos_ = saved_pos;
        end_ = saved_end;
        return result;
    }

    GiNaC::ex expr_in(std::pair<std::size_t, std::size_t> r, const char* what) {
        if (r.first >= r.second) fail(r.first, std::string("empty ") + what);
        return within(
            r.first, r.second, [this] { return expr(); }, what);
    }

    // ----- grammar
    struct DepthGuard {
        int& d;
        explicit DepthGuard(int& depth, std::size_t p, const Parser& parser) : d(depth) {
            if (++d > 150) parser.fail(p, "the formula is nested too deeply");
        }
        ~DepthGuard() { --d; }
    };

    bool stops_expression(const Token* t) const {
        if (!t) return true;
        if (t->kind == Tok::Char)
            return is_one_of(t->text, {")", "]", "}", ",", ";", "=", "<", ">", "&"}) ||
                   (t->text == "|" && abs_depth_ > 0);
        if (t->kind == Tok::Word)
            return t->text == "\\right" || t->text == "\\}" || t->text == "\\\\" || is_relation_word(t->text) ||
                   is_hard_breaker(t->text) || t->text == "\\end";
        return false;
    }

    GiNaC::ex expr() {
        DepthGuard g(depth_, pos_, *this);
        GiNaC::ex sum = 0;
        bool first = true;
        while (true) {
            const Token* t = peek();
            int sign = 1;
            if (is_char(t, "+") || is_char(t, "-")) {
                sign = t->text == "-" ? -1 : 1;
                ++pos_;
            } else if (is_word(t, "\\pm") || is_word(t, "\\mp")) {
                fail(pos_, "'" + t->text + "' (two equations in one) is not read");
            } else if (!first) {
                break;
            }
            if (stops_expression(peek())) {
                if (first && sign == 1) fail(pos_, "expected an expression, found " + describe(pos_));
                fail(pos_, "expected a term after the sign, found " + describe(pos_));
            }
            sum += sign * term();
            first = false;
            if (!(is_char(peek(), "+") || is_char(peek(), "-") || is_word(peek(), "\\pm") ||
                  is_word(peek(), "\\mp")))
                break;
        }
        return sum;
    }

    bool starts_factor(const Token* t) const {
        if (!t) return false;
        switch (t->kind) {
            case Tok::Letter:
            case Tok::Digit:
                return true;
            case Tok::Other:
                return true;  // reported as unexpected by primary()
            case Tok::Char:
                return is_one_of(t->text, {"(", "[", "{", "."}) || (t->text == "|" && abs_depth_ == 0);
            case Tok::Word:
                return !(stops_expression(t) || is_one_of(t->text, {"\\cdot", "\\times", "\\div", "\\pm",
                                                                    "\\mp", "\\ast", "\\star"}));
        }
        return false;
    }

    GiNaC::ex term() {
        DepthGuard g(depth_, pos_, *this);
        GiNaC::ex product = factor();
        while (true) {
            const Token* t = peek();
            if (!t) break;
            if (is_char(t, "*") || is_word(t, "\\cdot") || is_word(t, "\\times") || is_word(t, "\\ast")) {
                ++pos_;
                product = product * factor();
            } else if (is_char(t, "/") || is_word(t, "\\div")) {
                const std::size_t at = pos_;
                ++pos_;
                const GiNaC::ex d = factor();
                if (d.is_zero()) fail(at, "division by zero");
                product = product / d;
            } else if (starts_factor(t)) {
                // Every factor consumes a token; one that did not would multiply forever.
                const std::size_t at = pos_;
                product = product * factor();
                if (pos_ == at) fail(at, "unexpected " + describe(at));
            } else {
                break;
            }
        }
        return product;
    }

    GiNaC::ex factor() {
        DepthGuard g(depth_, pos_, *this);
        const Token* t = peek();
        if (is_char(t, "-")) {  // 2 \times -3
            ++pos_;
            return -factor();
        }
        GiNaC::ex base = primary();
        return postfix(base);
    }

    GiNaC::ex postfix(GiNaC::ex base) {
        while (true) {
            const Token* t = peek();
            if (is_char(t, "^")) {
                const std::size_t at = pos_;
                ++pos_;
                base = power(base, superscript(at), at);
            } else if (is_char(t, "!")) {
                fail(pos_, "factorials are not read");
            } else if (is_char(t, "'")) {
                fail(pos_, "a prime after an expression (not a name) is not read");
            } else if (is_char(t, "_")) {
                fail(pos_, "a subscript after an expression (not a name) is not read");
            } else {
                return base;
            }
        }
    }

    /// The exponent after '^' (pos_ just after it); degrees `^{\circ}` become the factor pi/180 via a marker.
    GiNaC::ex superscript(std::size_t at) {
        const auto r = argument_range("'^'");
        if (r.second == r.first + 1 && t_[r.first].kind == Tok::Word && t_[r.first].text == "\\circ")
            return degree_marker();
        if (r.first >= r.second) fail(at, "empty exponent");
        if (t_[r.first].kind == Tok::Word && t_[r.first].text == "\\prime")
            fail(at, "a prime after an expression (not a name) is not read");
        return expr_in(r, "the exponent");
    }

    static const GiNaC::symbol& degree_marker() {
        static const GiNaC::symbol s("__degree__");
        return s;
    }

    GiNaC::ex power(const GiNaC::ex& base, const GiNaC::ex& exponent, std::size_t at) {
        if (exponent.is_equal(degree_marker())) return base * GiNaC::Pi / 180;
        if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
            const GiNaC::numeric e = GiNaC::ex_to<GiNaC::numeric>(exponent);
            if (!e.is_rational()) fail(at, "the exponent is not a real number");
            // Large powers of sums would be expanded term by term; no derivation needs them.
            if (GiNaC::abs(e.numer()) > 12 || e.denom() > 12)
                fail(at, "the exponent is too large to compare");
            if (GiNaC::is_a<GiNaC::numeric>(base) && base.is_zero() && e.is_negative())
                fail(at, "division by zero");
        }
        return GiNaC::pow(base, exponent);
    }

    // primary := number | name | group | function | \frac | \sqrt | \int | \pi
    GiNaC::ex primary() {
        DepthGuard g(depth_, pos_, *this);
        const Token* t = peek();
        if (!t) fail(pos_, "expected an expression, found the end of the formula");
        const std::size_t at = pos_;
        switch (t->kind) {
            case Tok::Digit:
                return number();
            case Tok::Other:
                fail(at, "unexpected character " + describe(at));
            case Tok::Char:
                if (t->text == ".") {  // ".5"; "Fig. 1" is a full stop and a number
                    if (pos_ + 1 < end_ && t_[pos_ + 1].kind == Tok::Digit &&
                        t_[pos_ + 1].offset == t->offset + 1)
                        return number();
                    fail(at, "unexpected '.'");
                }
                if (t->text == "(" || t->text == "[") return bracket_group();
                if (t->text == "{") {
                    const std::size_t close = match_brace(pos_);
                    const std::pair<std::size_t, std::size_t> r{pos_ + 1, close};
                    pos_ = close + 1;
                    return expr_in(r, "the braces");
                }
                if (t->text == "|") return absolute_value(at);
                fail(at, "unexpected " + describe(at));
            case Tok::Letter:
                if (t->text == "d" && differential_here()) return differential();
                return name_value();
            case Tok::Word:
                return word(at);
        }
        fail(at, "unexpected " + describe(at));
    }

    GiNaC::ex number() {
        std::string digits, frac;
        bool point = false;
        const std::size_t at = pos_;
        while (pos_ < end_) {
            const Token& t = t_[pos_];
            if (t.kind == Tok::Digit) {
                (point ? frac : digits) += t.text;
                ++pos_;
            } else if (t.kind == Tok::Char && t.text == "." && !point && pos_ + 1 < end_ &&
                       t_[pos_ + 1].kind == Tok::Digit && t_[pos_ + 1].offset == t.offset + 1) {
                point = true;
                ++pos_;
            } else {
                break;
            }
            // Digits separated by spaces are separate numbers in LaTeX source only when written so; OCR'd
            // text writes "10" as one run, so only adjacent characters join.
            if (pos_ < end_ && t_[pos_].offset != t_[pos_ - 1].offset + 1) break;
        }
        if (pos_ == at) fail(at, "expected a number, found " + describe(at));
        if (digits.size() + frac.size() > 60) fail(at, "a number with too many digits");
        GiNaC::numeric v(0);
        for (char c : digits + frac) v = v * 10 + (c - '0');
        if (!frac.empty()) {
            GiNaC::numeric den = GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(long(frac.size())));
            v = v / den;
            if (!v.is_zero())
                side_.rounding += 0.5 / std::pow(10.0, double(frac.size())) / std::abs(v.to_double());
        }
        return v;
    }

    /// `V(r)`, `L(\theta, \dot\theta, t)`: a label letter written as a function of the coordinates, velocities
    /// or t. Returns true and moves past the `)` when the group at pos_ is such an argument list: the letter
    /// then stands alone (the caller multiplies it by 1), not times r.
    bool label_arguments() {
        const std::size_t at = pos_;
        if (at == 0 || t_[at].text != "(") return false;
        const Token& before = t_[at - 1];
        if (before.kind != Tok::Letter || before.offset + before.length != t_[at].offset) return false;
        static const char* const kLabels[] = {"T", "V", "U", "L", "H", "E", "K"};
        if (std::none_of(std::begin(kLabels), std::end(kLabels), [&](const char* l) { return before.text == l; }))
            return false;
        const std::size_t saved = pos_, saved_uses = side_.uses.size(), saved_notes = side_.notes.size();
        const int saved_abs = abs_depth_;
        try {
            ++pos_;
            while (true) {
                const GiNaC::ex e = expr();
                if (!GiNaC::is_a<GiNaC::symbol>(e) || ctx_.free_name_of(e) != nullptr) throw ParseFailure{0, ""};
                const Token* t = peek();
                if (is_char(t, ",")) {
                    ++pos_;
                    continue;
                }
                if (!is_char(t, ")")) throw ParseFailure{0, ""};
                ++pos_;
                return true;
            }
        } catch (const ParseFailure&) {
            pos_ = saved;
            abs_depth_ = saved_abs;
            side_.uses.resize(saved_uses);
            side_.notes.resize(saved_notes);
            return false;
        }
    }

    /// `(t)` right after a name (`\theta(t)`, `\dot{x}_1(t)`, `s(t)`, `y'(t)`): the name as a function of time, the
    /// name itself, not times t. Moves past the `)` when it is.
    bool of_time() {
        const std::size_t at = pos_;
        if (at == 0 || at + 2 >= t_.size() || t_[at].text != "(" || t_[at + 1].text != "t" || t_[at + 2].text != ")")
            return false;
        const Token& before = t_[at - 1];
        if (before.offset + before.length != t_[at].offset) return false;  // `m g (t)` is a product
        const bool name_end = before.kind == Tok::Letter || (before.kind == Tok::Word && !is_function_name(before.text.substr(1))) ||
                              (before.kind == Tok::Char && (before.text == "}" || before.text == "'"));
        if (!name_end) return false;
        pos_ += 3;
        return true;
    }

    GiNaC::ex bracket_group() {
        if (label_arguments()) return 1;
        if (of_time()) return 1;
        const std::size_t at = pos_;
        const std::string open = t_[pos_].text;
        const std::string close = open == "(" ? ")" : "]";
        ++pos_;
        const int saved_abs = abs_depth_;
        abs_depth_ = 0;
        GiNaC::ex e = expr();
        abs_depth_ = saved_abs;
        const Token* t = peek();
        if (is_char(t, ",")) {
            // F(a, b) right after a name: a function the checker does not know, not a vector.
            if (at > 0 && (t_[at - 1].kind == Tok::Letter || t_[at - 1].kind == Tok::Word) &&
                !ctx_.names.count(t_[at - 1].text) && t_[at - 1].text.size() == 1 &&
                t_[at - 1].offset + t_[at - 1].length >= t_[at].offset - 1 && open == "(")
                fail(at - 1, "an unknown function " + t_[at - 1].text + "(...) is not evaluated");
            fail(at, "a vector or tuple (a, b, ...) is not compared");
        }
        if (!is_char(t, close.c_str()) &&
            !(t && t->kind == Tok::Char && (t->text == ")" || t->text == "]"))) {
            if (t && !stops_expression(t)) fail(pos_, "unexpected " + describe(pos_));
            fail(at, "missing '" + close + "' for this '" + open + "'");
        }
        ++pos_;
        return e;
    }

    /// `\{a, b\}`: a Poisson bracket, evaluated by the checker (it knows the momenta).
    GiNaC::ex poisson_bracket(std::size_t at) {
        ++pos_;
        const GiNaC::ex a = expr();
        // `\frac{m}{2}\{a^2 + b^2\}`: braces as brackets (around one name alone, a bracket that lost its comma).
        if (is_word(peek(), "\\}") && !GiNaC::is_a<GiNaC::symbol>(a)) {
            ++pos_;
            return a;
        }
        if (!is_char(peek(), ",")) fail(at, "a brace \\{ that is not a Poisson bracket \\{a, b\\} is not read");
        ++pos_;
        const GiNaC::ex b = expr();
        if (!is_word(peek(), "\\}")) fail(at, "missing '\\}' for this '\\{'");
        ++pos_;
        return pbracket(a, b);
    }

    GiNaC::ex absolute_value(std::size_t at) {
        ++pos_;
        ++abs_depth_;
        GiNaC::ex e = expr();
        --abs_depth_;
        if (!is_char(peek(), "|")) fail(at, "missing '|' for this '|'");
        ++pos_;
        return eomgen::real_abs(e);
    }

    GiNaC::ex left_right(std::size_t at) {
        ++pos_;  // \left
        const Token* d = peek();
        if (!d) fail(at, "\\left needs a delimiter");
        const std::string delim = d->text;
        ++pos_;
        if (delim == "\\|" || delim == "\\Vert" || delim == "\\lVert") fail(at, "a norm \\| \\| is not read");
        const int saved_abs = abs_depth_;
        abs_depth_ = 0;
        GiNaC::ex e = expr();
        abs_depth_ = saved_abs;
        const Token* t = peek();
        if (is_char(t, ",")) fail(at, "a vector or tuple (a, b, ...) is not compared");
        if (!is_word(t, "\\right")) {
            if (t && !stops_expression(t)) fail(pos_, "unexpected " + describe(pos_));
            if (t && t->kind == Tok::Char && t->text != ")" && t->text != "]" && t->text != "}")
                fail(pos_, "unexpected " + describe(pos_));
            fail(at, "missing \\right for this \\left");
        }
        ++pos_;
        const Token* rd = peek();
        if (!rd) fail(at, "\\right needs a delimiter");
        const std::string rdelim = rd->text;
        ++pos_;
        if ((delim == "|" || delim == "\\vert" || delim == "\\lvert")) return eomgen::real_abs(e);
        if (delim == "." && rdelim == "|") fail(at, "an evaluation bar \\left. \\right| is not read");
        if (delim == "\\langle") fail(at, "angle brackets are not read");
        return e;
    }

    // ----- names

    bool starts_name(const Token* t) const {
        if (!t) return false;
        if (t->kind == Tok::Letter) return true;
        if (t->kind != Tok::Word) return false;
        const std::string w = t->text.substr(1);
        return greek_letters().count(w) ||
               is_one_of(t->text,
                         {"\\dot",      "\\ddot",    "\\dddot",     "\\mathbf",         "\\boldsymbol",
                          "\\bm",       "\\vec",     "\\hat",       "\\underline",      "\\bar",
                          "\\tilde",    "\\mathcal", "\\mathscr",   "\\mathfrak",       "\\mathbb",
                          "\\overline", "\\widehat", "\\widetilde", "\\overrightarrow", "\\check",
                          "\\breve",    "\\text",    "\\textrm",    "\\mathrm",         "\\mathit",
                          "\\mbox",     "\\textit",  "\\textbf",    "\\textnormal",     "\\mathsf",
                          "\\mathtt",   "\\textsf"});
    }

    /// Reads a name at pos_ into n (accents, base, subscripts, primes). False when there is none.
    /// A `^{\prime 2}` leaves the exponent 2 in pending_power_.
    /// The name in the braces of the command at token `at` (\dot{x}, \mathbf{r}, \bar{m}); moves past it.
    NameParts argument_name(std::size_t at, const char* what) {
        ++pos_;
        const auto r = argument_range(t_[at].text);
        NameParts inner;
        within(
            r.first, r.second,
            [&] {
                if (!read_name(inner)) fail(r.first, t_[at].text + " of an expression is not read");
                return 0;
            },
            what);
        return inner;
    }

    bool read_name(NameParts& n) {
        const Token* t = peek();
        if (!t) return false;
        const std::size_t at = pos_;
        if (t->kind == Tok::Letter) {
            n.base = t->text;
            ++pos_;
        } else if (t->kind == Tok::Word) {
            const std::string w = t->text.substr(1);
            if (greek_letters().count(w)) {
                n.base = "\\" + normal_greek(w);
                ++pos_;
                // \Delta t, \delta x: one name, an increment, not a product.
                const Token* next = peek();
                if ((w == "Delta" || w == "delta") && next && next->kind == Tok::Letter) {
                    n.base += " " + next->text;
                    ++pos_;
                }
            } else if (w == "dot" || w == "ddot" || w == "dddot") {
                const int d = w == "dot" ? 1 : (w == "ddot" ? 2 : 3);
                const NameParts inner = argument_name(at, "the accent");
                n = inner;
                n.dots += d;
            } else if (is_one_of(t->text, {"\\mathbf", "\\boldsymbol", "\\bm", "\\vec", "\\hat",
                                           "\\underline", "\\overrightarrow", "\\widehat"})) {
                const NameParts inner = argument_name(at, "the vector");
                n.base = t_[at].text + "{" + inner.canonical() + "}";
                n.kind = NameKind::Vector;
            } else if (is_one_of(t->text, {"\\bar", "\\tilde", "\\mathcal", "\\mathscr", "\\mathfrak",
                                           "\\mathbb", "\\overline", "\\widetilde", "\\check", "\\breve"})) {
                const NameParts inner = argument_name(at, "the accent");
                n.base = t_[at].text + "{" + inner.canonical() + "}";
                n.kind = inner.kind;
            } else if (takes_raw_argument(t->text) && t->text != "\\operatorname") {
                const std::string content = trim(t->raw);
                if (is_unit_command(t->text, t->raw)) {
                    n.base = "\\mathrm{" + content + "}";
                    n.kind = NameKind::Unit;
                } else if (is_plain_word(content)) {
                    n.base = content;
                } else {
                    return false;
                }
                ++pos_;
            } else {
                return false;
            }
        } else {
            return false;
        }
        // Subscripts and primes, in any order: x_{a}', x'_{a}, x^{\prime}_{1}.
        while (true) {
            const Token* s = peek();
            if (is_char(s, "_")) {
                if (!n.sub.empty()) fail(pos_, "double subscript");
                const std::size_t sat = pos_;
                ++pos_;
                const auto r = argument_range("'_'");
                n.sub = subscript_text(r.first, r.second);
                if (n.sub.empty()) fail(sat, "empty subscript");
            } else if (is_char(s, "'")) {
                ++n.primes;
                ++pos_;
            } else if (is_char(s, "^") && prime_superscript(n)) {
                continue;
            } else if (is_char(s, "^") && exponent_before_subscript(n)) {
                continue;
            } else {
                break;
            }
        }
        return true;
    }

    /// At '^': when the superscript starts with \prime, counts the primes into n and leaves any rest of the
    /// superscript (`^{\prime 2}`) as pending_power_. Returns false (pos_ unchanged) when it is an exponent.
    bool prime_superscript(NameParts& n) {
        const std::size_t at = pos_;
        const Token* a = peek_at(1);
        if (!a) return false;
        if (a->kind == Tok::Word && a->text == "\\prime") {
            ++pos_;
            ++pos_;
            ++n.primes;
            return true;
        }
        if (!(a->kind == Tok::Char && a->text == "{")) return false;
        // pos_ at '^'; find the '{'
        std::size_t open = pos_ + 1;
        while (open < end_ && t_[open].space) ++open;
        const std::size_t close = match_brace(open);
        std::size_t q = open + 1;
        int primes = 0;
        while (q < close && t_[q].kind == Tok::Word && t_[q].text == "\\prime") {
            ++primes;
            ++q;
        }
        if (primes == 0) {
            pos_ = at;
            return false;
        }
        n.primes += primes;
        if (q < close) {
            if (has_pending_power_) fail(at, "double exponent");
            pending_power_ = expr_in({q, close}, "the exponent");
            has_pending_power_ = true;
        }
        pos_ = close + 1;
        return true;
    }

    /// At '^': `x^{2}_{1}` (as many editors write x₁²): the exponent comes before the subscript. Leaves the
    /// exponent in pending_power_ and returns true when a subscript follows it and the name has none yet.
    bool exponent_before_subscript(const NameParts& n) {
        if (!n.sub.empty()) return false;
        std::size_t q = pos_ + 1;
        while (q < end_ && t_[q].space) ++q;
        if (q >= end_) return false;
        const std::size_t after = is_char(&t_[q], "{") ? match_brace(q) + 1 : q + 1;
        std::size_t u = after;
        while (u < end_ && t_[u].space) ++u;
        if (u >= end_ || !is_char(&t_[u], "_")) return false;
        const std::size_t at = pos_;
        if (has_pending_power_) fail(at, "double exponent");
        ++pos_;
        pending_power_ = superscript(at);
        has_pending_power_ = true;
        return true;
    }

    /// A subscript as canonical text: `\text {rod }` → rod, `x^{\prime}` → x', `1 x` → 1x.
    std::string subscript_text(std::size_t b, std::size_t e) const {
        std::string s;
        for (std::size_t q = b; q < e; ++q) {
            const Token& t = t_[q];
            if (t.space) continue;
            if (t.kind == Tok::Word) {
                if (t.text == "\\prime") {
                    s += "'";
                } else if (!t.raw.empty() || takes_raw_argument(t.text)) {
                    std::string content = trim(t.raw);
                    content.erase(std::remove(content.begin(), content.end(), ' '), content.end());
                    s += content;
                } else {
                    const std::string w = t.text.substr(1);
                    s += greek_letters().count(w) ? "\\" + normal_greek(w) : t.text;
                }
            } else if (t.kind == Tok::Char && (t.text == "{" || t.text == "}")) {
                continue;
            } else if (t.kind == Tok::Char && t.text == "^") {
                continue;  // x_{a^{\prime}}: the prime is kept, the caret is noise
            } else {
                s += t.text;
            }
        }
        return s;
    }

    /// The value of the name at pos_: known, d/dt of a known name, or a free name.
    GiNaC::ex name_value() {
        const std::size_t at = pos_;
        NameParts n;
        has_pending_power_ = false;
        if (!read_name(n)) fail(at, "unexpected " + describe(at));
        // `e^{\alpha t}`: Euler's number raised to a power is the exponential, unless the model or the text
        // gives e a meaning of its own (an eccentricity, a restitution coefficient).
        if (n.base == "e" && n.sub.empty() && n.dots == 0 && n.primes == 0 && !ctx_.names.count("e")) {
            if (has_pending_power_) {
                has_pending_power_ = false;
                return GiNaC::exp(pending_power_);
            }
            if (is_char(peek(), "^")) {
                const std::size_t pat = pos_;
                ++pos_;
                return GiNaC::exp(superscript(pat));
            }
        }
        GiNaC::ex v = resolve(n, at);
        if (has_pending_power_) {
            has_pending_power_ = false;
            v = power(v, pending_power_, at);
        }
        return v;
    }

    GiNaC::ex resolve(const NameParts& n, std::size_t at) {
        const std::string full = n.canonical();
        auto it = ctx_.names.find(full);
        if (it != ctx_.names.end()) return it->second;
        if (n.dots > 0) {
            auto base = ctx_.names.find(n.canonical(false));
            if (base != ctx_.names.end()) {
                GiNaC::ex v = base->second;
                for (int i = 0; i < n.dots; ++i) v = ddt(v);
                return v;
            }
        }
        // \text{ml} where m and l are known: OCR'd products such as "2 \mathrm{ml}^{2}".
        if (n.dots == 0 && n.sub.empty() && n.primes == 0 && n.kind == NameKind::Unknown &&
            n.base.size() > 1 && is_plain_word(n.base)) {
            bool all_known = true;
            for (char c : n.base) all_known = all_known && ctx_.names.count(std::string(1, c));
            if (all_known) {
                GiNaC::ex v = 1;
                for (char c : n.base) v *= ctx_.names.at(std::string(1, c));
                return v;
            }
        }
        side_.uses.push_back({full, offset_of(at)});
        return ctx_.free_symbol(full, n.kind);
    }

    // ----- differentials and integrals

    /// 'd' followed by a name, inside an integral whose variable is not yet read.
    bool differential_here() {
        if (frames_.empty() || frames_.back().found) return false;
        const Token* next = peek_at(1);
        return starts_name(next);
    }

    GiNaC::ex differential() {
        const std::size_t at = pos_;
        ++pos_;  // d
        NameParts n;
        has_pending_power_ = false;
        if (!read_name(n)) fail(at, "expected the variable of integration after 'd'");
        if (has_pending_power_) fail(at, "a power of a differential is not read");
        IntegralFrame& f = frames_.back();
        f.found = true;
        f.var = n.canonical();
        f.var_offset = offset_of(at);
        auto it = ctx_.names.find(f.var);
        f.var_value = it != ctx_.names.end() ? it->second : GiNaC::ex(ctx_.free_symbol(f.var, n.kind));
        return 1;
    }

    GiNaC::ex integral(std::size_t at) {
        ++pos_;  // \int
        GiNaC::ex lo, hi;
        bool has_lo = false, has_hi = false;
        for (int k = 0; k < 2; ++k) {
            const Token* t = peek();
            if (is_char(t, "_") && !has_lo) {
                ++pos_;
                lo = expr_in(argument_range("'_'"), "the lower limit");
                has_lo = true;
            } else if (is_char(t, "^") && !has_hi) {
                ++pos_;
                hi = expr_in(argument_range("'^'"), "the upper limit");
                has_hi = true;
            }
        }
        if (!has_lo && !has_hi) fail(at, "an indefinite integral is not evaluated");
        if (!has_lo || !has_hi) fail(at, "an integral over a region is not evaluated");
        frames_.push_back({});
        GiNaC::ex body = 1;
        while (!frames_.back().found) {
            const Token* t = peek();
            if (!t || is_char(t, "+") || is_char(t, "-")) break;
            if (is_char(t, "/") || is_word(t, "\\div")) {
                ++pos_;
                body = body / factor();
                continue;
            }
            if (is_word(t, "\\cdot") || is_word(t, "\\times") || is_char(t, "*")) {
                ++pos_;
                continue;
            }
            if (!starts_factor(t)) break;
            body = body * factor();
        }
        IntegralFrame f = frames_.back();
        frames_.pop_back();
        if (!f.found) fail(at, "the integral has no differential d<variable>");
        if (!GiNaC::is_a<GiNaC::symbol>(f.var_value))
            fail(f.var_offset, "the variable of integration " + f.var + " is mapped to an expression");
        GiNaC::ex var = f.var_value;
        // "∫ dψ'/√(−sin ψ)": the integrand uses the unprimed name; read it as the variable, and say so.
        if (!body.has(var) && !f.var.empty() && f.var.back() == '\'') {
            std::string unprimed = f.var;
            while (!unprimed.empty() && unprimed.back() == '\'') unprimed.pop_back();
            GiNaC::ex alt;
            auto kn = ctx_.names.find(unprimed);
            if (kn != ctx_.names.end()) alt = kn->second;
            auto fr = ctx_.free_names.find(unprimed);
            if (fr != ctx_.free_names.end()) alt = fr->second.symbol;
            if (GiNaC::is_a<GiNaC::symbol>(alt) && body.has(alt)) {
                side_.notes.push_back("the integrand uses $" + unprimed +
                                      "$ where the variable of integration is $" + f.var +
                                      "$; read as the same variable");
                var = alt;
                remove_uses(unprimed, offset_of(at));
            }
        }
        remove_uses(f.var, offset_of(at));
        const GiNaC::symbol bound(f.var, f.var);
        body = body.subs(var == bound);
        lo = lo.subs(var == bound);  // a limit in the variable itself is nonsense; keep it visible
        hi = hi.subs(var == bound);
        GiNaC::ex v = GiNaC::integral(bound, lo, hi, body);
        try {
            v = v.eval_integ();
        } catch (const std::exception&) {
        }
        return v;
    }

    void remove_uses(const std::string& name, std::size_t from) {
        auto& u = side_.uses;
        u.erase(std::remove_if(u.begin(), u.end(),
                               [&](const NameUse& x) { return x.name == name && x.offset >= from; }),
                u.end());
    }

    // ----- control words

    GiNaC::ex word(std::size_t at) {
        const Token& t = t_[pos_];
        const std::string w = t.text;
        const std::string bare = w.substr(1);
        if (w == "\\left") return left_right(at);
        if (w == "\\{") return poisson_bracket(at);
        if (w == "\\pi") {
            ++pos_;
            auto it = ctx_.names.find("\\pi");
            return it != ctx_.names.end() ? it->second : GiNaC::ex(GiNaC::Pi);
        }
        if (w == "\\frac" || w == "\\dfrac" || w == "\\tfrac" || w == "\\cfrac") return fraction(at);
        if (w == "\\sqrt") return square_root(at);
        if (w == "\\int" || w == "\\intop") return integral(at);
        if (is_function_name(bare)) {
            ++pos_;
            return function(bare, at);
        }
        if (w == "\\operatorname") {
            std::string f = trim(t.raw);
            f.erase(std::remove(f.begin(), f.end(), ' '), f.end());
            if (f == "dot" || f == "ddot") {  // OCR: "\operatorname{dot} \phi" for \dot{\phi}
                ++pos_;
                NameParts n;
                has_pending_power_ = false;
                if (!read_name(n)) fail(at, "\\operatorname{" + f + "} of an expression is not read");
                n.dots += f == "dot" ? 1 : 2;
                GiNaC::ex v = resolve(n, at);
                if (has_pending_power_) {
                    has_pending_power_ = false;
                    v = power(v, pending_power_, at);
                }
                return v;
            }
            if (is_function_name(f)) {
                ++pos_;
                return function(f, at);
            }
            fail(at, "the function '" + f + "' is not known");
        }
        if (w == "\\text" || w == "\\textrm" || w == "\\mathrm" || w == "\\mathit" || w == "\\mbox" ||
            w == "\\textit" || w == "\\textbf" || w == "\\textnormal" || w == "\\mathsf" || w == "\\mathtt" ||
            w == "\\textsf") {
            const std::string content = trim(t.raw);
            if (content == "d" && !frames_.empty() && !frames_.back().found) {
                // \mathrm{d} x
                return differential();
            }
            if (content.empty()) {
                ++pos_;
                return 1;
            }
            if (content == "sgn" || content == "sign") {  // \mathrm{sgn}(\dot x), \text{sign}(v)
                ++pos_;
                return function(content, at);
            }
            if (content.find_first_not_of(".,;: ") == std::string::npos) {  // `\text{. }`: the sentence's stop
                std::size_t next = pos_ + 1;
                while (next < end_ && t_[next].space) ++next;
                if (next >= end_) {
                    ++pos_;
                    return 1;
                }
            }
            if (is_plain_word(content) || is_unit_command(w, t.raw)) return name_value();
            fail(at, "text '" + content + "' in a formula is not read");
        }
        if (starts_name(&t)) return name_value();
        if (w == "\\partial")
            fail(at, "a partial derivative outside \\frac{\\partial ...}{\\partial ...} is not read");
        if (w == "\\begin") fail(at, "a matrix or array is not compared");
        if (w == "\\sum" || w == "\\prod") fail(at, "sums and products (" + w + ") are not evaluated");
        if (w == "\\lim") fail(at, "limits are not evaluated");
        if (w == "\\infty") fail(at, "infinity is not compared");
        if (w == "\\nabla") fail(at, "vector calculus (\\nabla) is not read");
        if (is_one_of(w, {"\\dots", "\\ldots", "\\cdots", "\\vdots", "\\ddots"}))
            fail(at, "an ellipsis is not read");
        if (is_one_of(w, {"\\det", "\\max", "\\min", "\\sup", "\\inf", "\\arg", "\\deg", "\\dim", "\\ker",
                          "\\Pr", "\\gcd"}))
            fail(at, "the function '" + bare + "' is not read");
        if (w == "\\%") {
            ++pos_;
            return GiNaC::numeric(1, 100);
        }
        if (w == "\\prime") fail(at, "a prime without a name");
        fail(at, "the command " + w + " is not read");
    }

    GiNaC::ex function(const std::string& f, std::size_t at) {
        // Optional power before the argument: \sin^{2} \alpha.
        GiNaC::ex pw = 1;
        bool has_pw = false;
        if (is_char(peek(), "^")) {
            const std::size_t pat = pos_;
            ++pos_;
            pw = superscript(pat);
            has_pw = true;
        }
        const Token* t = peek();
        if (!t || stops_expression(t) || is_char(t, "+") || is_char(t, "-"))
            fail(at, "\\" + f + " needs an argument");
        GiNaC::ex arg;
        if (is_char(t, "(") || is_char(t, "[") || is_char(t, "{") || is_word(t, "\\left")) {
            arg = primary();
        } else {
            // A bare argument is one factor, extended over a following time `t` (\cos \Omega t) or after a
            // leading number (\sin 2\theta): the conventions of physics texts.
            const bool leading_number = t->kind == Tok::Digit;
            arg = factor();
            while (true) {
                const Token* n = peek();
                const bool time_next = n && n->kind == Tok::Letter && n->text == "t" &&
                                       !is_char(peek_at(1), "_") && !is_char(peek_at(1), "'");
                if (time_next ||
                    (leading_number && starts_name(n) && !(n->kind == Tok::Letter && n->text == "d"))) {
                    arg = arg * factor();
                    if (!time_next) break;
                } else {
                    break;
                }
            }
        }
        GiNaC::ex v;
        if (f == "sin")
            v = GiNaC::sin(arg);
        else if (f == "cos")
            v = GiNaC::cos(arg);
        else if (f == "tan")
            v = GiNaC::tan(arg);
        else if (f == "cot")
            v = GiNaC::cos(arg) / GiNaC::sin(arg);
        else if (f == "sec")
            v = 1 / GiNaC::cos(arg);
        else if (f == "csc")
            v = 1 / GiNaC::sin(arg);
        else if (f == "exp")
            v = GiNaC::exp(arg);
        else if (f == "ln" || f == "log")
            v = GiNaC::log(arg);
        else if (f == "sinh")
            v = GiNaC::sinh(arg);
        else if (f == "cosh")
            v = GiNaC::cosh(arg);
        else if (f == "tanh")
            v = GiNaC::tanh(arg);
        else if (f == "coth")
            v = GiNaC::cosh(arg) / GiNaC::sinh(arg);
        else if (f == "arcsin" || f == "asin")
            v = GiNaC::asin(arg);
        else if (f == "arccos" || f == "acos")
            v = GiNaC::acos(arg);
        else if (f == "sgn" || f == "sign")
            v = eomgen::sign(arg);  // the model language's sign (sign(0) = 0), real_abs's derivative
        else
            v = GiNaC::atan(arg);
        return has_pw ? power(v, pw, at) : v;
    }

    GiNaC::ex square_root(std::size_t at) {
        ++pos_;
        GiNaC::ex index = 2;
        if (is_char(peek(), "[")) {
            const std::size_t open = pos_;
            std::size_t close = open + 1;
            while (close < end_ && !(t_[close].kind == Tok::Char && t_[close].text == "]")) ++close;
            if (close >= end_) fail(open, "missing ']' for this '['");
            index = expr_in({open + 1, close}, "the root's index");
            pos_ = close + 1;
            if (index.is_zero()) fail(at, "a zeroth root");
        }
        const GiNaC::ex radicand = expr_in(argument_range("\\sqrt"), "the square root");
        return power(radicand, 1 / index, at);
    }

    /// Is the range a derivative's numerator/denominator: starts with d, \mathrm{d} or \partial?
    int derivative_marker(std::size_t b, std::size_t e) const {
        while (b < e && t_[b].space) ++b;
        if (b >= e) return 0;
        const Token& t = t_[b];
        if (t.kind == Tok::Letter && t.text == "d") return 1;
        if (t.kind == Tok::Word && (t.text == "\\mathrm" || t.text == "\\text") && trim(t.raw) == "d")
            return 1;
        if (t.kind == Tok::Word && t.text == "\\partial") return 2;
        if (t.kind == Tok::Word && t.text == "\\delta") return 3;  // \frac{\delta L}{\delta q}: the text's ∂
        return 0;
    }

    GiNaC::ex fraction(std::size_t at) {
        ++pos_;
        const auto num = argument_range("\\frac");
        const auto den = argument_range("\\frac");
        const int kn = derivative_marker(num.first, num.second),
                  kd = derivative_marker(den.first, den.second);
        // A fraction is a derivative when both parts start with d (or ∂) and the denominator is d<name>[^n].
        if (kn != 0 && kn == kd) {
            bool is_derivative = false;
            NameParts var;
            int order = 1;
            within(
                den.first, den.second,
                [&] {
                    ++pos_;  // d or \partial
                    has_pending_power_ = false;
                    // `\partial{\dot{\theta}_1}`: the variable in braces, as some notebooks write it.
                    skip_spaces();
                    std::size_t close = 0;
                    if (is_char(peek(), "{")) {
                        close = match_brace(pos_);
                        ++pos_;
                    }
                    const bool named = read_name(var) && !has_pending_power_;
                    if (named && close != 0) skip_spaces();
                    if (named && (close == 0 || pos_ == close)) {
                        if (close != 0) ++pos_;
                        is_derivative = true;
                        if (is_char(peek(), "^")) {
                            const std::size_t pat = pos_;
                            ++pos_;
                            const GiNaC::ex o = superscript(pat);
                            if (!GiNaC::is_a<GiNaC::numeric>(o) ||
                                !GiNaC::ex_to<GiNaC::numeric>(o).is_pos_integer() ||
                                GiNaC::ex_to<GiNaC::numeric>(o).to_int() > 4)
                                fail(pat, "the order of a derivative must be 1 to 4");
                            order = GiNaC::ex_to<GiNaC::numeric>(o).to_int();
                        }
                    } else {
                        pos_ = den.second;
                    }
                    has_pending_power_ = false;
                    return 0;
                },
                "the denominator");
            if (is_derivative) {
                if (kn == 3 && std::none_of(side_.notes.begin(), side_.notes.end(), [](const std::string& n) {
                        return n.rfind("reads \\delta", 0) == 0;
                    }))
                    side_.notes.push_back("reads \\delta in $\\frac{\\delta \\dots}{\\delta \\dots}$ as $\\partial$, as the text uses it");
                return derivative(at, num, var, order, kn >= 2);
            }
        }
        const GiNaC::ex n = expr_in(num, "the numerator");
        const GiNaC::ex d = expr_in(den, "the denominator");
        if (d.is_zero()) fail(at, "division by zero");
        return n / d;
    }

    GiNaC::ex derivative(std::size_t at, std::pair<std::size_t, std::size_t> num, const NameParts& var,
                         int order, bool partial) {
        // Numerator: d[^n] [operand]; without an operand the derivative applies to the next factor.
        std::size_t b = num.first;
        while (b < num.second && t_[b].space) ++b;
        ++b;  // d or \partial
        while (b < num.second && t_[b].space) ++b;
        if (b < num.second && t_[b].kind == Tok::Char && t_[b].text == "^") {
            std::size_t q = b + 1;
            if (q < num.second && t_[q].kind == Tok::Char && t_[q].text == "{") q = match_brace(q);
            b = q + 1;
        }
        GiNaC::ex operand;
        if (b >= num.second) {
            if (at_end() || stops_expression(peek()) || !starts_factor(peek()))
                fail(at, "the derivative has nothing to act on");
            operand = factor();
        } else {
            operand = expr_in({b, num.second}, "the derivative");
        }
        const std::string v = var.canonical();
        if (!partial) {
            GiNaC::ex tv;
            auto it = ctx_.names.find(v);
            if (it != ctx_.names.end()) tv = it->second;
            if (v != "t" && !(it != ctx_.names.end() && tv.is_equal(ctx_.time)))
                fail(at, "a derivative with respect to " + v + " (only d/dt is read)");
            for (int i = 0; i < order; ++i) operand = ddt(operand);
            return operand;
        }
        GiNaC::ex wrt;
        auto it = ctx_.names.find(v);
        if (it != ctx_.names.end()) {
            wrt = it->second;
        } else {
            side_.uses.push_back({v, offset_of(at)});
            wrt = ctx_.free_symbol(v, var.kind);
        }
        if (!GiNaC::is_a<GiNaC::symbol>(wrt))
            fail(at, "a partial derivative with respect to " + v + ", which is an expression");
        for (int i = 0; i < order; ++i) operand = pdiff(operand, wrt);
        return operand;
    }

    const std::vector<Token>& t_;
    std::size_t pos_, end_;
    LatexContext& ctx_;
    Side& side_;
    int depth_ = 0;
    int abs_depth_ = 0;
    std::vector<IntegralFrame> frames_;
    GiNaC::ex pending_power_;
    bool has_pending_power_ = false;
};

// ------------------------------------------------------------------------------------ chains and sides

/// Depth of each token (braces, brackets, parentheses, \left...\right, \begin...\end) at its start.
std::vector<int> depths(const std::vector<Token>& t) {
    std::vector<int> d(t.size(), 0);
    int depth = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const Token& k = t[i];
        const bool closes = (k.kind == Tok::Char && (k.text == "}" || k.text == ")" || k.text == "]")) ||
                            (k.kind == Tok::Word && (k.text == "\\right" || k.text == "\\end" || k.text == "\\}"));
        if (closes && depth > 0) --depth;
        d[i] = depth;
        const bool opens = (k.kind == Tok::Char && (k.text == "{" || k.text == "(" || k.text == "[")) ||
                           (k.kind == Tok::Word && (k.text == "\\left" || k.text == "\\begin" || k.text == "\\{"));
        if (opens) ++depth;
        // \left( and \right): the delimiter token that follows is part of the command.
        if (k.kind == Tok::Word && (k.text == "\\left" || k.text == "\\right") && i + 1 < t.size()) {
            ++i;
            d[i] = depth;
        }
    }
    return d;
}

struct RelationAt {
    std::size_t index;  ///< token index of the sign
    std::size_t count;  ///< tokens it spans (":=" is two)
    Relation kind;
};

std::vector<RelationAt> relations_in(const std::vector<Token>& t, const std::vector<int>& d, std::size_t b,
                                     std::size_t e) {
    std::vector<RelationAt> out;
    for (std::size_t i = b; i < e; ++i) {
        if (d[i] != 0) continue;
        const Token& k = t[i];
        if (k.kind == Tok::Char) {
            if (k.text == "=")
                out.push_back({i, 1, Relation::Equal});
            else if (k.text == "<" || k.text == ">")
                out.push_back({i, 1, Relation::Inequality});
            else if (k.text == ":" && i + 1 < e && t[i + 1].kind == Tok::Char && t[i + 1].text == "=") {
                out.push_back({i, 2, Relation::Equal});
                ++i;
            }
        } else if (k.kind == Tok::Word && is_relation_word(k.text)) {
            Relation r = Relation::Inequality;
            if (k.text == "\\approx" || k.text == "\\simeq" || k.text == "\\doteq" || k.text == "\\cong")
                r = Relation::Approx;
            if (k.text == "\\equiv") r = Relation::Equal;
            out.push_back({i, 1, r});
        }
    }
    return out;
}

Side make_side(std::string_view text, const std::vector<Token>& t, std::size_t b, std::size_t e,
               LatexContext& ctx) {
    // Trailing punctuation ends sentences, not formulas.
    while (e > b && t[e - 1].kind == Tok::Char &&
           (t[e - 1].text == "." || t[e - 1].text == "," || t[e - 1].text == ";"))
        --e;
    while (b < e && t[b].space) ++b;
    while (e > b && t[e - 1].space) --e;
    Side s;
    if (b >= e) {
        s.begin = s.end = b < t.size() ? t[b].offset : text.size();
        s.error = "empty";
        s.error_offset = s.begin;
        return s;
    }
    s.begin = t[b].offset;
    s.end = t[e - 1].offset + t[e - 1].length;
    s.source = std::string(text.substr(s.begin, s.end - s.begin));
    try {
        Parser p(t, b, e, ctx, s);
        s.value = p.parse_all();
        s.ok = true;
    } catch (const ParseFailure& f) {
        s.ok = false;
        s.error = f.reason;
        s.error_offset = f.offset;
    } catch (const std::exception& x) {
        s.ok = false;
        s.error = std::string("cannot evaluate: ") + x.what();
        s.error_offset = s.begin;
    } catch (...) {
        s.ok = false;
        s.error = "cannot evaluate";
        s.error_offset = s.begin;
    }
    return s;
}

Chain make_chain(std::string_view text, const std::vector<Token>& t, const std::vector<int>& d, std::size_t b,
                 std::size_t e, LatexContext& ctx) {
    Chain c;
    c.begin = b < t.size() ? t[b].offset : text.size();
    c.end = e > b ? t[e - 1].offset + t[e - 1].length : c.begin;
    std::size_t start = b;
    for (const RelationAt& r : relations_in(t, d, b, e)) {
        c.sides.push_back(make_side(text, t, start, r.index, ctx));
        c.relations.push_back(r.kind);
        c.relation_offsets.push_back(t[r.index].offset);
        start = r.index + r.count;
    }
    c.sides.push_back(make_side(text, t, start, e, ctx));
    return c;
}

bool soft_breaker(const Token& k) {
    if (k.kind == Tok::Char) return k.text == "," || k.text == ";";
    if (k.kind != Tok::Word) return false;
    if (k.text == "\\quad" || k.text == "\\qquad") return true;
    if ((k.text == "\\text" || k.text == "\\mbox" || k.text == "\\textrm") &&
        trim(k.raw).find(' ') != std::string::npos)
        return true;
    // `\mbox{ and }`, `\text{and}`: a word joining two statements.
    if (is_one_of(k.text, {"\\text", "\\mbox", "\\textrm", "\\mathrm", "\\textnormal", "\\textit"}) &&
        is_one_of(trim(k.raw), {"and", "or", "for", "if", "with", "where", "so", "then", "i.e.", "i.e.,"}))
        return true;
    return false;
}

}  // namespace

std::vector<Chain> parse_math(std::string_view text, LatexContext& context) {
    std::vector<Chain> out;
    std::vector<Token> t;
    try {
        t = tokenize(text);
    } catch (...) {
        return out;
    }
    const std::vector<int> d = depths(t);
    // Hard breakers first, then soft ones where both neighbours are equations.
    std::vector<std::pair<std::size_t, std::size_t>> segments;
    std::size_t start = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (d[i] == 0 && t[i].kind == Tok::Word && is_hard_breaker(t[i].text)) {
            segments.push_back({start, i});
            start = i + 1;
        }
    }
    segments.push_back({start, t.size()});
    for (const auto& [sb, se] : segments) {
        std::vector<std::pair<std::size_t, std::size_t>> pieces;
        std::size_t ps = sb;
        for (std::size_t i = sb; i < se; ++i)
            if (d[i] == 0 && soft_breaker(t[i])) {
                pieces.push_back({ps, i});
                ps = i + 1;
            }
        pieces.push_back({ps, se});
        // Merge a piece without a relation into its neighbour: the breaker was not a separator there.
        std::vector<std::pair<std::size_t, std::size_t>> merged;
        for (const auto& p : pieces) {
            // Nothing between two breakers (`\qquad\text{or}\qquad`): the breakers are not a formula.
            if (std::all_of(t.begin() + long(p.first), t.begin() + long(p.second), [](const Token& k) { return k.space; }))
                continue;
            const bool rel = !relations_in(t, d, p.first, p.second).empty();
            if (!merged.empty() &&
                (!rel || relations_in(t, d, merged.back().first, merged.back().second).empty()))
                merged.back().second = p.second;
            else
                merged.push_back(p);
        }
        for (const auto& p : merged) {
            std::size_t b = p.first, e = p.second;
            while (b < e && t[b].space) ++b;
            if (b >= e) continue;
            out.push_back(make_chain(text, t, d, b, e, context));
        }
    }
    return out;
}

Side parse_expression(std::string_view text, LatexContext& context) {
    std::vector<Token> t = tokenize(text);
    return make_side(text, t, 0, t.size(), context);
}

std::string canonical_name(std::string_view latex) {
    try {
        std::vector<Token> t = tokenize(latex);
        LatexContext ctx;
        Side s;
        Parser p(t, 0, t.size(), ctx, s);
        return p.read_name_only();
    } catch (...) {
        return "";
    }
}

bool has_relation(std::string_view text) {
    std::vector<Token> t = tokenize(text);
    const std::vector<int> d = depths(t);
    return !relations_in(t, d, 0, t.size()).empty();
}

}  // namespace eomgen::checker
