/** @file checker.hpp  Compares each equation of a derivation text with what eomgen derived for the model. */
#pragma once

#include "checker/derivation.hpp"
#include "checker/verdict.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace eomgen::checker {

/// One entry of the per-derivation symbol map: a LaTeX name stands for a LaTeX expression of the model.
struct MapEntry {
    std::string name;    ///< e.g. "I_{0}"
    std::string value;   ///< e.g. "M a^{2}/2"
    std::string origin;  ///< where it was given, for messages: "--map", "pendulum.map.toml:4"
    int first_line = 0;  ///< with last_line: only for the text's rows on these lines (0: everywhere)
    int last_line = 0;
};

struct CheckOptions {
    std::vector<std::string>
        sections;               ///< --section patterns (case-insensitive substrings of headings); empty: all
    std::vector<MapEntry> map;  ///< applied in order; later entries may use earlier ones
    /// --set NAME=VALUE: parameter values for the numbers the text works out (printed_numbers.hpp)
    std::vector<std::pair<std::string, double>> set;
};

/// A map entry or a --section that cannot be used; the message says which and why.
class CheckError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

struct CheckReport {
    std::string model_path;
    std::string model_title;
    std::string derivation_path;
    std::vector<std::string> sections;  ///< titles of the sections checked (empty: the whole file)
    std::vector<MapEntry> map;
    std::vector<EquationCheck> equations;
    /// Delimiters of the checked sections that do not pair up (Derivation::problems), with their places.
    struct Problem {
        SourcePos where;
        std::string message;
    };
    std::vector<Problem> problems;

    int count(Verdict v) const;
};

/**
 * Checks every equation in the selected sections of `derivation` against the model.
 *
 * Each link a = b of each chain (display rows, and inline math containing a relation) is compared as follows,
 * symbolically first and at random points when simplification is inconclusive (GiNaC has no trigonometric
 * simplifier): the labels T, V, L, E (= T + V), H, p_q and ∂L/∂q, d/dt written with them stand for eomgen's
 * values; T_{x} and V_{x} are parts of T and V, taken from where the text defines them; a link that is an
 * identity agrees; one with accelerations agrees when it is a combination of the Euler–Lagrange equations
 * (equal up to a non-zero factor, terms moved across `=`); one without agrees when it is proportional to
 * h − h(0) or p − p(0) for a conserved momentum (also after squaring a square root). Otherwise it disagrees
 * when it can be matched with what it tries to be (a label, an Euler–Lagrange equation, the energy integral,
 * the neighbouring side of a chain), else it is not comparable.
 *
 * @throws CheckError for a map entry that does not parse, a --section that matches no heading, or a --set name
 *         that is not a parameter
 */
CheckReport check_derivation(const Model& model, const Equations& eq, const Derivation& derivation,
                             const CheckOptions& options);

}  // namespace eomgen::checker
