/** @file characteristic_equation.hpp  An exponential trial solution (`\varphi = e^{\lambda t}`, `x = C
 * e^{st}`) and what the text derives from it: the characteristic equation of the model's equations linearized
 * about rest, det(λ² M₀ + λ C₀ + K₀) = 0 (damping included, where (K₀ − ω² M₀) A = 0 of
 * amplitude_equations.hpp has none), and its roots (`\lambda = -\gamma \pm \sqrt{\gamma^2 - \omega_0^2}`). */
#pragma once

#include "checker/checker.hpp"
#include "checker/comparisons.hpp"
#include "checker/latex_parser.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace eomgen::checker {

/// A coordinate set to (a free name times) e^{λ t}: the exponent's name λ, from the link on to its section's
/// end.
struct ExponentialTrial {
    GiNaC::ex exponent;     ///< λ, a free name of the text
    std::size_t from = 0;   ///< file offset of its relation
    std::size_t until = 0;  ///< the end of its section
    int line = 0;
};

/**
 * The exponential trial `left = right` sets up, when it is one: one side a coordinate of the model, the other
 * e^{λ t} or A e^{λ t}, λ and A free names of the text (the exponent exactly a name times t: `e^{i\omega t}`
 * is an oscillation, amplitude_equations.hpp). std::nullopt otherwise.
 */
std::optional<ExponentialTrial> exponential_trial(const GiNaC::ex& left, const GiNaC::ex& right,
                                                  const Model& model, LatexContext& ctx);

/**
 * det(λ² M₀ + λ C₀ + K₀) in `lambda`, M₀, C₀, K₀ the derivatives of the Euler–Lagrange residuals `motion` by
 * q̈, q̇, q at rest (q = q̇ = q̈ = 0); std::nullopt where rest is no equilibrium or the equations hold t.
 */
std::optional<GiNaC::ex> characteristic_polynomial(const std::vector<GiNaC::ex>& motion, const Model& model,
                                                   const GiNaC::ex& lambda);

/**
 * Judges `a = b` (the text's sides, its definitions put in) against the characteristic polynomial `p` of the
 * trial's exponent: an equation in λ alone agrees when it is p = 0 times a factor free of λ; `λ = value`
 * agrees when the value is a root. False when the link is neither (it holds other unknowns, or the state).
 */
bool check_characteristic(const GiNaC::ex& a, const GiNaC::ex& b, const ExponentialTrial& trial,
                          const GiNaC::ex& p, Comparisons& cmp, EquationCheck& r);

}  // namespace eomgen::checker
