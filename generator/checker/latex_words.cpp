/** @file latex_words.cpp  The parser's control words and functions: \sin, \dot, \text, \cdot, ...
 * (latex_grammar.hpp). */
#include "checker/latex_grammar.hpp"
#include "checker/latex_normalize.hpp"

#include "checker/units.hpp"
#include "model/nonsmooth.hpp"

#include <algorithm>

namespace eomgen::checker::parsing {

GiNaC::ex Parser::word(std::size_t at) {
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
        // `\text{const.}`, `\mathrm{Const.}`: the text's constant, abbreviated with a full stop.
        std::string stem = content;
        while (!stem.empty() && (stem.back() == '.' || stem.back() == ' ')) stem.pop_back();
        if (stem != content && is_constant_name(stem)) {
            ++pos_;
            side_.uses.push_back({stem, offset_of(at)});
            return ctx_.free_symbol(stem, NameKind::Unknown);
        }
        fail(at, "text '" + content + "' in a formula is not read");
    }
    if (starts_name(&t)) return name_value();
    if (w == "\\partial") return slashed_partial(at);
    if (w == "\\begin") fail(at, "a matrix or array is not compared");
    if (w == "\\sum" || w == "\\prod") fail(at, "sums and products (" + w + ") are not evaluated");
    if (w == "\\lim") return limit(at);
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

GiNaC::ex Parser::limit(std::size_t at) {
    ++pos_;  // \lim
    if (!is_char(peek(), "_")) fail(at, "a limit is read as \\lim_{x \\to a} f, with its point");
    ++pos_;
    const std::pair<std::size_t, std::size_t> r = argument_range("the limit");
    std::size_t arrow = r.second;
    for (std::size_t k = r.first; k < r.second && arrow == r.second; ++k)
        if (t_[k].kind == Tok::Word && is_one_of(t_[k].text, {"\\to", "\\rightarrow", "\\longrightarrow"})) arrow = k;
    if (arrow == r.second) fail(at, "a limit is read as \\lim_{x \\to a} f, with its point");
    for (std::size_t k = arrow + 1; k < r.second; ++k)
        if (t_[k].kind == Tok::Word && t_[k].text == "\\infty") fail(at, "a limit at infinity is not taken");
    const GiNaC::ex var = expr_in({r.first, arrow}, "the limit's variable");
    const GiNaC::ex point = expr_in({arrow + 1, r.second}, "the limit's point");
    if (!GiNaC::is_a<GiNaC::symbol>(var)) fail(at, "a limit's variable is one name");
    if (at_end() || stops_expression(peek())) fail(at, "\\lim needs what it is the limit of");
    // Of one term, as \sin is of one factor: `\lim_{x \to 0} \frac{\sin x}{x} + 1` is 1 + 1. Taken by the checker
    // (latex_parser.hpp, limat), after the derivatives in it.
    return limat(term(), GiNaC::lst{var == point});
}

GiNaC::ex Parser::function(const std::string& f, std::size_t at) {
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

GiNaC::ex Parser::slashed_partial(std::size_t at) {
    // `\partial L/\partial \theta`, `\partial (T - V)/\partial q`: plain text's ∂L/∂θ, read as the \frac it stands
    // for. The operand runs to the `/` (outside brackets, before any + or −); a name follows the second ∂.
    std::size_t slash = pos_ + 1;
    for (int depth = 0; slash < end_; ++slash) {
        const Token& k = t_[slash];
        if (k.kind != Tok::Char) continue;
        if (k.text == "{" || k.text == "(" || k.text == "[") ++depth;
        if (k.text == "}" || k.text == ")" || k.text == "]") {
            if (depth == 0) break;
            --depth;
        }
        if (depth == 0 && (k.text == "/" || k.text == "+" || k.text == "-")) break;
    }
    std::size_t second = slash + 1;
    while (second < end_ && t_[second].space) ++second;
    const bool slashed = slash < end_ && t_[slash].kind == Tok::Char && t_[slash].text == "/" && slash > pos_ + 1 &&
                         second < end_ && t_[second].kind == Tok::Word && t_[second].text == "\\partial";
    if (!slashed) fail(at, "a partial derivative outside \\frac{\\partial ...}{\\partial ...} is not read");
    const std::pair<std::size_t, std::size_t> num{pos_, slash};
    pos_ = second + 1;
    skip_spaces();
    std::size_t close = 0;
    if (is_char(peek(), "{")) {
        close = match_brace(pos_);
        ++pos_;
    }
    has_pending_power_ = false;
    NameParts var;
    if (!read_name(var) || has_pending_power_)
        fail(at, "a partial derivative outside \\frac{\\partial ...}{\\partial ...} is not read");
    if (close != 0) {
        skip_spaces();
        if (pos_ != close) fail(at, "a partial derivative outside \\frac{\\partial ...}{\\partial ...} is not read");
        ++pos_;
    }
    return derivative(at, num, var, 1, true);
}

}  // namespace eomgen::checker::parsing
