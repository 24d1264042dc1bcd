/** @file kinks.cpp  Where a derivative does not exist: e's sides on a switching surface (kinks.hpp). */
#include "checker/kinks.hpp"

#include "mechanics/pole_free_subs.hpp"
#include "model/nonsmooth.hpp"

#include <cmath>
#include <optional>
#include <set>

namespace eomgen::checker {
namespace {

/// The real value of e under m, or nothing (a pole, not a number).
std::optional<double> value(const GiNaC::ex& e, const GiNaC::exmap& m) {
    const std::optional<GiNaC::ex> v = subs_unless_pole(e, m);
    if (!v) return std::nullopt;
    const GiNaC::ex n = GiNaC::evalf(*v);
    if (!GiNaC::is_a<GiNaC::numeric>(n) || !GiNaC::ex_to<GiNaC::numeric>(n).is_real()) return std::nullopt;
    const double d = GiNaC::ex_to<GiNaC::numeric>(n).to_double();
    return std::isfinite(d) ? std::optional<double>(d) : std::nullopt;
}

/// Whether a and b differ at points of s = 0 (x from s, the other symbols at reproducible values in (0.5, 1.5)):
/// true where they differ at one of them, false where they agree at all that could be evaluated.
bool differ_on_surface(const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::ex& s, const GiNaC::symbol& x) {
    const GiNaC::ex expanded = s.expand();
    if (expanded.degree(x) != 1) return false;
    const GiNaC::ex c1 = expanded.coeff(x, 1), c0 = expanded.coeff(x, 0);
    std::set<GiNaC::ex, GiNaC::ex_is_less> symbols;
    for (const GiNaC::ex& e : {a, b, s})
        for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(x)) symbols.insert(*it);
    for (unsigned point = 0; point < 3; ++point) {
        GiNaC::exmap m;
        unsigned k = 0;
        for (const GiNaC::ex& sym : symbols) m[sym] = GiNaC::numeric(0.5 + std::fmod(0.618034 * (k++ + 1) * (point + 2), 1.0));
        const std::optional<double> slope = value(c1, m), offset = value(c0, m);
        if (!slope || !offset || *slope == 0) continue;
        m[x] = GiNaC::numeric(-*offset / *slope);
        const std::optional<double> va = value(a, m), vb = value(b, m);
        if (!va || !vb) continue;
        if (std::abs(*va - *vb) > 1e-9 * (1 + std::abs(*va) + std::abs(*vb))) return true;
    }
    return false;
}

}  // namespace

std::vector<Kink> surfaces_without_derivative(const GiNaC::ex& e, const GiNaC::symbol& x) {
    std::vector<Kink> out;
    if (!contains_nonsmooth(e)) return out;
    for (const SwitchingSurface& surface : switching_surfaces({e})) {
        if (!surface.s.has(x)) continue;
        const GiNaC::ex plus = one_sided(e, surface.s, 1), minus = one_sided(e, surface.s, -1);
        if (differ_on_surface(plus, minus, surface.s, x))
            out.push_back({surface.s, true});
        else if (differ_on_surface(plus.diff(x), minus.diff(x), surface.s, x))
            out.push_back({surface.s, false});
    }
    return out;
}

}  // namespace eomgen::checker
