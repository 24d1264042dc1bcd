/** @file expression_parser.cpp  Recursive-descent parser of model expressions into GiNaC expressions. */
#include "model/expression_parser.hpp"

#include "model/names.hpp"
#include "model/nonsmooth.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace eomgen {

ExpressionError::ExpressionError(std::size_t offset, const std::string& message)
    : std::runtime_error(message), offset_(offset), message_(message) {}

namespace {

// Deeper nesting than this is certainly a mistake, and unbounded recursion could overflow the stack.
constexpr int kMaxDepth = 200;
// Largest |exponent| of a number literal: 1e400 is already beyond double, and 1e999999999 would take
// the exact arithmetic minutes and gigabytes.
constexpr long kMaxLiteralExponent = 400;
// Largest exact power computed, in bits of the result, for the same reason (9^9^9).
constexpr double kMaxPowerBits = 100000;

struct Function {
    const char* name;
    std::size_t arity;
    GiNaC::ex (*apply)(const std::vector<GiNaC::ex>& args);
};

// Sorted by name; expression_function_names() relies on it.
const Function kFunctions[] = {
    {"abs", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return real_abs(a[0]); }},
    {"acos", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return GiNaC::acos(a[0]); }},
    {"asin", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return GiNaC::asin(a[0]); }},
    {"atan", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return GiNaC::atan(a[0]); }},
    {"atan2", 2, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return GiNaC::atan2(a[0], a[1]); }},
    {"clamp", 3, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return real_min(real_max(a[0], a[1]), a[2]); }},
    {"cos", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return GiNaC::cos(a[0]); }},
    {"cosh", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return GiNaC::cosh(a[0]); }},
    {"exp", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return GiNaC::exp(a[0]); }},
    {"heaviside", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return heaviside(a[0]); }},
    {"log", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return GiNaC::log(a[0]); }},
    {"max", 2, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return real_max(a[0], a[1]); }},
    {"min", 2, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return real_min(a[0], a[1]); }},
    {"sign", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return sign(a[0]); }},
    {"sin", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return GiNaC::sin(a[0]); }},
    {"sinh", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return GiNaC::sinh(a[0]); }},
    {"sqrt", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return real_roots(GiNaC::sqrt(a[0])); }},
    {"tan", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return GiNaC::tan(a[0]); }},
    {"tanh", 1, [](const std::vector<GiNaC::ex>& a) -> GiNaC::ex { return GiNaC::tanh(a[0]); }},
};

const Function* find_function(std::string_view name) {
    for (const auto& f : kFunctions)
        if (name == f.name) return &f;
    return nullptr;
}

bool is_alpha(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
bool is_digit(char c) {
    return c >= '0' && c <= '9';
}
bool is_name_char(char c) {
    return is_alpha(c) || is_digit(c) || c == '_';
}
bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

/// The character at text[i] for a message: itself when printable ASCII, the whole UTF-8 sequence when
/// valid, else \xNN.
std::string describe_char(std::string_view text, std::size_t i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) return std::string(1, static_cast<char>(c));
    std::size_t len = (c & 0xe0) == 0xc0 ? 2 : (c & 0xf0) == 0xe0 ? 3 : (c & 0xf8) == 0xf0 ? 4 : 0;
    bool valid = len > 0 && i + len <= text.size();
    for (std::size_t k = 1; valid && k < len; ++k)
        valid = (static_cast<unsigned char>(text[i + k]) & 0xc0) == 0x80;
    if (valid) return std::string(text.substr(i, len));
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned>(c));
    return buf;
}

enum class Tok { End, Number, Name, Plus, Minus, Star, Slash, Caret, LParen, RParen, Comma, Prime };

struct Token {
    Tok kind = Tok::End;
    std::size_t offset = 0;
    std::string_view text;  ///< the characters of the token
    GiNaC::ex number;       ///< value of a Number
};

bool is_binary_operator(Tok k) {
    return k == Tok::Plus || k == Tok::Minus || k == Tok::Star || k == Tok::Slash || k == Tok::Caret;
}

bool starts_operand(Tok k) {
    return k == Tok::Number || k == Tok::Name || k == Tok::LParen;
}

/// "'x'" for a token in a message.
std::string quote(const Token& t) {
    return "'" + std::string(t.text) + "'";
}

class Parser {
  public:
    Parser(std::string_view text, const SymbolTable& symbols, const ParseOptions& options)
        : text_(text), symbols_(symbols), options_(options) {}

    GiNaC::ex parse() {
        advance();
        if (cur_.kind == Tok::End) throw ExpressionError(0, "empty expression");
        GiNaC::ex e = parse_sum();
        if (cur_.kind != Tok::End) unexpected_after_operand();
        return e;
    }

  private:
    // Counts nesting on the way down so that "((((...": an error instead of a stack overflow.
    class DepthGuard {
      public:
        DepthGuard(Parser& p, std::size_t offset) : p_(p) {
            if (++p_.depth_ > kMaxDepth) throw ExpressionError(offset, "expression nested too deeply");
        }
        ~DepthGuard() { --p_.depth_; }
        DepthGuard(const DepthGuard&) = delete;
        DepthGuard& operator=(const DepthGuard&) = delete;

      private:
        Parser& p_;
    };

    // ---- lexer ----

    void advance() {
        if (has_cur_) {
            prev_ = cur_;
            has_prev_ = true;
        }
        cur_ = lex();
        has_cur_ = true;
    }

    Token make(Tok kind, std::size_t start, std::size_t length) {
        Token t;
        t.kind = kind;
        t.offset = start;
        t.text = text_.substr(start, length);
        pos_ = start + length;
        return t;
    }

    Token lex() {
        while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
        if (pos_ >= text_.size()) {
            Token t;
            t.offset = text_.size();
            t.text = "end of expression";
            return t;
        }
        const std::size_t start = pos_;
        const char c = text_[pos_];
        if (is_digit(c) || (c == '.' && pos_ + 1 < text_.size() && is_digit(text_[pos_ + 1])))
            return lex_number();
        if (is_alpha(c) || c == '_') {
            std::size_t end = pos_;
            while (end < text_.size() && is_name_char(text_[end])) ++end;
            return make(Tok::Name, start, end - start);
        }
        switch (c) {
            case '+':
                return make(Tok::Plus, start, 1);
            case '-':
                return make(Tok::Minus, start, 1);
            case '/':
                return make(Tok::Slash, start, 1);
            case '^':
                return make(Tok::Caret, start, 1);
            case '(':
                return make(Tok::LParen, start, 1);
            case ')':
                return make(Tok::RParen, start, 1);
            case ',':
                return make(Tok::Comma, start, 1);
            case '\'':
                return make(Tok::Prime, start, 1);
            case '*':
                if (start + 1 < text_.size() && text_[start + 1] == '*')
                    throw ExpressionError(start, "'**' is not an operator: use ^ for powers");
                return make(Tok::Star, start, 1);
            case '[':
            case ']':
            case '{':
            case '}':
                throw ExpressionError(start, "unexpected character '" + std::string(1, c) +
                                                 "': use parentheses ( ) for grouping");
            default:
                throw ExpressionError(start, "unexpected character '" + describe_char(text_, start) + "'");
        }
    }

    // digits ['.' digits] [('e'|'E') ['+'|'-'] digits], or '.' digits ...; the value is exact:
    // mantissa digits as an integer times a power of ten.
    Token lex_number() {
        const std::size_t start = pos_;
        std::string digits;
        std::size_t i = pos_;
        while (i < text_.size() && is_digit(text_[i])) digits += text_[i++];
        long fraction_digits = 0;
        if (i < text_.size() && text_[i] == '.') {
            ++i;
            while (i < text_.size() && is_digit(text_[i])) {
                digits += text_[i++];
                ++fraction_digits;
            }
        }
        long exponent = 0;
        if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
            std::size_t j = i + 1;
            bool negative = false;
            if (j < text_.size() && (text_[j] == '+' || text_[j] == '-')) negative = text_[j++] == '-';
            // Only an exponent when digits follow; "2e" is the number 2 before the name e.
            if (j < text_.size() && is_digit(text_[j])) {
                while (j < text_.size() && is_digit(text_[j])) {
                    if (exponent <= kMaxLiteralExponent) exponent = exponent * 10 + (text_[j] - '0');
                    ++j;
                }
                if (exponent > kMaxLiteralExponent)
                    throw ExpressionError(start, "exponent of number out of range (at most " +
                                                     std::to_string(kMaxLiteralExponent) + ")");
                if (negative) exponent = -exponent;
                i = j;
            }
        }
        if (i < text_.size() && text_[i] == '.') throw ExpressionError(i, "malformed number: a second '.'");
        Token t = make(Tok::Number, start, i - start);
        const std::size_t first = digits.find_first_not_of('0');
        const GiNaC::numeric mantissa(first == std::string::npos ? "0" : digits.c_str() + first);
        const long power = exponent - fraction_digits;
        const GiNaC::numeric ten(10);
        t.number = power >= 0 ? mantissa * ten.power(power) : mantissa / ten.power(-power);
        return t;
    }

    // ---- grammar ----

    GiNaC::ex parse_sum() {
        GiNaC::ex e = parse_term();
        while (cur_.kind == Tok::Plus || cur_.kind == Tok::Minus) {
            const Token op = cur_;
            advance();
            const GiNaC::ex rhs = parse_term();
            e = guarded(op.offset, [&] { return op.kind == Tok::Plus ? e + rhs : e - rhs; });
        }
        return e;
    }

    GiNaC::ex parse_term() {
        GiNaC::ex e = parse_unary();
        while (cur_.kind == Tok::Star || cur_.kind == Tok::Slash) {
            const Token op = cur_;
            advance();
            const GiNaC::ex rhs = parse_unary();
            // Checked here because GiNaC leaks the half-built power when its eval throws.
            if (op.kind == Tok::Slash && rhs.is_zero()) throw ExpressionError(op.offset, "division by zero");
            e = guarded(op.offset, [&] { return op.kind == Tok::Star ? e * rhs : e / rhs; });
        }
        if (starts_operand(cur_.kind)) missing_operator();
        return e;
    }

    GiNaC::ex parse_unary() {
        DepthGuard guard(*this, cur_.offset);
        if (cur_.kind == Tok::Minus || cur_.kind == Tok::Plus) {
            const Token op = cur_;
            advance();
            const GiNaC::ex operand = parse_unary();
            return op.kind == Tok::Minus ? GiNaC::ex(-operand) : operand;
        }
        return parse_power();
    }

    GiNaC::ex parse_power() {
        const GiNaC::ex base = parse_postfix();
        if (cur_.kind != Tok::Caret) return base;
        const Token op = cur_;
        advance();
        const GiNaC::ex exponent = parse_unary();  // right-associative, and a^-b is a^(-b)
        check_power_size(op.offset, base, exponent);
        return guarded(op.offset, [&] { return real_roots(GiNaC::pow(base, exponent)); });
    }

    // A name that stood alone as a primary, so that a prime after it can refer to it.
    struct Primary {
        GiNaC::ex value;
        bool bare_name = false;
        Token name;
    };

    GiNaC::ex parse_postfix() {
        Primary p = parse_primary();
        if (cur_.kind != Tok::Prime) return p.value;
        const Token prime = cur_;
        if (!p.bare_name)
            throw ExpressionError(prime.offset, "a prime (') can only follow a coordinate name, as in psi'");
        const std::string name(p.name.text);
        const auto v = symbols_.velocities.find(name);
        if (v == symbols_.velocities.end())
            throw ExpressionError(prime.offset, "'" + name + "' is not a coordinate, so " + name +
                                                    "' is meaningless: only coordinates have velocities");
        check_velocity_allowed(p.name.offset, name + "'");
        advance();
        if (cur_.kind == Tok::Prime)
            throw ExpressionError(cur_.offset, "only one prime is allowed: " + name +
                                                   "' is the velocity; T and V may not use accelerations");
        return v->second;
    }

    Primary parse_primary() {
        DepthGuard guard(*this, cur_.offset);
        Primary p;
        switch (cur_.kind) {
            case Tok::Number:
                p.value = cur_.number;
                advance();
                return p;
            case Tok::LParen: {
                const Token open = cur_;
                advance();
                if (cur_.kind == Tok::RParen) throw ExpressionError(open.offset, "empty parentheses");
                p.value = parse_sum();
                expect_close(open);
                return p;
            }
            case Tok::Name:
                return parse_name();
            default:
                missing_operand();
        }
        return p;  // not reached
    }

    Primary parse_name() {
        const Token name = cur_;
        const std::string id(name.text);
        advance();
        const bool call = cur_.kind == Tok::LParen;
        Primary p;
        if (id == "dot") {
            p.value = parse_dot(name);
            return p;
        }
        if (const Function* f = find_function(id)) {
            if (!call)
                throw ExpressionError(name.offset, "'" + id + "' is a function: write " + id + "(...)");
            p.value = parse_call(name, *f);
            return p;
        }
        if (id == "pi") {
            if (call) not_a_function(name);
            p.value = GiNaC::Pi;
            return p;
        }
        const auto s = symbols_.symbols.find(id);
        if (s == symbols_.symbols.end()) unknown_name(name, call);
        if (options_.constants_only)
            throw ExpressionError(name.offset, "'" + id +
                                                   "' is not a constant: only numbers, pi and functions may "
                                                   "be used here");
        if (call) not_a_function(name);
        p.value = s->second;
        p.bare_name = true;
        p.name = name;
        return p;
    }

    GiNaC::ex parse_dot(const Token& dot) {
        if (cur_.kind != Tok::LParen)
            throw ExpressionError(dot.offset, "dot needs a coordinate in parentheses, as in dot(psi)");
        const Token open = cur_;
        advance();
        if (cur_.kind == Tok::End) throw ExpressionError(open.offset, "unclosed '('");
        if (cur_.kind != Tok::Name)
            throw ExpressionError(cur_.offset, "dot() takes a coordinate name, as in dot(psi)");
        const Token name = cur_;
        const std::string id(name.text);
        const auto v = symbols_.velocities.find(id);
        if (v == symbols_.velocities.end()) {
            if (symbols_.symbols.count(id))
                throw ExpressionError(name.offset, "'" + id + "' is not a coordinate, so dot(" + id +
                                                       ") is meaningless: only coordinates have velocities");
            std::vector<std::string> coordinates;
            for (const auto& c : symbols_.velocities) coordinates.push_back(c.first);
            throw ExpressionError(name.offset,
                                  "unknown coordinate '" + id + "'" + did_you_mean(id, coordinates));
        }
        if (options_.constants_only)
            throw ExpressionError(name.offset, "'" + id +
                                                   "' is not a constant: only numbers, pi and functions "
                                                   "may be used here");
        check_velocity_allowed(dot.offset, "dot(" + id + ")");
        advance();
        if (cur_.kind == Tok::End) throw ExpressionError(open.offset, "unclosed '('");
        if (cur_.kind != Tok::RParen)
            throw ExpressionError(cur_.offset, "dot() takes one coordinate name, as in dot(psi)");
        advance();
        return v->second;
    }

    GiNaC::ex parse_call(const Token& name, const Function& f) {
        const Token open = cur_;
        advance();
        std::vector<GiNaC::ex> args;
        if (cur_.kind == Tok::RParen) {
            advance();
        } else {
            while (true) {
                args.push_back(parse_sum());
                if (cur_.kind == Tok::Comma) {
                    advance();
                    continue;
                }
                expect_close(open);
                break;
            }
        }
        if (args.size() != f.arity) {
            std::string expected = f.arity == 1 ? "1 argument" : std::to_string(f.arity) + " arguments";
            if (std::string_view(f.name) == "atan2") expected += " (y, x)";
            throw ExpressionError(name.offset, std::string(f.name) + " takes " + expected + ", not " +
                                                   std::to_string(args.size()));
        }
        return guarded(name.offset, [&] { return f.apply(args); });
    }

    void expect_close(const Token& open) {
        if (cur_.kind == Tok::RParen) {
            advance();
            return;
        }
        if (cur_.kind == Tok::End) throw ExpressionError(open.offset, "unclosed '('");
        if (cur_.kind == Tok::Comma)
            throw ExpressionError(cur_.offset,
                                  "unexpected ',': only a function call takes several arguments");
        unexpected_after_operand();
    }

    // ---- errors ----

    [[noreturn]] void unexpected_after_operand() {
        switch (cur_.kind) {
            case Tok::RParen:
                throw ExpressionError(cur_.offset, "unmatched ')'");
            case Tok::Comma:
                throw ExpressionError(cur_.offset,
                                      "unexpected ',': only a function call takes several arguments");
            case Tok::Prime:
                throw ExpressionError(cur_.offset,
                                      "a prime (') can only follow a coordinate name, as in psi'");
            default:
                if (starts_operand(cur_.kind)) missing_operator();
                throw ExpressionError(cur_.offset, "unexpected " + quote(cur_));
        }
    }

    [[noreturn]] void missing_operator() {
        const std::string after = has_prev_ && (prev_.kind == Tok::Name || prev_.kind == Tok::Number)
                                      ? std::string(prev_.text)
                                      : "(...)";
        const std::string before = cur_.kind == Tok::LParen ? "(...)" : std::string(cur_.text);
        throw ExpressionError(cur_.offset, "missing operator before " + quote(cur_) + ": write " + after +
                                               "*" + before + " (there is no implicit multiplication)");
    }

    [[noreturn]] void missing_operand() {
        if (cur_.kind == Tok::End) {
            if (!has_prev_) throw ExpressionError(0, "empty expression");
            if (prev_.kind == Tok::LParen) throw ExpressionError(prev_.offset, "unclosed '('");
            if (prev_.kind == Tok::Comma) throw ExpressionError(prev_.offset, "missing argument after ','");
            throw ExpressionError(prev_.offset, "missing operand after " + quote(prev_));
        }
        if (cur_.kind == Tok::Prime)
            throw ExpressionError(cur_.offset, "a prime (') can only follow a coordinate name, as in psi'");
        if (has_prev_ && prev_.kind == Tok::Comma)
            throw ExpressionError(cur_.offset, "missing argument between ',' and " + quote(cur_));
        if (has_prev_ && is_binary_operator(prev_.kind))
            throw ExpressionError(cur_.offset,
                                  "missing operand between " + quote(prev_) + " and " + quote(cur_));
        if (cur_.kind == Tok::RParen && !(has_prev_ && prev_.kind == Tok::LParen))
            throw ExpressionError(cur_.offset, "unmatched ')'");
        throw ExpressionError(cur_.offset, "missing operand before " + quote(cur_));
    }

    [[noreturn]] void not_a_function(const Token& name) {
        throw ExpressionError(name.offset, quote(name) + " is not a function (to multiply, write " +
                                               std::string(name.text) + "*(...))");
    }

    [[noreturn]] void unknown_name(const Token& name, bool call) {
        const std::string id(name.text);
        if (call) {
            throw ExpressionError(
                name.offset, "unknown function '" + id + "'" + did_you_mean(id, expression_function_names()));
        }
        // The spellings people use for a velocity: x_dot, xdot, x_d, dx (the model language writes x' or dot(x)).
        for (const auto& c : symbols_.velocities) {
            if (id == c.first + "_dot" || id == c.first + "dot" || id == c.first + "_d" || id == "d" + c.first)
                throw ExpressionError(name.offset, "unknown symbol '" + id + "': write " + c.first +
                                                       "' or dot(" + c.first + ") for the velocity of " +
                                                       c.first);
        }
        std::vector<std::string> candidates{"pi"};
        if (!options_.constants_only)
            for (const auto& s : symbols_.symbols) candidates.push_back(s.first);
        throw ExpressionError(name.offset, "unknown symbol '" + id + "'" + did_you_mean(id, candidates));
    }

    static std::string did_you_mean(const std::string& id, const std::vector<std::string>& candidates) {
        const std::string best = closest_name(id, candidates);
        return best.empty() ? std::string() : "; did you mean '" + best + "'?";
    }

    void check_velocity_allowed(std::size_t offset, const std::string& written) const {
        if (!options_.forbid_velocities.empty())
            throw ExpressionError(offset,
                                  "velocity " + written + " not allowed here: " + options_.forbid_velocities);
    }

    // GiNaC computes powers of numbers exactly as it builds them, also inside products ((2^k*x)^n has
    // the coefficient 2^(k*n)): refuse a power whose numbers could exceed kMaxPowerBits bits.
    static void check_power_size(std::size_t offset, const GiNaC::ex& base, const GiNaC::ex& exponent) {
        if (!GiNaC::is_a<GiNaC::numeric>(exponent)) return;
        const GiNaC::numeric& e = GiNaC::ex_to<GiNaC::numeric>(exponent);
        if (GiNaC::is_a<GiNaC::numeric>(base)) {
            const GiNaC::numeric& b = GiNaC::ex_to<GiNaC::numeric>(base);
            // GiNaC would throw from inside pow() and leak the half-built power.
            if (b.is_zero() && e.is_negative()) throw ExpressionError(offset, "division by zero (0 to a negative power)");
            if (b.is_zero() && e.is_zero()) throw ExpressionError(offset, "0^0 is undefined");
            if (b.is_zero() || abs(b).is_equal(1)) return;
        }
        double base_bits = 1;
        for (auto it = base.preorder_begin(); it != base.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::numeric>(*it))
                base_bits += numeric_bits(GiNaC::ex_to<GiNaC::numeric>(*it));
        const double magnitude = numeric_bits(e) > 64 ? HUGE_VAL : std::abs(e.real().to_double());
        if (magnitude * base_bits > kMaxPowerBits)
            throw ExpressionError(offset, "power too large: exact numbers this big (over " +
                                              std::to_string(static_cast<long>(kMaxPowerBits)) +
                                              " bits) are certainly a mistake");
    }

    static double numeric_bits(const GiNaC::numeric& n) {
        if (n.is_rational()) return std::max(n.numer().int_length(), n.denom().int_length());
        if (!n.is_real()) return numeric_bits(n.real()) + numeric_bits(n.imag());
        return 64;  // a float; the parser makes none
    }

    // GiNaC evaluates as it builds (1/0, log(0), tan(pi/2), 0^0 throw): report those where they happen.
    template <class F>
    static GiNaC::ex guarded(std::size_t offset, F&& build) {
        try {
            return build();
        } catch (const GiNaC::pole_error&) {
            throw ExpressionError(offset,
                                  "division by zero or a pole of a function (the expression is infinite)");
        } catch (const std::domain_error&) {
            throw ExpressionError(offset, "undefined value (such as 0^0)");
        } catch (const ExpressionError&) {
            throw;
        } catch (const std::exception& e) {
            throw ExpressionError(offset, std::string("cannot evaluate: ") + e.what());
        }
    }

    std::string_view text_;
    const SymbolTable& symbols_;
    const ParseOptions& options_;
    std::size_t pos_ = 0;
    Token cur_, prev_;
    bool has_cur_ = false, has_prev_ = false;
    int depth_ = 0;
};

// Constant expressions are evaluated in double precision, as the generated code would: GiNaC's evalf at
// its default 17 digits returns exp(10^300) = 1 and sin(10^300) = 0, and complex values for log(-1).
// NaN for a value that is not real.
double to_double(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
        return n.is_real() ? n.to_double() : std::nan("");
    }
    if (e.is_equal(GiNaC::Pi)) return 3.141592653589793238462643383279502884;
    if (GiNaC::is_a<GiNaC::add>(e)) {
        double sum = 0;
        for (const auto& term : e) sum += to_double(term);
        return sum;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        double product = 1;
        for (const auto& factor : e) product *= to_double(factor);
        return product;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) return std::pow(to_double(e.op(0)), to_double(e.op(1)));
    if (GiNaC::is_a<GiNaC::function>(e)) {
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        if (name == "atan2" && e.nops() == 2) return std::atan2(to_double(e.op(0)), to_double(e.op(1)));
        if (is_nonsmooth_function(e)) {
            double args[2] = {0, 0}, out = 0;
            for (std::size_t i = 0; i < e.nops() && i < 2; ++i) args[i] = to_double(e.op(i));
            if (nonsmooth_value(name, args, e.nops(), out)) return out;
        }
        if (e.nops() == 1) {
            const double x = to_double(e.op(0));
            if (name == "sin") return std::sin(x);
            if (name == "cos") return std::cos(x);
            if (name == "tan") return std::tan(x);
            if (name == "exp") return std::exp(x);
            if (name == "log") return std::log(x);
            if (name == "sinh") return std::sinh(x);
            if (name == "cosh") return std::cosh(x);
            if (name == "tanh") return std::tanh(x);
            if (name == "asin") return std::asin(x);
            if (name == "acos") return std::acos(x);
            if (name == "atan") return std::atan(x);
        }
    }
    // Nothing else comes out of the parser; GiNaC's own evaluation as a last resort.
    const GiNaC::ex value = e.evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(value)) return std::nan("");
    return to_double(value);
}

}  // namespace

GiNaC::ex parse_expression(std::string_view text, const SymbolTable& symbols, const ParseOptions& options) {
    try {
        // Read for real numbers: sqrt(x^2) is |x|, x/sqrt(x^2) is sign(x) (model_files.md, "Non-smooth functions").
        return real_roots(Parser(text, symbols, options).parse());
    } catch (const ExpressionError&) {
        throw;
    } catch (const std::exception& e) {
        // Nothing else is expected; a stray exception still becomes an error about this expression.
        throw ExpressionError(0, std::string("cannot parse expression: ") + e.what());
    }
}

double evaluate_constant(std::string_view text, const SymbolTable& symbols) {
    ParseOptions options;
    options.constants_only = true;
    const GiNaC::ex e = parse_expression(text, symbols, options);
    double value = 0.0;
    try {
        value = to_double(e);
    } catch (const std::exception& x) {
        throw ExpressionError(0, std::string("cannot evaluate: ") + x.what());
    }
    if (std::isnan(value)) throw ExpressionError(0, "not a real number: " + std::string(text));
    if (!std::isfinite(value)) throw ExpressionError(0, "not a finite number: " + std::string(text));
    return value;
}

const std::vector<std::string>& expression_function_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (const auto& f : kFunctions) v.emplace_back(f.name);
        return v;
    }();
    return names;
}

}  // namespace eomgen
