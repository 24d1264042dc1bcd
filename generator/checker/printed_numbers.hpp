/** @file printed_numbers.hpp  Numbers a derivation works out (`1.51\sqrt{w/g} = 0.45\mathrm{~sec}`): units
 * converted to SI, the formula evaluated with the parameters' values, and the result compared with the
 * printed number to its printed digits. */
#pragma once

#include "checker/checker.hpp"
#include "checker/derivation.hpp"
#include "checker/latex_parser.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace eomgen::checker {

/// The number a side prints (`0.45` of `0.45 \mathrm{sec}`, `1.3` of `1.3^{\circ}`): where it is in the side's
/// LaTeX, its value and its digits after the point.
struct PrintedNumber {
    std::size_t begin = 0, end = 0;  ///< byte range in the side's LaTeX
    double value = 0;                ///< as printed, without sign or unit
    int decimals = 0;                ///< digits after the point (0: an integer)
    int significant = 0;             ///< significant digits printed (an integer's trailing zeros not counted)
};

/**
 * The one number `latex` prints, outside units (`\mathrm{...}`, `\text{...}`) and exponents (`^{\circ}`,
 * `10^{-3}`): the only decimal with a point, else the only number. std::nullopt when there is none or it is
 * ambiguous (`\frac{1}{2}`, two decimals).
 */
std::optional<PrintedNumber> printed_number(const std::string& latex);

/**
 * The values of the model's parameters for the numbers a text works out: the model file's, replaced by
 * `--set NAME=VALUE`, replaced by what the text chooses itself (`\theta = \pi/2`) for the rest of the
 * paragraph where it does.
 */
class ParameterValues {
  public:
    /// @throws CheckError for a --set name that is not a parameter of the model (the message lists them)
    ParameterValues(const Model& model, const std::vector<std::pair<std::string, double>>& set);
    /// The text sets parameter `index` to `value` at file offset `at`, until offset `until` (its paragraph).
    void choose(std::size_t index, double value, std::size_t at, std::size_t until, int line);
    /// Parameter `index`'s value at file offset `at`, and where it comes from ("from the model", "from --set",
    /// "chosen by the text on line 566").
    std::pair<double, std::string> at(std::size_t index, std::size_t offset) const;

  private:
    struct Choice {
        std::size_t index, from, until;
        double value;
        int line;
    };
    const Model& model_;
    std::vector<double> values_;
    std::vector<bool> set_;
    std::vector<Choice> choices_;
};

/**
 * Judges a = b (file offset `at`, its sides' LaTeX `sources`) as a worked-out number, when it is one: a side
 * prints a number (printed_number), possibly with units, and the other evaluates to a number once units are
 * converted to SI (degrees to radians) and the parameters take `values` (it must use a parameter or units
 * must be involved; plain arithmetic is left to the other comparisons). Agrees "to the printed digits" when
 * eomgen's value, in the text's units, rounded to the printed number's significant digits is the printed
 * number; otherwise disagrees "differs by 1.7 %", corrected to eomgen's value in as many digits. A number with
 * units for a quantity of the state is not comparable, with that reason. A parameter set to a number alone
 * (`\theta = \pi/2`) is the text's choice: not comparable, and used for the rest of the paragraph. Returns
 * false (r untouched) when the link is not a number.
 */
bool check_number(const GiNaC::ex& a, const GiNaC::ex& b, const std::pair<std::string, std::string>& sources,
                  std::size_t at, const Model& model, const LatexContext& ctx, const Derivation& d,
                  ParameterValues& values, EquationCheck& r);

}  // namespace eomgen::checker
