/** @file approximation.hpp  Approximations a derivation makes (`\approx`, `\simeq`, "for small θ"): compared
 * with the Taylor expansion of the model's equation about the point, to the order the text keeps. */
#pragma once

#include "checker/checker.hpp"
#include "checker/comparisons.hpp"
#include "checker/derivation.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace eomgen::checker {

/**
 * The coordinates the prose around file offset `at` calls small ("for small θ", "small \theta", "θ ≪ 1",
 * "small oscillations", "small angles": then every coordinate), by their name, LaTeX or Unicode letter, in the
 * paragraph of `at` (to the blank line before it and after it). Indices into model.coordinates.
 */
std::vector<std::size_t> small_coordinates_in_prose(const Derivation& d, std::size_t at, const Model& model);

/**
 * Where the text, before file offset `at`, says the motion is small ("makes small oscillations", "small
 * angles", "small amplitude", "small vibrations", "small displacements"), as a file offset; std::nullopt when it
 * does not. An equation after it that would disagree is compared as the approximation it may be.
 */
std::optional<std::size_t> small_motion_stated_before(const Derivation& d, std::size_t at);

/// "first", "second", "third", or "4th" ...
std::string ordinal(int order);

/// What an approximation is compared with, and how it came out.
struct ApproxVerdict {
    bool applies = false;  ///< a side is a polynomial in the small coordinates (the text's truncation)
    bool agrees = false;
    int order = 0;         ///< the order the text keeps (the degree of its polynomial side)
    int wrong_order = 0;   ///< disagrees: the lowest order at which it differs
    int equation = -1;     ///< the Euler–Lagrange equation it was compared with, or -1
    bool solved = false;   ///< compared with that coordinate's acceleration solved from the equations instead
    GiNaC::ex text;        ///< a − b to `order` (ε = 1)
    GiNaC::ex reference;   ///< what it should be to `order`: c·EL_i, or the reference side's expansion
};

/**
 * Compares a ≈ b about q = 0 for the coordinates `small` (each q, q̇, q̈ of the same small order ε): the
 * order k is the highest degree in ε of a side that is a polynomial in them; a − b must vanish to order k, or
 * (with accelerations) equal c·EL_i (c constant) to order k, c from the acceleration coefficients at q = 0, or —
 * with one acceleration alone, the others eliminated — c·(q̈_i − (M⁻¹f)_i), q̈_i solved from the equations.
 * `reference_side` (0: a, 1: b, −1: none) is the side that holds eomgen's value (a label), for an
 * approximation without accelerations that disagrees. `same(x, y)` decides equality (numerically).
 */
ApproxVerdict compare_approximation(const GiNaC::ex& a, const GiNaC::ex& b, int reference_side, const Model& model,
                                    const std::vector<GiNaC::ex>& motion, const std::vector<std::size_t>& small,
                                    const std::function<bool(const GiNaC::ex&, const GiNaC::ex&)>& same);

/**
 * The verdict on a ≈ b (a link at file offset `at`, its sides' LaTeX `sources`): the small coordinates are
 * those the prose names (small_coordinates_in_prose), or, when `implied`, every coordinate a − b holds. Agrees
 * "to first order in $\theta$", or disagrees "at first order" with the expanded reference as the correction
 * (written with `\approx`). False when it does not apply (no side polynomial in the small coordinates, or
 * nothing to compare a disagreement with).
 */
bool check_approximation(const Derivation& d, const Model& model, const std::vector<GiNaC::ex>& motion, std::size_t at,
                         const std::pair<std::string, std::string>& sources, const GiNaC::ex& a, const GiNaC::ex& b,
                         int reference_side, bool implied, Comparisons& cmp, EquationCheck& r);

}  // namespace eomgen::checker
