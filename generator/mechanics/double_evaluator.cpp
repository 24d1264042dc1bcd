/** @file double_evaluator.cpp  A walk of the expression tree in doubles (double_evaluator.hpp). */
#include "mechanics/double_evaluator.hpp"

#include "model/nonsmooth.hpp"
#include "model/stored_terms.hpp"

#include <cmath>
#include <string>
#include <unordered_map>

namespace eomgen {

namespace {

/// A number of the tree as Real: a rational p/q from its integers where they are exact in a double (so that
/// long double keeps its extra digits), else through double.
template <class Real>
Real to_real(const GiNaC::numeric& n) {
    if (n.is_rational() && !n.is_integer()) {
        const GiNaC::numeric p = n.numer(), q = n.denom();
        const GiNaC::numeric limit = GiNaC::numeric(1L << 53);
        if (GiNaC::abs(p) < limit && q < limit) return Real(p.to_double()) / Real(q.to_double());
    }
    return Real(n.to_double());
}

}  // namespace

template <class Real>
FloatEvaluator<Real> FloatEvaluator<Real>::at(const GiNaC::exmap& at) {
    SymbolValues values;
    for (const auto& [s, v] : at) {
        if (!GiNaC::is_a<GiNaC::symbol>(s)) continue;
        const GiNaC::ex x = GiNaC::evalf(v);
        if (GiNaC::is_a<GiNaC::numeric>(x) && GiNaC::ex_to<GiNaC::numeric>(x).is_real())
            values[s] = GiNaC::ex_to<GiNaC::numeric>(x).to_double();
    }
    return FloatEvaluator(std::move(values));
}

template <class Real>
std::optional<Real> FloatEvaluator<Real>::operator()(const GiNaC::ex& e) {
    const std::optional<Real> v = evaluate(e);
    if (!v || !std::isfinite(*v)) return std::nullopt;
    return v;
}

namespace {

enum class Elementary { None, Sin, Cos, Tan, Exp, Log, Asin, Acos, Atan, Sinh, Cosh, Tanh };

/// Which elementary function a GiNaC function serial is, named once per serial (comparing names at every node
/// was a tenth of the evaluation).
Elementary elementary(const GiNaC::function& f) {
    static std::unordered_map<unsigned, Elementary> by_serial;
    const auto [it, fresh] = by_serial.emplace(f.get_serial(), Elementary::None);
    if (!fresh) return it->second;
    static const std::unordered_map<std::string, Elementary> by_name{
        {"sin", Elementary::Sin},   {"cos", Elementary::Cos},   {"tan", Elementary::Tan},   {"exp", Elementary::Exp},
        {"log", Elementary::Log},   {"asin", Elementary::Asin}, {"acos", Elementary::Acos}, {"atan", Elementary::Atan},
        {"sinh", Elementary::Sinh}, {"cosh", Elementary::Cosh}, {"tanh", Elementary::Tanh}};
    if (const auto known = by_name.find(f.get_name()); known != by_name.end() && f.nops() == 1) it->second = known->second;
    return it->second;
}

template <class Real>
std::optional<Real> apply(Elementary f, Real x) {
    switch (f) {
        case Elementary::Sin: return std::sin(x);
        case Elementary::Cos: return std::cos(x);
        case Elementary::Tan: return std::tan(x);
        case Elementary::Exp: return std::exp(x);
        case Elementary::Log: return std::log(x);
        case Elementary::Asin: return std::asin(x);
        case Elementary::Acos: return std::acos(x);
        case Elementary::Atan: return std::atan(x);
        case Elementary::Sinh: return std::sinh(x);
        case Elementary::Cosh: return std::cosh(x);
        case Elementary::Tanh: return std::tanh(x);
        case Elementary::None: break;
    }
    return std::nullopt;
}

}  // namespace

template <class Real>
std::optional<Real> FloatEvaluator<Real>::evaluate(const GiNaC::ex& e) {
    const GiNaC::basic* node = &GiNaC::ex_to<GiNaC::basic>(e);
    if (const auto hit = cache_.find(node); hit != cache_.end()) return hit->second.second;
    std::optional<Real> out;
    // The exact types first, the commonest first: is_a<> is a dynamic_cast, which compares type names.
    if (GiNaC::is_exactly_a<GiNaC::add>(e) || GiNaC::is_exactly_a<GiNaC::mul>(e)) {
        // The pairs (rest, coefficient) as GiNaC stores them: the rests are shared nodes, whose values the cache
        // keeps, where e.op(k) would build a new product c·rest for every term. Coefficients are cached numbers too.
        static const GiNaC::ex one(1);  // GiNaC's shared 1: is_equal() is a pointer comparison
        const bool sum = GiNaC::is_exactly_a<GiNaC::add>(e);
        const std::optional<Real> constant = evaluate(StoredTerms::overall_coefficient(e));
        if (!constant) return std::nullopt;
        Real acc = *constant;
        for (const GiNaC::expair& pair : StoredTerms::pairs(e)) {
            const std::optional<Real> v = evaluate(pair.rest);
            if (!v) return std::nullopt;
            if (pair.coeff.is_equal(one)) {
                acc = sum ? acc + *v : acc * *v;
                continue;
            }
            const std::optional<Real> c = evaluate(pair.coeff);
            if (!c) return std::nullopt;
            if (sum) acc += *c * *v;
            else acc *= *c == 2 ? *v * *v : std::pow(*v, *c);
        }
        out = acc;
    } else if (GiNaC::is_exactly_a<GiNaC::power>(e)) {
        const std::optional<Real> b = evaluate(e.op(0)), x = evaluate(e.op(1));
        if (b && x) out = *x == 2 ? *b * *b : std::pow(*b, *x);
    } else if (GiNaC::is_exactly_a<GiNaC::function>(e)) {
        if (is_nonsmooth_function(e)) {
            double args[2] = {0, 0}, value = 0;
            for (std::size_t i = 0; i < e.nops() && i < 2; ++i) {
                const std::optional<Real> a = evaluate(e.op(i));
                if (!a) return std::nullopt;
                args[i] = static_cast<double>(*a);
            }
            if (nonsmooth_value(GiNaC::ex_to<GiNaC::function>(e).get_name(), args, e.nops(), value)) out = value;
        } else if (const Elementary f = elementary(GiNaC::ex_to<GiNaC::function>(e)); f != Elementary::None) {
            const std::optional<Real> a = evaluate(e.op(0));
            if (!a) return std::nullopt;
            out = apply(f, *a);
        }
    } else if (GiNaC::is_exactly_a<GiNaC::numeric>(e)) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
        if (n.is_real()) out = to_real<Real>(n);
    } else if (GiNaC::is_a<GiNaC::symbol>(e)) {
        const auto it = values_.find(e);
        if (it != values_.end()) out = it->second;
    } else if (GiNaC::is_a<GiNaC::constant>(e)) {
        const GiNaC::ex x = GiNaC::evalf(e);
        if (GiNaC::is_a<GiNaC::numeric>(x)) out = GiNaC::ex_to<GiNaC::numeric>(x).to_double();
    }
    if (!out) return std::nullopt;
    cache_.emplace(node, std::make_pair(e, *out));
    return out;
}

template class FloatEvaluator<double>;
template class FloatEvaluator<long double>;

}  // namespace eomgen
