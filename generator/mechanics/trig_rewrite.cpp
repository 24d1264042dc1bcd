/** @file trig_rewrite.cpp  Angle-sum formulas both ways, sin² + cos² = 1, like terms collected (GiNaC has
 * none). */
#include "mechanics/trig_rewrite.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <string>

namespace eomgen::trig {
namespace {

std::size_t terms(const GiNaC::ex& e) {
    return GiNaC::is_a<GiNaC::add>(e) ? e.nops() : (e.is_zero() ? 0 : 1);
}

std::vector<GiNaC::ex> terms_of(const GiNaC::ex& e) {
    std::vector<GiNaC::ex> out;
    if (GiNaC::is_a<GiNaC::add>(e))
        for (const GiNaC::ex& t : e) out.push_back(t);
    else if (!e.is_zero())
        out.push_back(e);
    return out;
}

bool is_trig(const GiNaC::ex& x) {
    return GiNaC::is_the_function<GiNaC::sin_SERIAL>(x) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(x);
}

/// A key that orders expressions the same way in every process (GiNaC's own order follows hash values that
/// change with addresses): symbol names, numbers, and the keys of the parts, sorted where order is free.
std::string key(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::symbol>(e)) return GiNaC::ex_to<GiNaC::symbol>(e).get_name();
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
        std::ostringstream os;
        os << e;
        return os.str();
    }
    std::vector<std::string> parts;
    for (const GiNaC::ex& x : e) parts.push_back(key(x));
    std::string head;
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
        std::sort(parts.begin(), parts.end());
        head = GiNaC::is_a<GiNaC::add>(e) ? "+" : "*";
    } else if (GiNaC::is_a<GiNaC::function>(e)) {
        head = GiNaC::ex_to<GiNaC::function>(e).get_name();
    } else if (GiNaC::is_a<GiNaC::power>(e)) {
        head = "^";
    } else {
        head = "?";
    }
    std::string out = head + "(";
    for (const std::string& p : parts) out += p + ",";
    return out + ")";
}

void sort_by_key(std::vector<GiNaC::ex>& v) {
    std::vector<std::pair<std::string, GiNaC::ex>> keyed;
    for (const GiNaC::ex& x : v) keyed.push_back({key(x), x});
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = keyed[i].second;
}

/// The numerical factor of a term (3/2 of 3/2·m·x), 1 when there is none.
GiNaC::numeric numeric_part(const GiNaC::ex& t) {
    if (GiNaC::is_a<GiNaC::numeric>(t)) return GiNaC::ex_to<GiNaC::numeric>(t);
    GiNaC::numeric c = 1;
    if (GiNaC::is_a<GiNaC::mul>(t))
        for (const GiNaC::ex& f : t)
            if (GiNaC::is_a<GiNaC::numeric>(f)) c *= GiNaC::ex_to<GiNaC::numeric>(f);
    return c;
}

/// sin(arg) or cos(arg) with arg's sums split by the angle-sum formulas.
GiNaC::ex split(const GiNaC::ex& arg, bool sine) {
    if (GiNaC::is_a<GiNaC::add>(arg) && arg.nops() > 1) {
        const GiNaC::ex p = arg.op(0), q = arg - p;
        const GiNaC::ex sp = split(p, true), cp = split(p, false), sq = split(q, true), cq = split(q, false);
        return sine ? sp * cq + cp * sq : cp * cq - sp * sq;
    }
    if (numeric_part(arg).is_negative()) return sine ? -GiNaC::sin(-arg) : GiNaC::cos(-arg);
    return sine ? GiNaC::sin(arg) : GiNaC::cos(arg);
}

struct ExpandSums : GiNaC::map_function {
    GiNaC::ex operator()(const GiNaC::ex& x) override {
        if (is_trig(x))
            return split(x.op(0).map(*this).expand(), GiNaC::is_the_function<GiNaC::sin_SERIAL>(x));
        if (GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<GiNaC::numeric>(x.op(1)) &&
            GiNaC::ex_to<GiNaC::numeric>(x.op(1)).is_negative())
            return x;  // denominators are rewritten on their own (TidyDenominators)
        return x.map(*this);
    }
};

/// Every distinct argument of a sine or cosine in e, deepest first not needed: top level and nested alike.
std::vector<GiNaC::ex> trig_arguments(const GiNaC::ex& e) {
    GiNaC::exset seen;
    std::vector<GiNaC::ex> out, stack{e};
    while (!stack.empty()) {
        const GiNaC::ex x = stack.back();
        stack.pop_back();
        if (is_trig(x) && seen.insert(x.op(0)).second) out.push_back(x.op(0));
        for (const GiNaC::ex& y : x) stack.push_back(y);
    }
    sort_by_key(out);
    return out;
}

/// u = p + s·q with p's sign positive, or false when u is not a sum of two terms of which one is positive.
bool decompose(const GiNaC::ex& u, GiNaC::ex& p, int& s, GiNaC::ex& q) {
    if (!GiNaC::is_a<GiNaC::add>(u) || u.nops() != 2) return false;
    const GiNaC::ex a = u.op(0), b = u.op(1);
    if (GiNaC::is_a<GiNaC::numeric>(a) || GiNaC::is_a<GiNaC::numeric>(b)) return false;
    const bool na = numeric_part(a).is_negative(), nb = numeric_part(b).is_negative();
    if (na && nb) return false;
    p = na ? b : a;
    const GiNaC::ex other = na ? a : b;
    s = numeric_part(other).is_negative() ? -1 : 1;
    q = s * other;
    return true;
}

/// One angle u = p + s·q: pairs of terms contracted into cos u and sin u until none is left.
std::vector<GiNaC::ex> contract_one(std::vector<GiNaC::ex> ts, const GiNaC::ex& u) {
    GiNaC::ex p, q;
    int s = 1;
    if (!decompose(u, p, s, q)) return ts;
    const GiNaC::ex sp = GiNaC::sin(p), cp = GiNaC::cos(p), sq = GiNaC::sin(q), cq = GiNaC::cos(q);
    // cos u = cos p cos q − s sin p sin q;  sin u = sin p cos q + s cos p sin q.
    struct Pattern {
        GiNaC::ex first, second, result;
        int sign;
    };
    const Pattern patterns[2] = {{cp * cq, sp * sq, GiNaC::cos(u), -s}, {sp * cq, cp * sq, GiNaC::sin(u), s}};
    for (int guard = 0; guard < 10000; ++guard) {
        sort_by_key(ts);
        std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> index;  // term without its number → position
        for (std::size_t i = 0; i < ts.size(); ++i) index[ts[i] / numeric_part(ts[i])] = i;
        bool changed = false;
        for (std::size_t i = 0; i < ts.size() && !changed; ++i)
            for (const Pattern& pat : patterns) {
                const GiNaC::ex f0 = pat.first.op(0), f1 = pat.first.op(1);
                if (ts[i].degree(f0) < 1 || ts[i].degree(f1) < 1) continue;
                const GiNaC::ex x = ts[i] / pat.first;                // X: the term without the first pair
                const GiNaC::ex partner = pat.sign * x * pat.second;  // the term the formula needs beside it
                const auto it = index.find(partner / numeric_part(partner));
                if (it == index.end() || it->second == i) continue;
                const std::size_t j = it->second;
                const GiNaC::numeric r = numeric_part(ts[j]) / numeric_part(partner);  // t_j = r · partner
                if (!r.is_positive()) continue;
                const GiNaC::numeric k = r < 1 ? r : GiNaC::numeric(1);
                ts.push_back(k * x * pat.result);
                ts[i] = (1 - k) * ts[i];
                ts[j] = ts[j] - k * partner;
                ts.erase(std::remove_if(ts.begin(), ts.end(), [](const GiNaC::ex& t) { return t.is_zero(); }),
                         ts.end());
                changed = true;
                break;
            }
        if (!changed) break;
    }
    return ts;
}

GiNaC::ex sum(const std::vector<GiNaC::ex>& ts) {
    GiNaC::ex out = 0;
    for (const GiNaC::ex& t : ts) out += t;
    return out;
}

/// Angle sums of the atoms of e's sines and cosines that shorten e, tried pair by pair.
GiNaC::ex contract_others(const GiNaC::ex& e) {
    std::vector<GiNaC::ex> atoms;
    for (const GiNaC::ex& a : trig_arguments(e))
        if (!GiNaC::is_a<GiNaC::add>(a)) atoms.push_back(a);
    if (atoms.size() > 8) return e;
    GiNaC::ex best = e;
    for (std::size_t i = 0; i < atoms.size(); ++i)
        for (std::size_t j = i + 1; j < atoms.size(); ++j)
            for (const GiNaC::ex& u : {atoms[i] - atoms[j], atoms[i] + atoms[j]}) {
                const GiNaC::ex c = contract_sums(best, {u});
                if (terms(c) < terms(best)) best = c;
            }
    return best;
}

/// No negative or fractional powers of a symbol: a sum that factor() takes without a common denominator.
bool polynomial(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::power>(e) && !GiNaC::is_a<GiNaC::numeric>(e.op(0)) &&
        !e.op(1).info(GiNaC::info_flags::posint))
        return false;
    for (const GiNaC::ex& x : e)
        if (!polynomial(x)) return false;
    return true;
}

/// The coefficient of a group of like terms, factored where that is cheap: ½ g l (m + 2M), and over a
/// common denominator when its terms have denominators: I₃/I − 1 → (I₃ − I)/I.
GiNaC::ex factored(const GiNaC::ex& c) {
    if (!GiNaC::is_a<GiNaC::add>(c) || c.nops() > 12) return c;
    try {
        if (polynomial(c)) return GiNaC::factor(c);
        const GiNaC::ex nd = GiNaC::numer_denom(GiNaC::normal(c));
        if (!polynomial(nd.op(0)) || !polynomial(nd.op(1))) return c;
        return GiNaC::factor(nd.op(0)) / GiNaC::factor(nd.op(1));
    } catch (const std::exception&) {
        return c;
    }
}

bool only_constants(const GiNaC::ex& f, const GiNaC::exset& constants) {
    if (GiNaC::is_a<GiNaC::numeric>(f)) return true;
    if (GiNaC::is_a<GiNaC::symbol>(f)) return constants.count(f) > 0;
    if (GiNaC::is_a<GiNaC::power>(f))
        return only_constants(f.op(0), constants) && GiNaC::is_a<GiNaC::numeric>(f.op(1));
    return false;
}

/// Denominators rewritten like the whole (1/(m₁ + m₂ sin² θ + m₂ cos² θ) → 1/(m₁ + m₂)) and their common
/// factors pulled out, before the terms are paired and collected, so that terms over one denominator meet.
struct TidyDenominators : GiNaC::map_function {
    const Hints& hints;
    std::size_t max_terms;
    TidyDenominators(const Hints& h, std::size_t m) : hints(h), max_terms(m) {}
    GiNaC::ex operator()(const GiNaC::ex& x) override {
        if (GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<GiNaC::add>(x.op(0)) &&
            GiNaC::is_a<GiNaC::numeric>(x.op(1)) && GiNaC::ex_to<GiNaC::numeric>(x.op(1)).is_negative())
            // Common factors out, so that l₁ (m₁ l₂ + m₂ l₂ s²) and m₁ l₁ l₂ + m₂ l₁ l₂ s² meet.
            return GiNaC::pow(GiNaC::collect_common_factors(readable(x.op(0).map(*this), hints, max_terms)),
                              x.op(1));
        return x.map(*this);
    }
};

}  // namespace

GiNaC::ex expand_sums(const GiNaC::ex& e) {
    ExpandSums f;
    return f(e).expand();
}

std::vector<GiNaC::ex> angle_sums(const GiNaC::ex& e) {
    std::vector<GiNaC::ex> out;
    for (const GiNaC::ex& a : trig_arguments(e)) {
        GiNaC::ex p, q;
        int s = 1;
        if (decompose(a, p, s, q)) out.push_back(a);
    }
    return out;
}

GiNaC::ex contract_sums(const GiNaC::ex& e, const std::vector<GiNaC::ex>& angles) {
    std::vector<GiNaC::ex> ts = terms_of(e.expand());
    for (const GiNaC::ex& u : angles) ts = contract_one(ts, u);
    return sum(ts);
}

GiNaC::ex pythagoras(const GiNaC::ex& e) {
    GiNaC::ex best = e.expand();
    for (bool better = true; better;) {
        better = false;
        for (const GiNaC::ex& x : trig_arguments(best)) {
            for (const GiNaC::ex& rule :
                 {GiNaC::ex(GiNaC::pow(GiNaC::cos(x), 2) == 1 - GiNaC::pow(GiNaC::sin(x), 2)),
                  GiNaC::ex(GiNaC::pow(GiNaC::sin(x), 2) == 1 - GiNaC::pow(GiNaC::cos(x), 2))}) {
                const GiNaC::ex candidate = best.subs(rule, GiNaC::subs_options::algebraic).expand();
                if (terms(candidate) < terms(best)) {
                    best = candidate;
                    better = true;
                }
            }
            if (better) break;  // the arguments may have changed
        }
    }
    return best;
}

GiNaC::ex collect_like_terms(const GiNaC::ex& e, const GiNaC::exset& constants) {
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> groups;  // (the part with variables, the summed coefficient)
    std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> where;
    for (const GiNaC::ex& t : terms_of(e.expand())) {
        GiNaC::ex coefficient = 1, rest = 1;
        if (GiNaC::is_a<GiNaC::mul>(t)) {
            for (const GiNaC::ex& f : t) (only_constants(f, constants) ? coefficient : rest) *= f;
        } else {
            (only_constants(t, constants) ? coefficient : rest) = t;
        }
        const auto [it, fresh] = where.emplace(rest, groups.size());
        if (fresh)
            groups.push_back({rest, coefficient});
        else
            groups[it->second].second += coefficient;
    }
    GiNaC::ex out = 0;
    // Quantities of parameters alone with denominators (2 g/l − √2 g/l, a normal frequency) stay as written.
    for (const auto& [rest, coefficient] : groups)
        out += (rest.is_equal(1) && !polynomial(coefficient) ? coefficient : factored(coefficient)) * rest;
    return out;
}

namespace {
GiNaC::ex rewritten(const GiNaC::ex& e, const Hints& hints, std::size_t max_terms);
}  // namespace

GiNaC::ex readable(const GiNaC::ex& e, const Hints& hints, std::size_t max_terms) {
    try {
        return rewritten(e, hints, max_terms);
    } catch (const std::exception&) {  // something GiNaC cannot expand or factor: as it is
        return e;
    }
}

namespace {

GiNaC::ex rewritten(const GiNaC::ex& e, const Hints& hints, std::size_t max_terms) {
    GiNaC::ex x = e.expand();
    if (terms(x) <= max_terms && !trig_arguments(x).empty()) {
        TidyDenominators tidy(hints, max_terms);
        x = tidy(x).expand();
    }
    GiNaC::ex best = x;
    if (terms(x) <= max_terms && !trig_arguments(x).empty()) {
        const GiNaC::ex p = pythagoras(x);
        GiNaC::ex z = expand_sums(x);
        if (terms(z) <= 4 * max_terms) {
            z = contract_sums(z, hints.angles);
            z = contract_sums(z, angle_sums(x));  // the angles e itself uses, where the author's are not them
            if (hints.other_angles) z = contract_others(z);
            z = pythagoras(z);
        }
        // The author's angles where they cost no terms; else the shorter.
        best = terms(z) <= terms(p) ? z : p;
    }
    return hints.collect ? collect_like_terms(best, hints.constants) : best;
}

}  // namespace

GiNaC::ex readable_ratio(const GiNaC::ex& num, const GiNaC::ex& den, const Hints& hints) {
    Hints h = hints;
    h.collect = false;
    const GiNaC::ex nd = GiNaC::numer_denom(GiNaC::normal(num / den));
    return GiNaC::normal(readable(nd.op(0), h) / readable(nd.op(1), h));
}

Hints model_hints(const Model& model) {
    Hints h;
    GiNaC::ex text = model.T.expr + model.V.expr;
    for (const Constraint& c : model.constraints) text += c.expr.expr;
    for (const Body& b : model.bodies)
        for (std::size_t k = 0; k < 3; ++k) text += b.centre[k] + b.angles[k];
    h.angles = angle_sums(text);
    for (const Parameter& p : model.parameters) h.constants.insert(p.symbol);
    return h;
}

}  // namespace eomgen::trig
