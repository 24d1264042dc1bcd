/** @file latex_grammar.cpp  The parser's expressions: sums, products, powers, numbers, brackets, |x|,
 * \left…\right (latex_grammar.hpp). */
#include "checker/latex_grammar.hpp"

#include "model/nonsmooth.hpp"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <cmath>

namespace eomgen::checker::parsing {

bool Parser::stops_expression(const Token* t) const {
    if (!t) return true;
    if (t->kind == Tok::Char)
        return is_one_of(t->text, {")", "]", "}", ",", ";", "=", "<", ">", "&"}) ||
               (t->text == "|" && abs_depth_ > 0);
    if (t->kind == Tok::Word)
        return t->text == "\\right" || t->text == "\\}" || t->text == "\\\\" || is_relation_word(t->text) ||
               is_hard_breaker(t->text) || t->text == "\\end";
    return false;
}

GiNaC::ex Parser::expr() {
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

bool Parser::starts_factor(const Token* t) const {
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

GiNaC::ex Parser::term() {
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

GiNaC::ex Parser::factor() {
    DepthGuard g(depth_, pos_, *this);
    const Token* t = peek();
    if (is_char(t, "-")) {  // 2 \times -3
        ++pos_;
        return -factor();
    }
    if (is_char(t, "+")) {  // a + + b (a doubled sign): a unary plus
        ++pos_;
        return factor();
    }
    GiNaC::ex base = primary();
    return postfix(base);
}

GiNaC::ex Parser::postfix(GiNaC::ex base) {
    while (true) {
        const Token* t = peek();
        if (is_char(t, "^")) {
            const std::size_t at = pos_;
            ++pos_;
            base = power(base, superscript(at), at);
        } else if (is_char(t, "!")) {
            fail(pos_, "factorials are not read");
        } else if (is_char(t, "'")) {
            // `(m l^2 \dot\theta)'`, `\left(\dots\right)'`: the time derivative of the bracket, as such texts mean it.
            ++pos_;
            base = ddt(base);
            const std::string note = "a prime after a bracket read as its time derivative";
            add_note_once(side_.notes, note);
        } else if (is_char(t, "_")) {
            fail(pos_, "a subscript after an expression (not a name) is not read");
        } else {
            return base;
        }
    }
}

/// The exponent after '^' (pos_ just after it); degrees `^{\circ}` become the factor pi/180 via a marker.
GiNaC::ex Parser::superscript(std::size_t at) {
    const auto r = argument_range("'^'");
    if (r.second == r.first + 1 && t_[r.first].kind == Tok::Word && t_[r.first].text == "\\circ")
        return degree_marker();
    if (r.first >= r.second) fail(at, "empty exponent");
    if (t_[r.first].kind == Tok::Word && t_[r.first].text == "\\prime")
        fail(at, "a prime after an expression (not a name) is not read");
    return expr_in(r, "the exponent");
}

const GiNaC::symbol& Parser::degree_marker() {
    static const GiNaC::symbol s("__degree__");
    return s;
}

GiNaC::ex Parser::power(const GiNaC::ex& base, const GiNaC::ex& exponent, std::size_t at) {
    if (exponent.is_equal(degree_marker())) return base * GiNaC::Pi / 180;
    if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
        const GiNaC::numeric e = GiNaC::ex_to<GiNaC::numeric>(exponent);
        if (!e.is_rational()) fail(at, "the exponent is not a real number");
        // Large powers of sums would be expanded term by term; no derivation needs them. A number's are exact
        // rationals (`1.993 \cdot 10^{-26}`, a molecule's mass in kg).
        const bool number = GiNaC::is_a<GiNaC::numeric>(base) && e.is_integer() && GiNaC::abs(e) <= 400;
        if (!number && (GiNaC::abs(e.numer()) > 12 || e.denom() > 12))
            fail(at, "the exponent is too large to compare");
        if (GiNaC::is_a<GiNaC::numeric>(base) && base.is_zero() && e.is_negative())
            fail(at, "division by zero");
    }
    return GiNaC::pow(base, exponent);
}

// primary := number | name | group | function | \frac | \sqrt | \int | \pi
GiNaC::ex Parser::primary() {
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

GiNaC::ex Parser::number() {
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

/// `V(r)`, `L(\theta, \dot\theta, t)`, `L\left(\theta_1, \dot\theta_1\right)`: a label letter written as a
/// function of the coordinates, velocities or t. Returns true and moves past the `)` when the group at pos_ is
/// such an argument list: the letter then stands alone (the caller multiplies it by 1), not times r.
bool Parser::label_arguments() {
    const std::size_t at = pos_;
    const bool sized = at + 1 < t_.size() && t_[at].text == "\\left" && t_[at + 1].text == "(";
    if (at == 0 || (t_[at].text != "(" && !sized)) return false;
    const Token& before = t_[at - 1];
    if (before.offset + before.length != t_[at].offset) return false;
    // The letter itself, or the letter of a subscripted label (`V_{eff}(\theta)`, `U_{\text{eff}}(r)`).
    std::size_t letter = at - 1;
    if (before.kind == Tok::Char && before.text == "}") {
        int depth = 0;
        std::size_t k = at - 1;
        for (;; --k) {
            if (t_[k].kind == Tok::Char && t_[k].text == "}") ++depth;
            if (t_[k].kind == Tok::Char && t_[k].text == "{" && --depth == 0) break;
            if (k == 0) return false;
        }
        if (k < 2 || t_[k - 1].text != "_") return false;
        letter = k - 2;
    }
    static const char* const kLabels[] = {"T", "V", "U", "L", "H", "E", "K"};
    if (t_[letter].kind != Tok::Letter ||
        std::none_of(std::begin(kLabels), std::end(kLabels), [&](const char* l) { return t_[letter].text == l; }))
        return false;
    const std::size_t saved = pos_, saved_uses = side_.uses.size(), saved_notes = side_.notes.size();
    const int saved_abs = abs_depth_;
    try {
        pos_ += sized ? 2 : 1;
        while (true) {
            const GiNaC::ex e = expr();
            if (!GiNaC::is_a<GiNaC::symbol>(e) || ctx_.free_name_of(e) != nullptr) throw ParseFailure{0, ""};
            const Token* t = peek();
            if (is_char(t, ",")) {
                ++pos_;
                continue;
            }
            if (sized && is_word(t, "\\right")) t = ++pos_ < t_.size() ? &t_[pos_] : nullptr;
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
bool Parser::of_time() {
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

GiNaC::ex Parser::bracket_group() {
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
        // `\frac{mg}{(m+(k^2 mR^2)/(R_0^2 )}`: a bracket left open inside a brace group closes with the group, as
        // its author meant, said in a note.
        if (!t && end_ < t_.size() && is_char(&t_[end_], "}")) {
            const std::string note = "reads the '" + open + "' that is not closed as closed at the end of its group";
            add_note_once(side_.notes, note);
            return e;
        }
        // `\left( -k(-M\omega^2 + k \right))`: the bracket's closer typed after the \right that follows it. Closed
        // here; the \right's own group takes the closer after it (left_right).
        if (is_word(t, "\\right") && open == "(") {
            ++transposed_;
            return e;
        }
        if (t && !stops_expression(t)) fail(pos_, "unexpected " + describe(pos_));
        fail(at, "missing '" + close + "' for this '" + open + "'");
    }
    ++pos_;
    return e;
}

/// `\{a, b\}`: a Poisson bracket, evaluated by the checker (it knows the momenta).
GiNaC::ex Parser::poisson_bracket(std::size_t at) {
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

GiNaC::ex Parser::absolute_value(std::size_t at) {
    ++pos_;
    ++abs_depth_;
    GiNaC::ex e = expr();
    --abs_depth_;
    if (!is_char(peek(), "|")) fail(at, "missing '|' for this '|'");
    ++pos_;
    return eomgen::real_abs(e);
}

GiNaC::ex Parser::evaluation_bar(std::size_t at, GiNaC::ex e) {
    if (!is_char(peek(), "_")) fail(at, "an evaluation bar \\left. \\right| without the point it is taken at is not read");
    ++pos_;
    const std::pair<std::size_t, std::size_t> r = argument_range("the evaluation bar");
    if (is_char(peek(), "^")) fail(at, "an evaluation bar with limits \\left. \\right|_{a}^{b} is not read");
    std::vector<std::size_t> cuts{r.first};  // `x = a, y = b`: the assignments, split at top-level commas
    std::vector<std::size_t> equals;
    int depth = 0;
    for (std::size_t k = r.first; k < r.second; ++k) {
        const Token& tk = t_[k];
        if (tk.kind != Tok::Char) continue;
        if (tk.text == "{" || tk.text == "(" || tk.text == "[") ++depth;
        if (tk.text == "}" || tk.text == ")" || tk.text == "]") --depth;
        if (depth != 0) continue;
        if (tk.text == ",") cuts.push_back(k + 1);
        if (tk.text == "=") equals.push_back(k);
    }
    if (equals.empty()) {
        // `\right|_{\text{inertial}}`: the frame the rate is taken in, a label on the expression, not a value.
        static const char* const frames[] = {"inertial", "space", "spatial", "lab", "fixed", "space-fixed",
                                             "body", "rot", "rotating", "rel", "relative"};
        const Token* label = &t_[r.first];
        std::string word = label->raw;
        for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        word = trim(word);
        if (r.second == r.first + 1 && label->kind == Tok::Word && takes_raw_argument(label->text) &&
            std::find(std::begin(frames), std::end(frames), word) != std::end(frames))
            return e;
        fail(at, "an evaluation bar \\left. \\right|_{...} at a point it does not state as name = value is not read");
    }
    if (equals.size() != cuts.size()) fail(at, "an evaluation bar's point is read as name = value, one per comma");
    cuts.push_back(r.second + 1);
    GiNaC::lst at_point;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const std::size_t eq = equals[i];
        const GiNaC::ex name = expr_in({cuts[i], eq}, "the evaluation bar's name");
        const GiNaC::ex value = expr_in({eq + 1, cuts[i + 1] - 1}, "the evaluation bar's value");
        if (!GiNaC::is_a<GiNaC::symbol>(name))
            fail(at, "an evaluation bar sets a name to a value; the left of its '=' is not one name");
        at_point.append(name == value);
    }
    // Derivatives in e are taken by the checker, which knows the model (latex_parser.hpp): the point goes in after.
    for (GiNaC::const_preorder_iterator x = e.preorder_begin(); x != e.preorder_end(); ++x)
        if (is_ex_the_function(*x, ddt) || is_ex_the_function(*x, pdiff) || is_ex_the_function(*x, dby) ||
            is_ex_the_function(*x, pbracket) || is_ex_the_function(*x, antiderivative))
            return evalat(e, at_point);
    return e.subs(at_point);
}

GiNaC::ex Parser::left_right(std::size_t at) {
    if (label_arguments()) return 1;
    ++pos_;  // \left
    const Token* d = peek();
    if (!d) fail(at, "\\left needs a delimiter");
    const std::string delim = d->text;
    ++pos_;
    const int saved_abs = abs_depth_;
    abs_depth_ = 0;
    const int transposed_before = transposed_;
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
    // The closers of brackets closed at this \right (bracket_group), typed after it.
    for (; transposed_ > transposed_before; --transposed_) {
        if (!is_char(peek(), ")")) fail(at, "a '(' inside this \\left ... \\right is not closed");
        ++pos_;
        const std::string note = "reads a ')' typed after \\right as closing the '(' before it";
        add_note_once(side_.notes, note);
    }
    if ((delim == "|" || delim == "\\vert" || delim == "\\lvert")) return eomgen::real_abs(e);
    if (delim == "." && (rdelim == "|" || rdelim == "\\vert" || rdelim == "\\rvert")) return evaluation_bar(at, e);
    if (delim == "\\langle") fail(at, "angle brackets are not read");
    return e;
}

}  // namespace eomgen::checker::parsing
