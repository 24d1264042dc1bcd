/** @file latex_parser.cpp  Derivation LaTeX split into chains of relations and sides, each side parsed by the
 * recursive-descent parser of latex_grammar.hpp. */
#include "checker/latex_parser.hpp"
#include "checker/latex_grammar.hpp"

#include "checker/latex_normalize.hpp"
#include "checker/latex_tokens.hpp"
#include "checker/units.hpp"

#include <algorithm>
#include <cctype>

namespace eomgen::checker {

REGISTER_FUNCTION(ddt, dummy().latex_name("\\frac{d}{dt}"))
REGISTER_FUNCTION(pdiff, dummy().latex_name("\\partial"))
REGISTER_FUNCTION(pbracket, dummy().latex_name("\\{\\}"))
REGISTER_FUNCTION(dby, dummy().latex_name("\\frac{d}{ds}"))
REGISTER_FUNCTION(antiderivative, dummy().latex_name("\\int"))
REGISTER_FUNCTION(evalat, dummy().latex_name("\\Big|"))
REGISTER_FUNCTION(limat, dummy().latex_name("\\lim"))

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

const FreeName* LatexContext::subscript_case_variant(const std::string& name, NameKind kind) const {
    const std::size_t sub = name.find("_{");
    if (sub == std::string::npos || free_names.count(name)) return nullptr;
    const auto lower = [](std::string s) {
        for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return s;
    };
    const std::string folded = lower(name.substr(sub));
    // The subscript's text: `\vec{r_{M}}` → "M".
    const auto subscript = [&](const std::string& s) {
        const std::size_t close = s.find('}', sub + 2);
        return s.substr(sub + 2, close == std::string::npos ? std::string::npos : close - sub - 2);
    };
    for (const auto& [other, free] : free_names)
        if (free.kind == kind && other.size() == name.size() && other.compare(0, sub + 2, name, 0, sub + 2) == 0 &&
            lower(other.substr(sub)) == folded) {
            // `\vec{r_M}` and `\vec{r_m}` where M and m are both the model's (the cart's mass and the bob's): two
            // points, named after two bodies.
            if (names.count(subscript(name)) && names.count(subscript(other))) continue;
            return &free;
        }
    return nullptr;
}

namespace {

using namespace parsing;

// ------------------------------------------------------------------------------------ chains and sides

/// Depth of each token (braces, brackets, parentheses, \left...\right, \begin...\end) at its start.
std::vector<int> depths(const std::vector<Token>& t) {
    std::vector<int> d(t.size(), 0);
    // What is open, innermost last. A '}' closes its '{' and whatever the group left open inside it (TeX's groups
    // are what counts: `\frac{mg}{(m+(k^2 m R^2)/(R_0^2 )}` leaves a '(' open, and the '=' after the fraction is
    // still at the top level).
    std::vector<std::string> open;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const Token& k = t[i];
        if (k.kind == Tok::Char && k.text == "}") {
            if (std::find(open.begin(), open.end(), "{") != open.end())
                while (!open.empty()) {
                    const std::string last = open.back();
                    open.pop_back();
                    if (last == "{") break;
                }
            else if (!open.empty())
                open.pop_back();
        } else if ((k.kind == Tok::Char && (k.text == ")" || k.text == "]")) ||
                   (k.kind == Tok::Word && (k.text == "\\right" || k.text == "\\end" || k.text == "\\}"))) {
            if (!open.empty()) open.pop_back();
        }
        d[i] = int(open.size());
        const bool opens = (k.kind == Tok::Char && (k.text == "{" || k.text == "(" || k.text == "[")) ||
                           (k.kind == Tok::Word && (k.text == "\\left" || k.text == "\\begin" || k.text == "\\{"));
        if (opens) open.push_back(k.text);
        // \left( and \right): the delimiter token that follows is part of the command.
        if (k.kind == Tok::Word && (k.text == "\\left" || k.text == "\\right") && i + 1 < t.size()) {
            ++i;
            d[i] = int(open.size());
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
            if (k.text == "\\neq" || k.text == "\\ne") r = Relation::NotEqual;
            out.push_back({i, 1, r});
        }
    }
    return out;
}

Side make_side(std::string_view text, const std::vector<Token>& t, std::size_t b, std::size_t e,
               LatexContext& ctx) {
    // Trailing punctuation ends sentences, not formulas (`x = A\cos(\omega t):` before the display it leads into).
    while (e > b && ((t[e - 1].kind == Tok::Char && (t[e - 1].text == "." || t[e - 1].text == "," ||
                                                     t[e - 1].text == ";" || t[e - 1].text == ":")) ||
                     (t[e - 1].space && e - 1 > b && t[e - 2].kind == Tok::Char &&
                      (t[e - 2].text == "." || t[e - 2].text == "," || t[e - 2].text == ";" || t[e - 2].text == ":"))))
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
    // `1.993 \cdot 10^{-26} kg`, `3628 N/m`: a unit written in bare letters after a number, one of them no name
    // the text may mean (g here is no symbol of the model): read as \mathrm{~kg}.
    std::vector<Token> with_unit;
    {
        std::size_t u = e;
        while (u > b && (t[u - 1].kind == Tok::Letter ||
                         (t[u - 1].kind == Tok::Char && (t[u - 1].text == "/" || t[u - 1].text == "^")) ||
                         (t[u - 1].kind == Tok::Digit && u - 1 > b && t[u - 2].kind == Tok::Char && t[u - 2].text == "^")))
            --u;
        while (u < e && t[u].kind != Tok::Letter) ++u;  // starts with a letter
        const bool after_number = u > b && u < e && (t[u - 1].kind == Tok::Digit || (t[u - 1].kind == Tok::Char && t[u - 1].text == "}"));
        std::string unit;
        bool unknown_letter = false;
        for (std::size_t k = u; k < e; ++k) {
            unit += t[k].text;
            if (t[k].kind == Tok::Letter && !ctx.names.count(t[k].text)) unknown_letter = true;
        }
        if (after_number && unknown_letter && unit.size() >= 2 && is_unit(unit)) {
            with_unit.assign(t.begin(), t.begin() + std::ptrdiff_t(u));
            with_unit.push_back({Tok::Word, "\\mathrm", t[u].offset, t[e - 1].offset + t[e - 1].length - t[u].offset,
                                 "~" + unit, false});
            e = u + 1;
        }
    }
    const std::vector<Token>& tokens = with_unit.empty() ? t : with_unit;
    try {
        Parser p(tokens, b, e, ctx, s);
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

// ------------------------------------------------------------------------------------ tuples

/// The entries of a list `a, b, c` or `(a, b, c)` (`\left( … \right)` too) in tokens [b, e): their token ranges,
/// split at the commas of the list's own level; empty when [b, e) is not a list of two or more.
std::vector<std::pair<std::size_t, std::size_t>> list_entries(const std::vector<Token>& t, const std::vector<int>& d,
                                                              std::size_t b, std::size_t e) {
    const auto is_char = [&](std::size_t i, const char* c) { return t[i].kind == Tok::Char && t[i].text == c; };
    const auto is_word = [&](std::size_t i, const char* w) { return t[i].kind == Tok::Word && t[i].text == w; };
    while (b < e && t[b].space) ++b;
    while (e > b && (t[e - 1].space || is_char(e - 1, ".") || is_char(e - 1, ";") || is_char(e - 1, ","))) --e;
    if (b >= e) return {};
    int level = d[b];
    // One group around the whole: `(x, y, z)`, `\left(x, y\right)`.
    std::size_t ib = b, ie = e;
    if (is_char(b, "(") && is_char(e - 1, ")") && e - b >= 2) {
        ib = b + 1;
        ie = e - 1;
    } else if (e - b >= 4 && is_word(b, "\\left") && is_char(b + 1, "(") && is_word(e - 2, "\\right") &&
               is_char(e - 1, ")")) {
        ib = b + 2;
        ie = e - 2;
    }
    if (ib != b) {
        for (std::size_t i = ib; i < ie; ++i)
            if (d[i] <= level) return {};  // `(a)(b)`: two groups, not one around the whole
        ++level;
    }
    std::vector<std::pair<std::size_t, std::size_t>> out;
    std::size_t from = ib;
    for (std::size_t i = ib; i < ie; ++i)
        if (d[i] == level && is_char(i, ",")) {
            out.push_back({from, i});
            from = i + 1;
        }
    out.push_back({from, ie});
    if (out.size() < 2 || out.size() > 4) return {};
    for (const auto& [x, y] : out)
        if (std::all_of(t.begin() + long(x), t.begin() + long(y), [](const Token& k) { return k.space; })) return {};
    return out;
}

/**
 * `x, y, z = 0, 0, 0` and `(x, y) = (a, b)`: one `=` between two lists of as many entries, each entry on the left a
 * name: one chain a name, `x = 0`, `y = 0`, `z = 0`, each with its relation placed just after its name (their places
 * differ, as the report and the comparisons need). `\mathbf{r} = (x, y, z)`: a vector set to a list of two or three
 * entries is its components along the axes, `x\hat{x} + y\hat{y} + z\hat{z}`. Empty when the piece is neither.
 */
std::vector<Chain> tuple_chains(std::string_view text, const std::vector<Token>& t, const std::vector<int>& d,
                                std::size_t b, std::size_t e, LatexContext& ctx) {
    const std::vector<RelationAt> rel = relations_in(t, d, b, e);
    if (rel.size() != 1 || rel[0].kind != Relation::Equal) return {};
    const std::size_t sign = rel[0].index, after = rel[0].index + rel[0].count;
    const auto left = list_entries(t, d, b, sign);
    const auto right = list_entries(t, d, after, e);
    if (right.empty()) return {};
    // Lists in parentheses are also vectors, which linear_algebra.hpp reads (`(I_1, I_2, I_3) = (…)`, a stated
    // `\mathbf{u} = (1, 0, 0)`): split only where they name a point's coordinates, x, y, z (`x_{2}`), or its
    // position vector, r (`\vec{r}_{2}`); bare lists, which are no vectors, always.
    const auto enclosed = [&](std::size_t from, std::size_t to) {
        while (from < to && t[from].space) ++from;
        return from < to && ((t[from].kind == Tok::Char && t[from].text == "(") ||
                             (t[from].kind == Tok::Word && t[from].text == "\\left"));
    };
    const auto position_vector = [](const std::string& n) {
        for (const char* deco : {"\\mathbf{r", "\\vec{r", "\\boldsymbol{r", "\\bm{r", "\\textbf{r"})
            if (n.rfind(deco, 0) == 0) {
                const std::size_t k = std::string(deco).size();
                return n.size() > k && (n[k] == '}' || n.compare(k, 2, "_{") == 0);
            }
        return false;
    };
    const bool parentheses = enclosed(b, sign) || enclosed(after, e);
    const auto end_of = [&](std::size_t last) { return t[last - 1].offset + t[last - 1].length; };
    std::vector<Chain> out;
    if (left.empty()) {
        Side whole = make_side(text, t, b, sign, ctx);
        const FreeName* f = whole.ok ? ctx.free_name_of(whole.value) : nullptr;
        if (!f || f->kind != NameKind::Vector || right.size() > 3 || !position_vector(f->name)) return {};
        Side comps = make_side(text, t, after, e, ctx);  // for its place and source; its value is the sum below
        comps.ok = true;
        comps.error.clear();
        comps.uses.clear();
        comps.value = 0;
        static const char* const units[] = {"\\hat{x}", "\\hat{y}", "\\hat{z}"};
        for (std::size_t k = 0; k < right.size(); ++k) {
            const Side entry = make_side(text, t, right[k].first, right[k].second, ctx);
            if (!entry.ok) return {};
            comps.value += entry.value * ctx.free_symbol(units[k], NameKind::Vector);
            comps.uses.insert(comps.uses.end(), entry.uses.begin(), entry.uses.end());
            comps.rounding += entry.rounding;
        }
        Chain c;
        c.begin = t[b].offset;
        c.end = comps.end;
        c.sides = {std::move(whole), std::move(comps)};
        c.relations = {Relation::Equal};
        c.relation_offsets = {t[sign].offset};
        out.push_back(std::move(c));
        return out;
    }
    if (left.size() != right.size()) return {};
    for (std::size_t k = 0; k < left.size(); ++k) {
        Side name = make_side(text, t, left[k].first, left[k].second, ctx);
        if (!name.ok || !GiNaC::is_a<GiNaC::symbol>(name.value)) return {};
        if (parentheses) {
            const FreeName* f = ctx.free_name_of(name.value);
            if (!f || !position_name(f->name)) return {};
        }
        Chain c;
        c.begin = name.begin;
        c.relations = {Relation::Equal};
        c.relation_offsets = {name.end};
        c.sides.push_back(std::move(name));
        c.sides.push_back(make_side(text, t, right[k].first, right[k].second, ctx));
        c.end = std::max(c.sides.back().end, end_of(right[k].second));
        out.push_back(std::move(c));
    }
    return out;
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
            if (std::vector<Chain> parts = tuple_chains(text, t, d, b, e, context); !parts.empty()) {
                for (Chain& c : parts) out.push_back(std::move(c));
                continue;
            }
            out.push_back(make_chain(text, t, d, b, e, context));
        }
    }
    // Math inside a display's text (`\qquad \text{where $\omega^2 = k/m$}`): its own chains, at their places.
    for (const Token& k : t) {
        if (k.kind != Tok::Word || k.raw.find('$') == std::string::npos || k.offset + k.length > text.size()) continue;
        const std::string_view whole = text.substr(k.offset, k.length);
        const std::size_t raw_at = whole.find(k.raw);
        if (raw_at == std::string_view::npos) continue;
        for (std::size_t open = k.raw.find('$'); open != std::string::npos;) {
            const std::size_t close = k.raw.find('$', open + 1);
            if (close == std::string::npos) break;
            const std::size_t at = k.offset + raw_at + open + 1;
            std::vector<Chain> inner = parse_math(text.substr(at, close - open - 1), context);
            for (Chain& c : inner) {
                c.begin += at;
                c.end += at;
                for (std::size_t& r : c.relation_offsets) r += at;
                for (Side& sd : c.sides) {
                    sd.begin += at;
                    sd.end += at;
                    sd.error_offset += at;
                    for (NameUse& u : sd.uses) u.offset += at;
                }
                out.push_back(std::move(c));
            }
            open = k.raw.find('$', close + 1);
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

std::optional<PositionName> position_name(const std::string& canonical) {
    if (canonical.empty()) return std::nullopt;
    // `X, Y` (a point's coordinates in capitals, beside a support's x): another point than x, y's.
    const bool capital = canonical[0] == 'X' || canonical[0] == 'Y' || canonical[0] == 'Z';
    if (!capital && canonical[0] != 'x' && canonical[0] != 'y' && canonical[0] != 'z') return std::nullopt;
    PositionName p;
    p.axis = canonical[0] - (capital ? 'X' : 'x');
    if (capital) p.point = "(capitals)";
    if (canonical.size() == 1) return p;
    // `x_{2}`, `y_{bob}`: one group of braces after the underscore, nothing else.
    if (canonical.size() < 5 || canonical.compare(1, 2, "_{") != 0 || canonical.back() != '}') return std::nullopt;
    p.point += canonical.substr(3, canonical.size() - 4);
    if (p.point.find_first_of("{}\\ ") != std::string::npos) return std::nullopt;
    return p;
}

bool has_relation(std::string_view text) {
    std::vector<Token> t = tokenize(text);
    const std::vector<int> d = depths(t);
    return !relations_in(t, d, 0, t.size()).empty();
}

}  // namespace eomgen::checker
