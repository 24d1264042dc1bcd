/**
 * @file nonsmooth.hpp  The model language's non-smooth functions as GiNaC functions: abs, sign, heaviside, max, min
 * (clamp is min(max(x, lo), hi)), with their derivatives where they exist — d|x|/dx = sign x, d sign x/dx = 0 and
 * d heaviside x/dx = 0 away from x = 0, d max(a, b)/da = heaviside(a − b) — and the switching surfaces they bring
 * (their arguments, or a − b for max and min), where those derivatives do not exist.
 *
 * Every symbol of a model is real, which GiNaC's own abs does not know (its derivative holds conjugate(x)); these
 * are registered under the same printed names, so a name-based consumer (the code generator, the evaluators, the
 * dimension check) reads them alike.
 */
#pragma once

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace eomgen {

GiNaC::ex real_abs(const GiNaC::ex& x);
GiNaC::ex sign(const GiNaC::ex& x);
/// H(x): 0 for x < 0, 1/2 at 0, 1 for x > 0 (so that H = (1 + sign x)/2).
GiNaC::ex heaviside(const GiNaC::ex& x);
GiNaC::ex real_max(const GiNaC::ex& a, const GiNaC::ex& b);
GiNaC::ex real_min(const GiNaC::ex& a, const GiNaC::ex& b);

/// The value of the function named name (abs, sign, heaviside, max, min) at doubles, as the generated code computes
/// it; false for another name or arity.
bool nonsmooth_value(const std::string& name, const double* args, std::size_t n, double& out);

/// Whether e is one of the functions above.
bool is_nonsmooth_function(const GiNaC::ex& e);

/// Whether e holds one of them anywhere.
bool contains_nonsmooth(const GiNaC::ex& e);
/// Whether any of `exprs` does: a subexpression they share is looked at once.
bool contains_nonsmooth(const std::vector<GiNaC::ex>& exprs);

/// Roots of squares read for real numbers: sqrt(x^2) = |x|, (x^2)^(3/2) = |x|^3, sqrt(l^2 x^2) = |l| |x|, so that a
/// quadratic drag written −k θ' sqrt(θ'^2) has the derivative 2k|θ'|, defined at rest.
GiNaC::ex real_roots(const GiNaC::ex& e);

/// A switching surface: where s = 0 the function f (one of e's non-smooth functions) has a kink or a jump.
struct SwitchingSurface {
    GiNaC::ex s;         ///< the surface's function: the argument of abs, sign, heaviside; a − b for max(a, b)
    GiNaC::ex function;  ///< the function as written in e (the first met)
    std::vector<GiNaC::ex> functions;  ///< every distinct function of e on this surface, `function` first
};

/// The surface a non-smooth function brings: its argument, or a − b for max(a, b) and min(a, b).
GiNaC::ex surface_of(const GiNaC::ex& function);

/// The distinct switching surfaces of the expressions, in first-appearance order (an argument and its negative are
/// one surface).
std::vector<SwitchingSurface> switching_surfaces(const std::vector<GiNaC::ex>& exprs);

/// e on one side of the switching surface s = 0 (side > 0: where s > 0, else where s < 0): each of its non-smooth
/// functions whose surface is s (or −s) replaced by the smooth expression it equals there — sign s by ±1, |s| by
/// ±s, heaviside s by 1 or 0, max(a, b) by a or b — and the others kept. Its derivatives are e's one-sided ones.
GiNaC::ex one_sided(const GiNaC::ex& e, const GiNaC::ex& s, int side);

/// Whether e holds a non-smooth function whose switching surface depends on one of the symbols.
bool nonsmooth_in(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& symbols);

}  // namespace eomgen
