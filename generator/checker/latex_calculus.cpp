/** @file latex_calculus.cpp  The parser's calculus: \frac and the derivatives it writes, \sqrt,
 * differentials and integrals (latex_grammar.hpp). */
#include "checker/latex_grammar.hpp"

#include <algorithm>

namespace eomgen::checker::parsing {

/// 'd' followed by a name, inside an integral whose variable is not yet read.
bool Parser::differential_here() {
    if (frames_.empty() || frames_.back().found) return false;
    const Token* next = peek_at(1);
    return starts_name(next);
}

GiNaC::ex Parser::differential() {
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

GiNaC::ex Parser::integral(std::size_t at) {
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
    if (has_lo != has_hi) fail(at, "an integral over a region is not evaluated");
    if (!has_lo) return indefinite_integral(at);
    return integral_body(at, lo, hi, true);
}

/// The integrand up to its differential d<variable> (pos_ after \int and its limits): ∫_lo^hi f dx evaluated where
/// GiNaC can, or, not `definite`, antiderivative(f, x) held.
GiNaC::ex Parser::integral_body(std::size_t at, GiNaC::ex lo, GiNaC::ex hi, bool definite) {
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
    if (!definite) return antiderivative(body, var).hold();
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

/// ∫ f dx without limits (pos_ after \int): antiderivative(f, x), held, when x is a coordinate of the model or the
/// time and one differential closes it; the checker judges it up to a constant of integration
/// (indefinite_integral.hpp). Anything else (∫ v² dm over a body, ∫ σ dx dz over a region) is not read, as before.
GiNaC::ex Parser::indefinite_integral(std::size_t at) {
    GiNaC::ex v;
    try {
        v = integral_body(at, 0, 0, false);
    } catch (const ParseFailure&) {
        fail(at, "an indefinite integral is not evaluated");
    }
    const bool variable = std::any_of(ctx_.coordinates.begin(), ctx_.coordinates.end(),
                                      [&](const GiNaC::ex& q) { return q.is_equal(v.op(1)); }) ||
                          v.op(1).is_equal(ctx_.time);
    // A second differential (`d z'`) makes it an integral over a region.
    const Token* next = peek();
    if (!variable || (next && next->kind == Tok::Letter && next->text == "d" && starts_name(peek_at(1))))
        fail(at, "an indefinite integral is not evaluated");
    return v;
}

void Parser::remove_uses(const std::string& name, std::size_t from) {
    auto& u = side_.uses;
    u.erase(std::remove_if(u.begin(), u.end(),
                           [&](const NameUse& x) { return x.name == name && x.offset >= from; }),
            u.end());
}

GiNaC::ex Parser::square_root(std::size_t at) {
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
int Parser::derivative_marker(std::size_t b, std::size_t e) const {
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

GiNaC::ex Parser::fraction(std::size_t at) {
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

GiNaC::ex Parser::derivative(std::size_t at, std::pair<std::size_t, std::size_t> num, const NameParts& var,
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
        if (v != "t" && !(it != ctx_.names.end() && tv.is_equal(ctx_.time))) {
            // (By one of the model's coordinates, `\frac{d}{d\phi}`, it is not read: texts write it for a partial
            // derivative of a function of several, the seed's f_x(θ, φ), as often as for one along the motion.)
            // By a name the text introduces (a dimensionless time τ = t/T): the checker reads its definition.
            if (it == ctx_.names.end() && var.dots == 0) {
                side_.uses.push_back({v, offset_of(at)});
                const GiNaC::ex s = ctx_.free_symbol(v, var.kind);
                for (int i = 0; i < order; ++i) operand = dby(operand, s);
                return operand;
            }
            fail(at, "a derivative with respect to " + v + " (only d/dt is read)");
        }
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

}  // namespace eomgen::checker::parsing
