/** @file double_evaluator.cpp  A walk of the expression tree in doubles (double_evaluator.hpp). */
#include "mechanics/double_evaluator.hpp"

#include "model/nonsmooth.hpp"

#include <cmath>
#include <string>

namespace eomgen {

DoubleEvaluator DoubleEvaluator::at(const GiNaC::exmap& at) {
    SymbolValues values;
    for (const auto& [s, v] : at) {
        if (!GiNaC::is_a<GiNaC::symbol>(s)) continue;
        const GiNaC::ex x = GiNaC::evalf(v);
        if (GiNaC::is_a<GiNaC::numeric>(x) && GiNaC::ex_to<GiNaC::numeric>(x).is_real())
            values[s] = GiNaC::ex_to<GiNaC::numeric>(x).to_double();
    }
    return DoubleEvaluator(std::move(values));
}

std::optional<double> DoubleEvaluator::operator()(const GiNaC::ex& e) {
    const std::optional<double> v = evaluate(e);
    if (!v || !std::isfinite(*v)) return std::nullopt;
    return v;
}

std::optional<double> DoubleEvaluator::evaluate(const GiNaC::ex& e) {
    const GiNaC::basic* node = &GiNaC::ex_to<GiNaC::basic>(e);
    if (const auto hit = cache_.find(node); hit != cache_.end()) return hit->second.second;
    std::optional<double> out;
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
        if (n.is_real()) out = n.to_double();
    } else if (GiNaC::is_a<GiNaC::symbol>(e)) {
        const auto it = values_.find(e);
        if (it != values_.end()) out = it->second;
    } else if (GiNaC::is_a<GiNaC::constant>(e)) {
        const GiNaC::ex x = GiNaC::evalf(e);
        if (GiNaC::is_a<GiNaC::numeric>(x)) out = GiNaC::ex_to<GiNaC::numeric>(x).to_double();
    } else if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
        const bool sum = GiNaC::is_a<GiNaC::add>(e);
        double acc = sum ? 0.0 : 1.0;
        for (const GiNaC::ex& term : e) {
            const std::optional<double> v = evaluate(term);
            if (!v) return std::nullopt;
            acc = sum ? acc + *v : acc * *v;
        }
        out = acc;
    } else if (GiNaC::is_a<GiNaC::power>(e)) {
        const std::optional<double> b = evaluate(e.op(0)), x = evaluate(e.op(1));
        if (b && x) out = std::pow(*b, *x);
    } else if (is_nonsmooth_function(e)) {
        double args[2] = {0, 0}, value = 0;
        for (std::size_t i = 0; i < e.nops() && i < 2; ++i) {
            const std::optional<double> a = evaluate(e.op(i));
            if (!a) return std::nullopt;
            args[i] = *a;
        }
        if (nonsmooth_value(GiNaC::ex_to<GiNaC::function>(e).get_name(), args, e.nops(), value)) out = value;
    } else if (GiNaC::is_a<GiNaC::function>(e) && e.nops() == 1) {
        const std::optional<double> a = evaluate(e.op(0));
        if (!a) return std::nullopt;
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        const double x = *a;
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

}  // namespace eomgen
