/**
 * @file latex_grammar.hpp  The recursive-descent parser of derivation LaTeX (class Parser), shared by the files
 * that define its parts: latex_grammar.cpp (expressions, terms, factors, brackets), latex_names.cpp (names with
 * accents, subscripts and primes), latex_calculus.cpp (derivatives, fractions, roots, differentials and integrals)
 * and latex_words.cpp (control words and functions). Internal to the checker: latex_parser.hpp is its interface.
 */
#pragma once

#include "checker/latex_parser.hpp"
#include "checker/latex_tokens.hpp"

#include <ginac/ginac.h>

#include <cctype>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace eomgen::checker::parsing {

using latex::greek_letters;
using latex::is_one_of;
using latex::normal_greek;
using latex::takes_raw_argument;
using latex::Tok;
using latex::Token;
using latex::tokenize;

// ------------------------------------------------------------------------------------------- helpers

inline std::string trim(std::string_view s) {
    std::size_t a = 0, b = s.size();
    while (a < b && (std::isspace(static_cast<unsigned char>(s[a])) || s[a] == '~')) ++a;
    while (b > a && (std::isspace(static_cast<unsigned char>(s[b - 1])) || s[b - 1] == '~')) --b;
    return std::string(s.substr(a, b - a));
}

inline bool is_plain_word(const std::string& s) {
    if (s.empty()) return false;
    for (char c : s)
        if (!std::isalpha(static_cast<unsigned char>(c))) return false;
    return true;
}

inline bool is_function_name(const std::string& f) {
    return is_one_of(f, {"sin", "cos", "tan", "cot", "sec", "csc", "exp", "ln", "log", "sinh", "cosh", "tanh",
                         "coth", "arcsin", "arccos", "arctan", "asin", "acos", "atan", "sgn", "sign"});
}

inline bool is_relation_word(const std::string& w) {
    return is_one_of(
        w, {"\\approx", "\\simeq", "\\equiv", "\\neq", "\\ne", "\\le", "\\leq", "\\ge", "\\geq", "\\leqslant",
            "\\geqslant", "\\ll", "\\gg", "\\sim", "\\propto", "\\cong", "\\lt", "\\gt", "\\doteq"});
}

inline bool is_hard_breaker(const std::string& w) {
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

    bool stops_expression(const Token* t) const;

    GiNaC::ex expr();

    bool starts_factor(const Token* t) const;

    GiNaC::ex term();

    GiNaC::ex factor();

    GiNaC::ex postfix(GiNaC::ex base);

    /// The exponent after '^' (pos_ just after it); degrees `^{\circ}` become the factor pi/180 via a marker.
    GiNaC::ex superscript(std::size_t at);

    static const GiNaC::symbol& degree_marker();

    GiNaC::ex power(const GiNaC::ex& base, const GiNaC::ex& exponent, std::size_t at);

    // primary := number | name | group | function | \frac | \sqrt | \int | \pi
    GiNaC::ex primary();

    GiNaC::ex number();

    /// `V(r)`, `L(\theta, \dot\theta, t)`: a label letter written as a function of the coordinates, velocities
    /// or t. Returns true and moves past the `)` when the group at pos_ is such an argument list: the letter
    /// then stands alone (the caller multiplies it by 1), not times r.
    bool label_arguments();

    /// `(t)` right after a name (`\theta(t)`, `\dot{x}_1(t)`, `s(t)`, `y'(t)`): the name as a function of time, the
    /// name itself, not times t. Moves past the `)` when it is.
    bool of_time();

    GiNaC::ex bracket_group();

    /// `\{a, b\}`: a Poisson bracket, evaluated by the checker (it knows the momenta).
    GiNaC::ex poisson_bracket(std::size_t at);

    GiNaC::ex absolute_value(std::size_t at);

    GiNaC::ex left_right(std::size_t at);

    /// After `\left. e \right|`: `_{\theta=\theta_0}` puts the value in e, `_{\text{inertial}}` (the frame of a rate)
    /// leaves e as it is; any other point, or none, fails.
    GiNaC::ex evaluation_bar(std::size_t at, GiNaC::ex e);

    // ----- names

    bool starts_name(const Token* t) const;

    /// Reads a name at pos_ into n (accents, base, subscripts, primes). False when there is none.
    /// A `^{\prime 2}` leaves the exponent 2 in pending_power_.
    /// The name in the braces of the command at token `at` (\dot{x}, \mathbf{r}, \bar{m}); moves past it. With
    /// `power_inside`, a power after the name inside the braces (`\dot{r^2}`) is left in pending_power_, with a note.
    NameParts argument_name(std::size_t at, const char* what, bool power_inside = false);

    bool read_name(NameParts& n);

    /// At '^': when the superscript starts with \prime, counts the primes into n and leaves any rest of the
    /// superscript (`^{\prime 2}`) as pending_power_. Returns false (pos_ unchanged) when it is an exponent.
    bool prime_superscript(NameParts& n);

    /// At '^': `x^{2}_{1}` (as many editors write x₁²): the exponent comes before the subscript. Leaves the
    /// exponent in pending_power_ and returns true when a subscript follows it and the name has none yet.
    bool exponent_before_subscript(const NameParts& n);

    /// A subscript as canonical text: `\text {rod }` → rod, `x^{\prime}` → x', `1 x` → 1x.
    std::string subscript_text(std::size_t b, std::size_t e) const;

    /// The value of the name at pos_: known, d/dt of a known name, or a free name.
    GiNaC::ex name_value();
    /// `(\theta)` right after a name, θ one of the model's coordinates: the name as a function of it (`V(\theta)`,
    /// `I_p(\theta)`). Moves past the `)` and returns the coordinate; nullopt (pos_ unchanged) otherwise.
    std::optional<GiNaC::ex> coordinate_argument();

    GiNaC::ex resolve(const NameParts& n, std::size_t at);

    // ----- differentials and integrals

    /// 'd' followed by a name, inside an integral whose variable is not yet read.
    bool differential_here();

    GiNaC::ex differential();

    GiNaC::ex integral(std::size_t at);
    GiNaC::ex integral_body(std::size_t at, GiNaC::ex lo, GiNaC::ex hi, bool definite);
    GiNaC::ex indefinite_integral(std::size_t at);

    void remove_uses(const std::string& name, std::size_t from);

    // ----- control words

    GiNaC::ex word(std::size_t at);

    GiNaC::ex function(const std::string& f, std::size_t at);

    /// `\lim_{x \to a} f`: f's limit at a, of the term that follows (taken in evaluation.cpp).
    GiNaC::ex limit(std::size_t at);

    GiNaC::ex square_root(std::size_t at);

    /// Is the range a derivative's numerator/denominator: starts with d, \mathrm{d} or \partial?
    int derivative_marker(std::size_t b, std::size_t e) const;

    GiNaC::ex fraction(std::size_t at);

    /// `\partial L/\partial \theta`: the derivative written with a slash (latex_words.cpp).
    GiNaC::ex slashed_partial(std::size_t at);
    GiNaC::ex derivative(std::size_t at, std::pair<std::size_t, std::size_t> num, const NameParts& var,
                         int order, bool partial);

    const std::vector<Token>& t_;
    std::size_t pos_, end_;
    LatexContext& ctx_;
    Side& side_;
    int depth_ = 0;
    int abs_depth_ = 0;
    int transposed_ = 0;  ///< brackets closed at a \right whose ')' comes after it (bracket_group, left_right)
    std::vector<IntegralFrame> frames_;
    GiNaC::ex pending_power_;
    bool has_pending_power_ = false;
};

}  // namespace eomgen::checker::parsing
