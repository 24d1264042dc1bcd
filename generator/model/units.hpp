/**
 * @file units.hpp  Units of the model file's values, read with UDUNITS-2 (Debian's libudunits2).
 *
 * A unit text ("deg", "N/m", "kg*m^2", "m/s^2", "rpm", "5 cm" for a value with its unit) is parsed by UDUNITS-2,
 * which knows the SI base and derived units, their prefixes and the common others (g, min, h, rpm, km/h, lbf),
 * with "deg" and "rev" added for the angles people write. Each unit has a factor to its coherent SI unit (deg:
 * π/180 rad) and a dimension (exponents of kg, m, s, A, K, mol, cd; the radian and steradian are dimensionless).
 * eomgen works in SI: a value given in another unit is converted when the model file is read. UDUNITS-2 is a
 * well-kept library with a units database maintained by Unidata; writing a parser and a table here would be
 * neither as complete nor as correct.
 */
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>

namespace eomgen {

/// Exponents of kg, m, s, A, K, mol, cd.
struct Dimension {
    std::array<int, 7> exponent{0, 0, 0, 0, 0, 0, 0};
    bool operator==(const Dimension& o) const { return exponent == o.exponent; }
    bool operator!=(const Dimension& o) const { return !(*this == o); }
    bool dimensionless() const { return *this == Dimension{}; }
    /// "kg m^2 s^-2", "1" for none.
    std::string str() const;
};

struct Unit {
    std::string text;       ///< as written
    double to_si = 1.0;     ///< a value in this unit times to_si is the value in the coherent SI unit
    Dimension dimension;
    int radians = 0;        ///< the power of rad in it (rpm: 1), for showing the SI unit
    /// The coherent SI unit it converts to, as shown: "rad", "m", "kg m^2", "rad/s"; "1" when dimensionless.
    std::string si() const;
    /// This unit per second, "(deg)/s": a coordinate's rate.
    Unit per_second() const {
        Unit u = *this;
        u.text = "(" + text + ")/s";
        u.dimension.exponent[2] -= 1;
        return u;
    }
};

/// A unit text that UDUNITS-2 does not read, with its reason.
struct UnitError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Parses a unit; throws UnitError for an unknown one or one with an offset (degC: write K).
Unit parse_unit(const std::string& text);

/// A value written with its unit at the end, "30 deg", "40 N/m", "9.81 m/s^2": the number part (what comes before
/// the last run of unit text, handed to `number`, which evaluates a constant expression such as "pi/6") and the
/// unit. Nothing when the text has no unit part UDUNITS-2 reads.
template <class Evaluate>
std::optional<std::pair<double, Unit>> split_value_with_unit(const std::string& text, Evaluate number) {
    // Try each space from the left: "2*pi rad/s" splits as "2*pi" and "rad/s".
    for (std::size_t cut = text.find(' '); cut != std::string::npos; cut = text.find(' ', cut + 1)) {
        const std::string left = text.substr(0, cut), right = text.substr(cut + 1);
        if (right.find_first_not_of(' ') == std::string::npos) continue;
        Unit u;
        try {
            u = parse_unit(right);
        } catch (const UnitError&) {
            continue;
        }
        try {
            return std::make_pair(number(left), u);
        } catch (...) {
            continue;
        }
    }
    return std::nullopt;
}

}  // namespace eomgen
