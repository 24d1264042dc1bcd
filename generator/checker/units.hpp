/** @file units.hpp  Units of measure as derivations print them (`\mathrm{~s}`, `\text{ cm}`, `\mathrm{rad/s}`,
 * `\mathrm{m}/\mathrm{s}^{2}`): which names are units, and their factors to SI. */
#pragma once

#include "model/units.hpp"

#include <optional>
#include <string_view>

namespace eomgen::checker {

/// A unit as a derivation prints it: its factor to SI and its dimension (UDUNITS-2's, model/units.hpp).
struct TextUnit {
    double factor = 1.0;
    Dimension dimension;
};

/**
 * The unit `unit` prints ("cm", "m/s^{2}", "\mathrm{~N~m}"'s argument) with its factor and dimension: the names
 * derivations print as units (m, cm, mm, km, s, sec, ms, min, hr, kg, g, N, mN, J, W, Hz, K, Pa, rad, deg, rev,
 * rpm, ft, seconds, degrees) with integer powers, products and one quotient, read by UDUNITS-2. The list keeps
 * letters that are names (`d` of a differential, `h`, `a`) from being read as units (a day, an hour, a year).
 * std::nullopt when `unit` is not one.
 */
std::optional<TextUnit> text_unit(std::string_view unit);

/**
 * The factor that turns a quantity in `unit` into SI (radians for angles): "cm" → 0.01, "min" → 60, "g" →
 * 0.001 (grams), "deg" → π/180, "rad" → 1, "N" → 1. A compound of them with `/` and integer powers
 * (`rad/s`, `m/s^2`, `m/s^{2}`, `kg m^2`) multiplies out. Spaces and `~` around it are ignored.
 * std::nullopt when `unit` is not one (an empty string, an unknown name, a malformed power).
 */
std::optional<double> unit_factor(std::string_view unit);

/// unit_factor(unit) has a value: `unit` is printed as a unit of measure.
bool is_unit(std::string_view unit);

/**
 * `\mathrm{~s}`, `\mathrm{rad/s}` and `\text{ s}`, `\text{m/s}`: `command` (with its backslash) with its raw
 * `argument` typesets a unit of measure. `\text{s}` (one word, no space before it) is not one: it may be a
 * name's subscript (`T_{\text{s}}`).
 */
bool is_unit_command(std::string_view command, std::string_view argument);

}  // namespace eomgen::checker
