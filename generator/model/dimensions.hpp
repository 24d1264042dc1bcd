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
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

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

/// An inconsistency inside an expression: a sum whose terms differ, the argument of a function that is not
/// dimensionless. The message names the part and both dimensions.
struct DimensionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The dimension of `e` from its symbols' (a symbol missing from `symbols` has none: nothing then); throws
/// DimensionError where e is inconsistent in itself. `print` writes a subexpression as the message shows it.
std::optional<Dims> dimension_of(const GiNaC::ex& e, const std::map<GiNaC::ex, Dims, GiNaC::ex_is_less>& symbols);

/// The top-level terms of an expression's text, with their byte offsets: "m/2*x'^2 - k*x" → ("m/2*x'^2", 0),
/// ("- k*x", 9). A '+' or '−' splits where parentheses are balanced and it follows an operand (not an exponent's
/// sign, "a^-2", "1e-3").
std::vector<std::pair<std::string, std::size_t>> top_level_terms(const std::string& text);

}  // namespace eomgen
