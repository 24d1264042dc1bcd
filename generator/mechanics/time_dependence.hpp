/**
 * @file time_dependence.hpp  Whether an expression depends on t explicitly, decided once for every command.
 *
 * `e.has(t)` is not the question: a kinetic energy written from Cartesian velocities of a point carried round
 * at a fixed rate holds cos(ωt) and sin(ωt) that cancel (sin² + cos² = 1), and a forcing term τ₀ cos(ωt)
 * vanishes when τ₀ = 0 is given. The answer is ∂e/∂t ≡ 0 (mechanics/lagrangian.hpp's is_zero: exactly, else
 * at random points), after substituting the parameter values a command fixes (`modes --set`).
 */
#pragma once

#include "model/model.hpp"

#include <ginac/ginac.h>

#include <optional>

namespace eomgen {

/// True when ∂e/∂t ≢ 0 once the parameters in `fixed` take their values.
bool depends_on_time(const GiNaC::ex& e, const Model& model, const GiNaC::exmap& fixed = {});

/// e without t where it does not depend on t (its value at t = 0, which is its value at every t); nothing when
/// it does. Where the independence holds only at the values in `fixed`, they are substituted too.
std::optional<GiNaC::ex> without_time(const GiNaC::ex& e, const Model& model, const GiNaC::exmap& fixed = {});

}  // namespace eomgen
