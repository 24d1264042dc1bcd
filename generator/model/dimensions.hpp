/**
 * @file dimensions.hpp  Dimensional analysis of a model file's expressions (issue 29).
 *
 * Each symbol whose entry declares a `unit` has its dimension (model/units.hpp); q̇ is q's per second, q̈ per
 * second squared, t is a time. An expression's dimension follows: a product adds exponents, a power multiplies
 * them by a number, sin, cos, exp, log and the others take and give dimensionless values, and the terms of a
 * sum must agree. A term with a symbol of no declared unit has no known dimension and is not judged: a model
 * without units is read as before.
 */
#pragma once

#include "model/units.hpp"

#include <ginac/ginac.h>

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen {

/// Exponents of kg, m, s, A, K, mol, cd (fractional where a root makes them so).
struct Dims {
    std::array<double, 7> e{0, 0, 0, 0, 0, 0, 0};
    static Dims of(const Dimension& d);
    bool operator==(const Dims& o) const;
    bool operator!=(const Dims& o) const { return !(*this == o); }
    Dims operator+(const Dims& o) const;
    Dims operator-(const Dims& o) const;
    Dims operator*(double k) const;
    bool dimensionless() const { return *this == Dims{}; }
    /// "kg m^2/s^2", "1".
    std::string str() const;
};

/// The energy, kg m² s⁻².
Dims energy_dims();

/// The SI unit a quantity of dimension d is shown in: J, N and W by name, else the base units ("kg m^2/s",
/// "m/s"); "" for a dimensionless one (a pure number).
std::string si_unit_text(const Dims& d);

struct Model;

/// Whether the model file declares a unit for any parameter or coordinate (else nothing is judged, and the
/// numbers it shows have no units).
bool has_declared_units(const Model& model);

/// The note a command gives once for a model without units: its dimensions are not checked.
inline constexpr const char* kNoUnitsNote =
    "note: no coordinate or parameter declares a unit, so the dimensions of T, V, the forces and the constraints are "
    "not checked (give each a `unit`: docs/model_files.md, Units)";

/// The dimensions of the model's symbols: t a time, each parameter and coordinate with a declared unit its own,
/// q̇ q's per second, q̈ per second squared. Symbols without a unit are absent (their terms are not judged).
std::map<GiNaC::ex, Dims, GiNaC::ex_is_less> symbol_dimensions(const Model& model);

/// An inconsistency inside an expression: a sum whose terms differ, the argument of a function that is not
/// dimensionless. The message names the part and both dimensions.
struct DimensionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The dimension of `e` from its symbols' (a symbol missing from `symbols` has none: nothing then); throws
/// DimensionError where e is inconsistent in itself. `print` writes a subexpression as the message shows it.
std::optional<Dims> dimension_of(const GiNaC::ex& e, const std::map<GiNaC::ex, Dims, GiNaC::ex_is_less>& symbols);

/// A term whose dimension is wrong: where it starts in the expression's text, and what is wrong.
struct TermProblem {
    std::size_t offset = 0;
    std::string message;
};

/// Dimensional analysis of an expression's text term by term: each top-level term is parsed alone (`parse`, which
/// may throw for a term that does not stand alone: it is then skipped) and must have `expected` (an energy for T
/// and V), or, without one, the dimension most of the terms have (a tie going to one that a coordinate or its
/// velocity has, `coordinate_dims`; x' - R psi' cos(phi) is in m/s), its inside consistent too. Terms with a symbol
/// of no declared unit are not judged. The first problem, with `what` ("V is an energy") leading its message.
std::optional<TermProblem> term_dimension_problem(
    const std::string& text, const std::function<GiNaC::ex(const std::string&)>& parse,
    const std::map<GiNaC::ex, Dims, GiNaC::ex_is_less>& symbols, const std::vector<Dims>& coordinate_dims,
    const std::optional<Dims>& expected, const std::string& what);

/// x as an exact number for an expression: a fraction of π with a denominator up to 10⁴ (deg: π/180, rpm: π/30),
/// or a decimal of up to 15 places (cm: 1/100, lbf: 4.4482216152605); nothing otherwise (√2). The factor of a unit
/// to SI, for an output recorded in that unit.
std::optional<GiNaC::ex> exact_factor(double x);

/// The top-level terms of an expression's text, with their byte offsets: "m/2*x'^2 - k*x" → ("m/2*x'^2", 0),
/// ("- k*x", 9). A '+' or '−' splits where parentheses are balanced and it follows an operand (not an exponent's
/// sign, "a^-2", "1e-3").
std::vector<std::pair<std::string, std::size_t>> top_level_terms(const std::string& text);

}  // namespace eomgen
