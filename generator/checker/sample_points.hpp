/** @file sample_points.hpp  The numbers the checker compares at: random points for every symbol of a model and of
 * a text (class Numbers), the exact rationals of a model's decimal defaults, integrals evaluated by tanh–sinh
 * quadrature. Private to generator/checker (checker_internals.hpp includes it). */
#pragma once

#include "checker/latex_parser.hpp"
#include "codegen/cpp_emitter.hpp"
#include "mechanics/pole_free_subs.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <cmath>
#include <complex>
#include <cstdlib>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen::checker::detail {

using Complex = std::complex<double>;
using ExSet = std::set<GiNaC::ex, GiNaC::ex_is_less>;
template <class V>
using ExMap = std::map<GiNaC::ex, V, GiNaC::ex_is_less>;

/// The exact rational a model's double default stands for ("0.3" is 3/10, not the binary float).
inline GiNaC::numeric exact_decimal(double v) {
    const std::string s = codegen::shortest_decimal(v);
    GiNaC::numeric mant(0);
    long exponent = 0;
    bool neg = false, point = false;
    std::size_t i = 0;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) neg = s[i++] == '-';
    for (; i < s.size(); ++i) {
        const char c = s[i];
        if (c >= '0' && c <= '9') {
            mant = mant * 10 + (c - '0');
            if (point) --exponent;
        } else if (c == '.') {
            point = true;
        } else if (c == 'e' || c == 'E') {
            exponent += std::strtol(s.c_str() + i + 1, nullptr, 10);
            break;
        }
    }
    GiNaC::numeric r = mant * GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(exponent));
    return neg ? -r : r;
}

inline bool has_integral(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::integral>(e)) return true;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (has_integral(e.op(i))) return true;
    return false;
}

inline std::optional<Complex> as_complex(const GiNaC::ex& v) {
    if (!GiNaC::is_a<GiNaC::numeric>(v)) return std::nullopt;
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(v);
    const Complex c(n.real().to_double(), n.imag().to_double());
    if (!std::isfinite(c.real()) || !std::isfinite(c.imag())) return std::nullopt;
    return c;
}

/**
 * ∫_a^b f(x) dx by tanh–sinh quadrature (Takahasi & Mori 1974), which copes with the integrable endpoint
 * singularities of derivations such as ∫ dψ/√(sin ψ). Nodes are placed by their distance from the nearer end
 * so that points next to a singular end are not rounded onto it.
 */
template <class F>
inline std::optional<Complex> tanh_sinh(F f, double a, double b) {
    const double half = (b - a) / 2, mid = (a + b) / 2;
    if (half == 0) return Complex(0);
    std::optional<Complex> previous;
    for (int level = 2; level <= 7; ++level) {
        const double h = std::ldexp(1.0, -level);
        Complex sum = 0;
        bool ok = true;
        for (double t = -4.0; t <= 4.0 + 1e-12; t += h) {
            const double u = M_PI / 2 * std::sinh(t);
            const double w = M_PI / 2 * std::cosh(t) / (std::cosh(u) * std::cosh(u));
            if (w < 1e-300) continue;
            const double dist = 2 / (std::exp(2 * std::abs(u)) + 1);  // 1 − tanh|u|, accurately
            const double x = t > 0 ? b - half * dist : (t < 0 ? a + half * dist : mid);
            if (x == a || x == b) continue;
            const std::optional<Complex> fx = f(x);
            if (!fx) {
                ok = false;
                break;
            }
            sum += w * *fx;
        }
        if (!ok) return std::nullopt;
        const Complex value = half * h * sum;
        if (previous && std::abs(value - *previous) <= 1e-11 * std::max(1.0, std::abs(value))) return value;
        previous = value;
    }
    return previous;
}

/// Numbers for the comparisons: random points for every symbol, values with integrals evaluated.
class Numbers {
  public:
    Numbers(const Model& model, const LatexContext& ctx) : model_(model), ctx_(ctx) {}

    /// Parameters (and free names) from `param_seed`, coordinates, velocities, accelerations and t from
    /// `state_seed`; each a rational in (0.5, 1.5).
    GiNaC::exmap point(unsigned param_seed, unsigned state_seed) const {
        GiNaC::exmap at;
        std::mt19937 pr(param_seed * 7919u + 17u), sr(state_seed * 104729u + 5u), flip(state_seed * 31u + 7u);
        std::uniform_int_distribution<int> pick(500, 1500);
        auto value = [&](std::mt19937& r) { return GiNaC::numeric(pick(r), 1000); };
        // Where abs, sign, max … of the state are compared, every other point gives the state values either sign:
        // at positive values alone θ'|θ'| and θ'² are one function.
        const bool signs = signed_state_ && state_seed % 2 == 0;
        auto state_value = [&] { return (signs && (flip() & 1u)) ? -value(sr) : value(sr); };
        for (const Parameter& p : model_.parameters) at[p.symbol] = value(pr);
        for (const auto& [name, f] : ctx_.free_names) at[f.symbol] = value(pr);
        at[model_.t] = value(sr);
        for (const Coordinate& c : model_.coordinates) {
            at[c.q] = state_value();
            at[c.qd] = state_value();
            at[c.qdd] = state_value();
        }
        for (const GiNaC::symbol& s : state_symbols_) at[s] = value(sr);
        // A pin may name other symbols (m_1 → m_2, m_2 → m): the point's values, to a fixed point.
        for (int round = 0; round < 3; ++round)
            for (const auto& [p, v] : pinned_)
                if (const auto x = subs_unless_pole(v, at)) at[p] = *x;
        return at;
    }
    /// A symbol that takes a value per state, as the coordinates do (a constraint's multiplier λ).
    void add_state_symbol(const GiNaC::symbol& s) { state_symbols_.push_back(s); }
    /// Whether the points give q, q', q'' either sign (at even state seeds): while a non-smooth function is compared.
    void sign_state(bool on) { signed_state_ = on; }
    /// Parameters and coordinates held at a value the text chose for its paragraph (`m_1 = 0`, `\\theta = \\pi/2`):
    /// every point uses it.
    void pin(const GiNaC::exmap& values) { pinned_ = values; }
    const GiNaC::exmap& pinned() const { return pinned_; }
    bool state_signed() const { return signed_state_; }
    GiNaC::exmap point(unsigned seed) const { return point(seed, seed); }

    std::optional<Complex> value(const GiNaC::ex& e, const GiNaC::exmap& at) {
        try {
            // A pinned value (θ = 0, m₁ = 0) can make a denominator exactly 0: GiNaC would throw from inside the
            // product it builds, and leak it.
            const std::optional<GiNaC::ex> at_point = subs_unless_pole(e, at);
            if (!at_point) return std::nullopt;
            GiNaC::ex v = *at_point;
            v = integrals(v);
            return as_complex(GiNaC::evalf(v));
        } catch (...) {
            return std::nullopt;
        }
    }

    /// Σ |term| over the terms of e expanded: the scale against which a difference is small.
    double scale(const GiNaC::ex& e, const GiNaC::exmap& at) {
        GiNaC::ex x = e;
        try {
            x = e.expand();
        } catch (...) {
        }
        double s = 0;
        if (GiNaC::is_a<GiNaC::add>(x)) {
            for (const GiNaC::ex& t : x)
                if (auto v = value(t, at)) s += std::abs(*v);
        } else if (auto v = value(x, at)) {
            s = std::abs(*v);
        }
        return s;
    }

  private:
    std::vector<GiNaC::symbol> state_symbols_;
    GiNaC::exmap pinned_;
    bool signed_state_ = false;
    GiNaC::ex integrals(const GiNaC::ex& e) {
        if (!has_integral(e)) return e;
        if (GiNaC::is_a<GiNaC::integral>(e)) {
            auto hit = cache_.find(e);
            if (hit != cache_.end()) return hit->second;
            const GiNaC::ex x = e.op(0);
            const GiNaC::ex lo = integrals(e.op(1)), hi = integrals(e.op(2)), f = integrals(e.op(3));
            const auto a = as_complex(GiNaC::evalf(lo)), b = as_complex(GiNaC::evalf(hi));
            if (!a || !b || a->imag() != 0 || b->imag() != 0) throw std::runtime_error("limits");
            auto integrand = [&](double xv) -> std::optional<Complex> {
                try {
                    return as_complex(GiNaC::evalf(f.subs(x == GiNaC::numeric(xv))));
                } catch (...) {
                    return std::nullopt;
                }
            };
            const auto v = tanh_sinh(integrand, a->real(), b->real());
            if (!v) throw std::runtime_error("integral");
            const GiNaC::ex r = GiNaC::numeric(v->real()) + GiNaC::I * GiNaC::numeric(v->imag());
            cache_[e] = r;
            return r;
        }
        struct Each : GiNaC::map_function {
            Numbers* self;
            explicit Each(Numbers* n) : self(n) {}
            GiNaC::ex operator()(const GiNaC::ex& x) override { return self->integrals(x); }
        } each(this);
        return e.map(each);
    }

    const Model& model_;
    const LatexContext& ctx_;
    ExMap<GiNaC::ex> cache_;
};

}  // namespace eomgen::checker::detail
