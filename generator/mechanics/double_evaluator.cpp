/** @file double_evaluator.cpp  A walk of the expression tree in doubles (double_evaluator.hpp). */
#include "mechanics/double_evaluator.hpp"

#include "model/nonsmooth.hpp"
#include "model/stored_terms.hpp"

#include <cmath>
#include <string>

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

template <class Real>
std::optional<Real> FloatEvaluator<Real>::evaluate(const GiNaC::ex& e) {
    const GiNaC::basic* node = &GiNaC::ex_to<GiNaC::basic>(e);
    if (const auto hit = cache_.find(node); hit != cache_.end()) return hit->second.second;
    std::optional<Real> out;
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
        if (n.is_real()) out = to_real<Real>(n);
    } else if (GiNaC::is_a<GiNaC::symbol>(e)) {
        const auto it = values_.find(e);
        if (it != values_.end()) out = it->second;
    } else if (GiNaC::is_a<GiNaC::constant>(e)) {
        const GiNaC::ex x = GiNaC::evalf(e);
        if (GiNaC::is_a<GiNaC::numeric>(x)) out = GiNaC::ex_to<GiNaC::numeric>(x).to_double();
    } else if (GiNaC::is_exactly_a<GiNaC::add>(e) || GiNaC::is_exactly_a<GiNaC::mul>(e)) {
        // The pairs (rest, coefficient) as GiNaC stores them: the rests are shared nodes, whose values the cache
        // keeps, where e.op(k) would build a new product c·rest for every term.
        const bool sum = GiNaC::is_exactly_a<GiNaC::add>(e);
        const std::optional<Real> constant = evaluate(StoredTerms::overall_coefficient(e));
        if (!constant) return std::nullopt;
        Real acc = *constant;
        for (const GiNaC::expair& pair : StoredTerms::pairs(e)) {
            const std::optional<Real> v = evaluate(pair.rest);
            if (!v) return std::nullopt;
            const GiNaC::numeric& c = GiNaC::ex_to<GiNaC::numeric>(pair.coeff);
            if (sum) acc += (c == 1 ? Real(1) : to_real<Real>(c)) * *v;
            else acc *= c == 1 ? *v : std::pow(*v, to_real<Real>(c));
        }
        out = acc;
    } else if (GiNaC::is_a<GiNaC::power>(e)) {
        const std::optional<Real> b = evaluate(e.op(0)), x = evaluate(e.op(1));
        if (b && x) out = std::pow(*b, *x);
    } else if (is_nonsmooth_function(e)) {
        double args[2] = {0, 0}, value = 0;
        for (std::size_t i = 0; i < e.nops() && i < 2; ++i) {
            const std::optional<Real> a = evaluate(e.op(i));
            if (!a) return std::nullopt;
            args[i] = static_cast<double>(*a);
        }
        if (nonsmooth_value(GiNaC::ex_to<GiNaC::function>(e).get_name(), args, e.nops(), value)) out = value;
    } else if (GiNaC::is_a<GiNaC::function>(e) && e.nops() == 1) {
        const std::optional<Real> a = evaluate(e.op(0));
        if (!a) return std::nullopt;
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        const Real x = *a;
        if (name == "sin") out = std::sin(x);
        else if (name == "cos") out = std::cos(x);
        else if (name == "tan") out = std::tan(x);
        else if (name == "exp") out = std::exp(x);
        else if (name == "log") out = std::log(x);
        else if (name == "asin") out = std::asin(x);
        else if (name == "acos") out = std::acos(x);
        else if (name == "atan") out = std::atan(x);
        else if (name == "sinh") out = std::sinh(x);
        else if (name == "cosh") out = std::cosh(x);
        else if (name == "tanh") out = std::tanh(x);
    }
    if (!out) return std::nullopt;
    cache_.emplace(node, std::make_pair(e, *out));
    return out;
}

template class FloatEvaluator<double>;
template class FloatEvaluator<long double>;

}  // namespace eomgen
