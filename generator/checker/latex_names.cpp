/** @file latex_names.cpp  The parser's names: accents, subscripts, primes, and what a name stands for
 * (latex_grammar.hpp). */
#include "checker/latex_grammar.hpp"

#include "checker/units.hpp"

#include <algorithm>
#include <sstream>

namespace eomgen::checker::parsing {

bool Parser::starts_name(const Token* t) const {
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
NameParts Parser::argument_name(std::size_t at, const char* what, bool power_inside) {
    ++pos_;
    const auto r = argument_range(t_[at].text);
    NameParts inner;
    within(
        r.first, r.second,
        [&] {
            if (!read_name(inner)) fail(r.first, t_[at].text + " of an expression is not read");
            // `\dot{r^2}` for ṙ² (the accent over the power, as some write it; the rate of r² is written
            // \frac{d}{dt}(r^2) or \dot{(r^2)}): the power is the name's, after its dots.
            if (power_inside && is_char(peek(), "^") && !has_pending_power_) {
                const std::size_t power_at = pos_;
                ++pos_;
                pending_power_ = superscript(power_at);
                has_pending_power_ = true;
                std::ostringstream power;
                power << pending_power_;
                const std::string x = inner.canonical(), p = "^{" + power.str() + "}";
                const std::string note = "reads $" + t_[at].text + "{" + x + p + "}$ as $" + t_[at].text + "{" + x +
                                         "}" + p + "$ (the accent written over the power)";
                add_note_once(side_.notes, note);
            }
            return 0;
        },
        what);
    return inner;
}

bool Parser::read_name(NameParts& n) {
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
            const NameParts inner = argument_name(at, "the accent", true);
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

/// At '^': when the superscript starts with \prime or ', counts the primes into n and leaves any rest of the
/// superscript (`^{\prime 2}`) as pending_power_. Returns false (pos_ unchanged) when it is an exponent.
bool Parser::prime_superscript(NameParts& n) {
    const std::size_t at = pos_;
    const Token* a = peek_at(1);
    if (!a) return false;
    if ((a->kind == Tok::Word && a->text == "\\prime") || (a->kind == Tok::Char && a->text == "'")) {
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
    // \prime or ' (`r_{1}^{'}`, as a word processor writes r₁′).
    while (q < close && ((t_[q].kind == Tok::Word && t_[q].text == "\\prime") || (t_[q].kind == Tok::Char && t_[q].text == "'"))) {
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
bool Parser::exponent_before_subscript(const NameParts& n) {
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
std::string Parser::subscript_text(std::size_t b, std::size_t e) const {
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
GiNaC::ex Parser::name_value() {
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
    // `\theta(0)`, `\dot x(0)`: a coordinate or its rate at an instant (a number written right after it, no space):
    // a value of its own, the text's name for it (an initial condition), not the coordinate times that number.
    if (pos_ + 2 < end_ && is_char(peek(), "(") && t_[pos_ - 1].offset + t_[pos_ - 1].length == t_[pos_].offset) {
        std::size_t q = pos_ + 1;
        std::string digits;
        while (q < end_ && (t_[q].kind == Tok::Digit || is_char(&t_[q], "."))) digits += t_[q++].text;
        NameParts plain = n;
        plain.dots = 0;
        plain.primes = 0;
        const auto it = ctx_.names.find(plain.canonical());
        if (!digits.empty() && q < end_ && is_char(&t_[q], ")") && !has_pending_power_ && it != ctx_.names.end() &&
            std::any_of(ctx_.coordinates.begin(), ctx_.coordinates.end(),
                        [&](const GiNaC::ex& c) { return c.is_equal(it->second); })) {
            pos_ = q + 1;
            const std::string full = n.canonical() + "(" + digits + ")";
            side_.uses.push_back({full, offset_of(at)});
            GiNaC::ex v = ctx_.free_symbol(full, NameKind::Unknown);
            if (is_char(peek(), "^")) {
                const std::size_t pat = pos_;
                ++pos_;
                v = power(v, superscript(pat), pat);
            }
            return v;
        }
    }
    // `V'(\theta)`, `I_p''(\theta)`: the derivative by the coordinate of the name as a function of it (a label, or
    // a name the text defines, then differentiated as its definition); `I_p(\theta)`: the name itself.
    GiNaC::ex v;
    const std::size_t after = pos_;
    if (const std::optional<GiNaC::ex> q = n.dots == 0 ? coordinate_argument() : std::nullopt) {
        NameParts unprimed = n;
        unprimed.primes = 0;
        v = resolve(unprimed, at);
        static const char* const kLabels[] = {"T", "V", "U", "L", "H", "E", "K"};
        const bool label = std::any_of(std::begin(kLabels), std::end(kLabels), [&](const char* l) { return n.base == l; });
        const bool coordinate = std::any_of(ctx_.coordinates.begin(), ctx_.coordinates.end(),
                                            [&](const GiNaC::ex& c) { return v.is_equal(c); });
        if (coordinate && n.primes > 0 && !v.is_equal(*q)) {
            // `r'(\theta)`, `r''(\theta)`: one coordinate as a function of another along the motion (an orbit),
            // dr/dθ = ṙ/θ̇, each prime one more d/dθ = (1/θ̇) d/dt.
            for (int k = 0; k < n.primes; ++k) v = ddt(v) / ddt(*q);
            std::string by = t_[after + 1].text;
            for (const auto& [name, value] : ctx_.names)
                if (value.is_equal(*q)) by = name;
            const std::string note =
                "$" + n.canonical() + "(" + by + ")$ read as the derivative by it along the motion (d/dt over its rate)";
            add_note_once(side_.notes, note);
        } else if (ctx_.free_name_of(v) == nullptr && !label) {
            pos_ = after;  // `m(\theta)`: a parameter times θ
            v = resolve(n, at);
        } else {
            for (int k = 0; k < n.primes; ++k) v = pdiff(v, *q);
        }
    } else {
        v = resolve(n, at);
    }
    if (has_pending_power_) {
        has_pending_power_ = false;
        v = power(v, pending_power_, at);
    }
    return v;
}

std::optional<GiNaC::ex> Parser::coordinate_argument() {
    const std::size_t at = pos_;
    if (at == 0 || at + 2 >= t_.size() || t_[at].text != "(" ||
        t_[at - 1].offset + t_[at - 1].length != t_[at].offset)
        return std::nullopt;
    const std::size_t saved_uses = side_.uses.size();
    const bool saved_pending = has_pending_power_;
    try {
        ++pos_;
        NameParts a;
        if (read_name(a) && !has_pending_power_ && is_char(peek(), ")")) {
            const auto it = ctx_.names.find(a.canonical());
            if (it != ctx_.names.end() &&
                std::any_of(ctx_.coordinates.begin(), ctx_.coordinates.end(),
                            [&](const GiNaC::ex& q) { return q.is_equal(it->second); })) {
                ++pos_;
                return it->second;
            }
        }
    } catch (const ParseFailure&) {
    }
    pos_ = at;
    side_.uses.resize(saved_uses);
    has_pending_power_ = saved_pending;
    return std::nullopt;
}

GiNaC::ex Parser::resolve(const NameParts& n, std::size_t at) {
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
    // `\theta''`, `x'` of a coordinate: its time derivatives, as texts that write primes for them mean it.
    if (n.primes > 0 && n.dots == 0 && ctx_.primes_are_time_derivatives) {
        NameParts unprimed = n;
        unprimed.primes = 0;
        const auto q = ctx_.names.find(unprimed.canonical());
        if (q != ctx_.names.end() &&
            std::any_of(ctx_.coordinates.begin(), ctx_.coordinates.end(), [&](const GiNaC::ex& c) { return c.is_equal(q->second); })) {
            GiNaC::ex v = q->second;
            for (int i = 0; i < n.primes; ++i) v = ddt(v);
            const std::string note = "primes on a coordinate read as time derivatives ($" + full + "$)";
            add_note_once(side_.notes, note);
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
    if (const FreeName* same = ctx_.subscript_case_variant(full, n.kind)) {
        const std::string note = "reads $" + full + "$ as $" + same->name +
                                 "$, the same name but for the case of its subscript, as the text writes both";
        add_note_once(side_.notes, note);
        return same->symbol;
    }
    return ctx_.free_symbol(full, n.kind);
}

}  // namespace eomgen::checker::parsing
