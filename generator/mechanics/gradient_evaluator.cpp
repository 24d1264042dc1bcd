/** @file gradient_evaluator.cpp  Value and gradient of an expression by forward differentiation (gradient_evaluator.hpp). */
#include "mechanics/gradient_evaluator.hpp"

#include "model/nonsmooth.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace eomgen {

GradientEvaluator::GradientEvaluator(SymbolValues values, const SymbolValues& seeds) : values_(std::move(values)) {
    for (const auto& [s, index] : seeds) {
        seeds_[s] = static_cast<int>(index);
        size_ = std::max<Eigen::Index>(size_, static_cast<Eigen::Index>(index) + 1);
    }
    if (size_ > kMaxSeeds) throw std::length_error("more than 64 symbols to differentiate for at once");
    cache_.reserve(1 << 14);
}

std::optional<GradientEvaluator::Dual> GradientEvaluator::operator()(const GiNaC::ex& e) {
    std::optional<Dual> v = evaluate(e);
    if (!v || !std::isfinite(v->value) || !v->gradient.allFinite()) return std::nullopt;
    return v;
}

std::optional<GradientEvaluator::Dual> GradientEvaluator::evaluate(const GiNaC::ex& e) {
    const GiNaC::basic* node = &GiNaC::ex_to<GiNaC::basic>(e);
    if (const auto hit = cache_.find(node); hit != cache_.end()) return hit->second.second;
    Dual out;
    out.gradient = Gradient::Zero(size_);
    bool ok = true;
    auto constant = [&](double x) { out.value = x; };
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
        if (!n.is_real()) return std::nullopt;
        constant(n.to_double());
    } else if (GiNaC::is_a<GiNaC::symbol>(e)) {
        const auto it = values_.find(e);
        if (it == values_.end()) return std::nullopt;
        out.value = it->second;
        if (const auto s = seeds_.find(e); s != seeds_.end()) out.gradient(s->second) = 1;
    } else if (GiNaC::is_a<GiNaC::constant>(e)) {
        const GiNaC::ex x = GiNaC::evalf(e);
        if (!GiNaC::is_a<GiNaC::numeric>(x)) return std::nullopt;
        constant(GiNaC::ex_to<GiNaC::numeric>(x).to_double());
    } else if (GiNaC::is_a<GiNaC::add>(e)) {
        for (const GiNaC::ex& term : e) {
            const std::optional<Dual> v = evaluate(term);
            if (!v) return std::nullopt;
            out.value += v->value;
            out.gradient += v->gradient;
        }
    } else if (GiNaC::is_a<GiNaC::mul>(e)) {
        out.value = 1;
        for (const GiNaC::ex& factor : e) {
            const std::optional<Dual> v = evaluate(factor);
            if (!v) return std::nullopt;
            out.gradient = out.gradient * v->value + out.value * v->gradient;
            out.value *= v->value;
        }
    } else if (GiNaC::is_a<GiNaC::power>(e)) {
        const std::optional<Dual> b = evaluate(e.op(0));
        if (!b) return std::nullopt;
        const GiNaC::ex& x = e.op(1);
        if (GiNaC::is_a<GiNaC::numeric>(x) && GiNaC::ex_to<GiNaC::numeric>(x).is_real()) {
            const double p = GiNaC::ex_to<GiNaC::numeric>(x).to_double();
            out.value = std::pow(b->value, p);
            out.gradient = p * std::pow(b->value, p - 1) * b->gradient;
        } else {
            const std::optional<Dual> y = evaluate(x);
            if (!y || b->value <= 0) return std::nullopt;
            out.value = std::pow(b->value, y->value);
            out.gradient = out.value * (y->gradient * std::log(b->value) + y->value / b->value * b->gradient);
        }
    } else if (GiNaC::is_a<GiNaC::function>(e)) {
        std::optional<Dual> a[2];
        for (std::size_t i = 0; i < e.nops() && i < 2; ++i)
            if (!(a[i] = evaluate(e.op(i)))) return std::nullopt;
        ok = false;  // until a branch below knows the function
        if (e.nops() == 2 && GiNaC::is_the_function<GiNaC::atan2_SERIAL>(e)) {
            ok = true;
            const double y = a[0]->value, x = a[1]->value, r2 = x * x + y * y;
            out.value = std::atan2(y, x);
            out.gradient = (x * a[0]->gradient - y * a[1]->gradient) / r2;
        } else if (e.nops() == 1) {
            const double x = a[0]->value;
            const Gradient& dx = a[0]->gradient;
            double d = 0;
            ok = true;
            if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(e)) out.value = std::sin(x), d = std::cos(x);
            else if (GiNaC::is_the_function<GiNaC::cos_SERIAL>(e)) out.value = std::cos(x), d = -std::sin(x);
            else if (GiNaC::is_the_function<GiNaC::tan_SERIAL>(e)) out.value = std::tan(x), d = 1 + out.value * out.value;
            else if (GiNaC::is_the_function<GiNaC::exp_SERIAL>(e)) out.value = std::exp(x), d = out.value;
            else if (GiNaC::is_the_function<GiNaC::log_SERIAL>(e)) out.value = std::log(x), d = 1 / x;
            else if (GiNaC::is_the_function<GiNaC::asin_SERIAL>(e)) out.value = std::asin(x), d = 1 / std::sqrt(1 - x * x);
            else if (GiNaC::is_the_function<GiNaC::acos_SERIAL>(e)) out.value = std::acos(x), d = -1 / std::sqrt(1 - x * x);
            else if (GiNaC::is_the_function<GiNaC::atan_SERIAL>(e)) out.value = std::atan(x), d = 1 / (1 + x * x);
            else if (GiNaC::is_the_function<GiNaC::sinh_SERIAL>(e)) out.value = std::sinh(x), d = std::cosh(x);
            else if (GiNaC::is_the_function<GiNaC::cosh_SERIAL>(e)) out.value = std::cosh(x), d = std::sinh(x);
            else if (GiNaC::is_the_function<GiNaC::tanh_SERIAL>(e)) out.value = std::tanh(x), d = 1 - out.value * out.value;
            else ok = false;
            out.gradient = d * dx;
        }
        if (!ok && e.nops() <= 2) {
            if (is_nonsmooth_function(e)) {
                const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
                double args[2] = {a[0]->value, e.nops() > 1 ? a[1]->value : 0};
                if (!nonsmooth_value(name, args, e.nops(), out.value)) return std::nullopt;
                if (name == "abs") out.gradient = (a[0]->value < 0 ? -1.0 : 1.0) * a[0]->gradient;
                else if (name == "max") out.gradient = a[0]->value >= a[1]->value ? a[0]->gradient : a[1]->gradient;
                else if (name == "min") out.gradient = a[0]->value <= a[1]->value ? a[0]->gradient : a[1]->gradient;
                // sign and heaviside: locally constant
                ok = true;
            }
        }
    } else {
        ok = false;
    }
    if (!ok) return std::nullopt;
    cache_.emplace(node, std::make_pair(e, out));
    return out;
}

}  // namespace eomgen
