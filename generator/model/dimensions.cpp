/** @file dimensions.cpp  The dimension of a GiNaC expression from its symbols' (dimensions.hpp). */
#include "model/dimensions.hpp"

#include "model/model.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace eomgen {
namespace {

constexpr const char* kBase[7] = {"kg", "m", "s", "A", "K", "mol", "cd"};

std::string shown(const GiNaC::ex& e) {
    std::ostringstream os;
    os << e;
    std::string s = os.str();
    // The velocity symbols print as x_dot: the model file writes x'.
    for (std::size_t at = s.find("_dot"); at != std::string::npos; at = s.find("_dot", at)) s.replace(at, 4, "'");
    return s.size() > 120 ? s.substr(0, 117) + "..." : s;
}

std::string power_text(double x) {
    if (std::abs(x - std::round(x)) < 1e-9) return std::to_string(long(std::lround(x)));
    std::ostringstream os;
    os << x;
    return os.str();
}

}  // namespace

Dims Dims::of(const Dimension& d) {
    Dims out;
    for (std::size_t i = 0; i < 7; ++i) out.e[i] = d.exponent[i];
    return out;
}

bool Dims::operator==(const Dims& o) const {
    for (std::size_t i = 0; i < 7; ++i)
        if (std::abs(e[i] - o.e[i]) > 1e-9) return false;
    return true;
}

Dims Dims::operator+(const Dims& o) const {
    Dims out;
    for (std::size_t i = 0; i < 7; ++i) out.e[i] = e[i] + o.e[i];
    return out;
}

Dims Dims::operator-(const Dims& o) const { return *this + o * -1.0; }

Dims Dims::operator*(double k) const {
    Dims out;
    for (std::size_t i = 0; i < 7; ++i) out.e[i] = e[i] * k;
    return out;
}

std::string Dims::str() const {
    std::string num, den;
    for (std::size_t i = 0; i < 7; ++i) {
        const double x = e[i];
        if (std::abs(x) < 1e-9) continue;
        std::string& side = x > 0 ? num : den;
        side += (side.empty() ? "" : " ") + std::string(kBase[i]) +
                (std::abs(std::abs(x) - 1) < 1e-9 ? "" : "^" + power_text(std::abs(x)));
    }
    if (num.empty() && den.empty()) return "1 (dimensionless)";
    if (den.empty()) return num;
    return (num.empty() ? "1" : num) + "/" + (den.find(' ') == std::string::npos ? den : "(" + den + ")");
}

Dims energy_dims() {
    Dims d;
    d.e = {1, 2, -2, 0, 0, 0, 0};
    return d;
}

std::string si_unit_text(const Dims& d) {
    if (d.dimensionless()) return "";
    if (d == energy_dims()) return "J";
    if (d == Dims{{1, 1, -2, 0, 0, 0, 0}}) return "N";
    if (d == Dims{{1, 2, -3, 0, 0, 0, 0}}) return "W";
    return d.str();
}

bool has_declared_units(const Model& model) {
    return std::any_of(model.parameters.begin(), model.parameters.end(),
                       [](const Parameter& p) { return p.declared_unit || p.value_unit; }) ||
           std::any_of(model.coordinates.begin(), model.coordinates.end(),
                       [](const Coordinate& c) { return c.declared_unit.has_value(); });
}

std::map<GiNaC::ex, Dims, GiNaC::ex_is_less> symbol_dimensions(const Model& model) {
    std::map<GiNaC::ex, Dims, GiNaC::ex_is_less> dims;
    const Dims second{{0, 0, 1, 0, 0, 0, 0}};
    dims[model.t] = second;
    for (const Parameter& p : model.parameters) {
        if (p.declared_unit) dims[p.symbol] = Dims::of(p.declared_unit->dimension);
        else if (p.value_unit) dims[p.symbol] = Dims::of(p.value_unit->dimension);
    }
    for (const Coordinate& c : model.coordinates)
        if (c.declared_unit) {
            const Dims q = Dims::of(c.declared_unit->dimension);
            dims[c.q] = q;
            dims[c.qd] = q - second;
            dims[c.qdd] = q - second - second;
        }
    return dims;
}

std::optional<Dims> dimension_of(const GiNaC::ex& e, const std::map<GiNaC::ex, Dims, GiNaC::ex_is_less>& symbols) {
    if (e.is_zero()) return std::nullopt;  // 0 has every dimension: "V = 0", a term that cancels
    if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e)) return Dims{};
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        const auto it = symbols.find(e);
        if (it == symbols.end()) return std::nullopt;
        return it->second;
    }
    if (GiNaC::is_a<GiNaC::add>(e)) {
        std::optional<Dims> first;
        GiNaC::ex first_term;
        bool all_known = true;
        for (const GiNaC::ex& term : e) {
            const std::optional<Dims> d = dimension_of(term, symbols);  // once per term: sums nest deeply
            if (!d) {
                all_known = false;  // unknown: not judged, the others still are
                continue;
            }
            if (!first) {
                first = d;
                first_term = term;
            } else if (*d != *first) {
                throw DimensionError("the terms of " + shown(e) + " differ: " + shown(first_term) + " is " +
                                     first->str() + ", " + shown(term) + " is " + d->str());
            }
        }
        // A sum with a term of unknown dimension has the known terms' dimension only if all are known.
        if (!first || !all_known) return std::nullopt;
        return first;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        Dims total;
        bool known = true;
        for (const GiNaC::ex& factor : e) {
            const std::optional<Dims> d = dimension_of(factor, symbols);
            if (!d) known = false;
            else total = total + *d;
        }
        if (!known) return std::nullopt;
        return total;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
        const std::optional<Dims> base = dimension_of(e.op(0), symbols);
        const std::optional<Dims> exponent = dimension_of(e.op(1), symbols);
        if (exponent && !exponent->dimensionless())
            throw DimensionError("the exponent of " + shown(e) + " is " + exponent->str() + ", not a number");
        if (!base) return std::nullopt;
        if (base->dimensionless()) return Dims{};
        if (!GiNaC::is_a<GiNaC::numeric>(e.op(1)) || !GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_real()) {
            throw DimensionError(shown(e) + " raises " + base->str() + " to a power that is not a number");
        }
        return *base * GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_double();
    }
    if (GiNaC::is_a<GiNaC::function>(e)) {
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        if (name == "abs" && e.nops() == 1) return dimension_of(e.op(0), symbols);
        if ((name == "sign" || name == "heaviside") && e.nops() == 1) {
            dimension_of(e.op(0), symbols);  // any dimension; a mismatch inside is still an error
            return Dims{};
        }
        if ((name == "max" || name == "min") && e.nops() == 2) {
            // A bare number (max(x, 0)) takes the other argument's dimension, as numbers alone are read in SI.
            if (GiNaC::is_a<GiNaC::numeric>(e.op(1))) return dimension_of(e.op(0), symbols);
            if (GiNaC::is_a<GiNaC::numeric>(e.op(0))) return dimension_of(e.op(1), symbols);
            const std::optional<Dims> a = dimension_of(e.op(0), symbols), b = dimension_of(e.op(1), symbols);
            if (a && b && *a != *b)
                throw DimensionError("the arguments of " + shown(e) + " differ: " + a->str() + " and " + b->str());
            return a ? a : b;
        }
        if (name == "atan2" && e.nops() == 2) {
            const std::optional<Dims> y = dimension_of(e.op(0), symbols), x = dimension_of(e.op(1), symbols);
            if (y && x && *y != *x)
                throw DimensionError("the arguments of " + shown(e) + " differ: " + y->str() + " and " + x->str());
            return Dims{};
        }
        for (const GiNaC::ex& argument : e) {
            const std::optional<Dims> d = dimension_of(argument, symbols);
            if (d && !d->dimensionless())
                throw DimensionError("the argument of " + name + " in " + shown(e) + " is " + d->str() +
                                     ", not a number");
        }
        return Dims{};
    }
    return std::nullopt;
}

std::vector<std::pair<std::string, std::size_t>> top_level_terms(const std::string& text) {
    std::vector<std::pair<std::string, std::size_t>> out;
    int depth = 0;
    std::size_t start = 0;
    char previous = 0;  // the last character that is not a space
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '(') ++depth;
        if (c == ')') --depth;
        if ((c == '+' || c == '-') && depth == 0 && previous != 0) {
            const bool operand_end = std::isalnum(static_cast<unsigned char>(previous)) || previous == ')' ||
                                     previous == '\'' || previous == '.' || previous == '_';
            // "1e-3": an exponent's sign, after a digit and an e.
            const bool exponent = (previous == 'e' || previous == 'E') && i >= 2 &&
                                  std::isdigit(static_cast<unsigned char>(text[i - 2]));
            if (operand_end && !exponent) {
                out.emplace_back(text.substr(start, i - start), start);
                start = i;
            }
        }
        if (c != ' ' && c != '\n' && c != '\t' && c != '\r') previous = c;
    }
    out.emplace_back(text.substr(start), start);
    return out;
}

std::optional<TermProblem> term_dimension_problem(
    const std::string& text, const std::function<GiNaC::ex(const std::string&)>& parse,
    const std::map<GiNaC::ex, Dims, GiNaC::ex_is_less>& symbols, const std::vector<Dims>& coordinate_dims,
    const std::optional<Dims>& expected, const std::string& what) {
    struct Term {
        std::string text;
        std::size_t offset;
        Dims dims;
    };
    std::vector<Term> terms;
    for (const auto& [term_text, offset] : top_level_terms(text)) {
        const std::size_t lead = term_text.find_first_not_of(" \t\r\n+");
        if (lead == std::string::npos) continue;
        std::optional<Dims> d;
        try {
            d = dimension_of(parse(term_text), symbols);
        } catch (const DimensionError& e) {
            return TermProblem{offset + lead, what + ": " + e.what()};
        } catch (const std::exception&) {
            continue;  // a term that does not stand alone; the whole expression was parsed already
        }
        if (!d) continue;
        std::string term = term_text.substr(lead);
        while (!term.empty() && std::isspace(static_cast<unsigned char>(term.back()))) term.pop_back();
        terms.push_back({term, offset + lead, *d});
    }
    if (terms.empty()) return std::nullopt;
    Dims want;
    if (expected) {
        want = *expected;
    } else {
        int best = -1;
        for (const Term& t : terms) {
            int count = 0;
            for (const Term& u : terms) count += u.dims == t.dims ? 2 : 0;
            if (std::find(coordinate_dims.begin(), coordinate_dims.end(), t.dims) != coordinate_dims.end()) ++count;
            if (count > best) {
                best = count;
                want = t.dims;
            }
        }
    }
    const auto reference = std::find_if(terms.begin(), terms.end(), [&](const Term& t) { return t.dims == want; });
    for (const Term& t : terms) {
        if (t.dims == want) continue;
        const Dims extra = t.dims - want;
        bool more = false, fewer = false;
        for (double x : extra.e) {
            more = more || x > 1e-9;
            fewer = fewer || x < -1e-9;
        }
        const std::string off = more && !fewer ? "a factor " + extra.str() + " too many"
                                : fewer && !more ? "a factor " + (extra * -1.0).str() + " missing"
                                                 : "off by a factor " + extra.str();
        return TermProblem{t.offset, what + ": the term " + t.text + " is " + t.dims.str() + ", but " +
                                         (expected ? std::string("it must be ") + want.str()
                                                   : "the term " + reference->text + " is " + want.str()) +
                                         " (" + off + ")"};
    }
    return std::nullopt;
}

std::optional<GiNaC::ex> exact_factor(double x) {
    if (!std::isfinite(x) || x == 0) return std::nullopt;
    // A fraction of π with a small denominator (deg: π/180, rpm: π/30), from the continued fraction of x/π.
    {
        const double y = x / M_PI;
        long p0 = 0, q0 = 1, p1 = 1, q1 = 0;
        double r = y;
        for (int k = 0; k < 30; ++k) {
            const double a = std::floor(r);
            if (std::abs(a) > 1e9) break;
            const long p2 = long(a) * p1 + p0, q2 = long(a) * q1 + q0;
            if (q2 > 10000) break;
            p0 = p1, q0 = q1, p1 = p2, q1 = q2;
            if (std::abs(double(p1) / double(q1) - y) <= 1e-14 * std::abs(y)) return GiNaC::numeric(p1, q1) * GiNaC::Pi;
            if (r - a == 0) break;
            r = 1 / (r - a);
        }
    }
    // A short decimal (cm: 1/100, mile: 1609.344, lbf: 4.4482216152605), as the definitions give them: the shortest
    // decimal that reads back as x, if it has at most 15 significant digits (√2 needs 17).
    for (int digits = 1; digits <= 15; ++digits) {
        char text[64];
        std::snprintf(text, sizeof text, "%.*e", digits - 1, x);
        if (std::strtod(text, nullptr) != x) continue;
        const std::string s(text);
        const std::size_t e = s.find('e');
        std::string mantissa = s.substr(0, e);
        const int exponent = std::atoi(s.c_str() + e + 1);
        const bool negative = mantissa[0] == '-';
        if (negative) mantissa.erase(0, 1);
        mantissa.erase(std::remove(mantissa.begin(), mantissa.end(), '.'), mantissa.end());
        // value = mantissa × 10^(exponent − (digits − 1))
        const int power = exponent - (digits - 1);
        GiNaC::numeric value(mantissa.c_str());
        if (negative) value = -value;
        return power >= 0 ? GiNaC::ex(value * GiNaC::pow(GiNaC::numeric(10), power))
                          : GiNaC::ex(value / GiNaC::pow(GiNaC::numeric(10), -power));
    }
    return std::nullopt;
}

}  // namespace eomgen
