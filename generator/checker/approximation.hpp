/** @file approximation.hpp  Approximations a derivation makes (`\approx`, `\simeq`, "for small θ"): compared
 * with the Taylor expansion of the model's equation about the point (q = 0, or the point of a change of variable
 * the text makes: change_of_variable.cpp), to the order the text keeps. */
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

/// Where each coordinate is expanded: 0, unless the text moved it (`r = r_{eq} + \rho`: about r_eq).
struct ExpansionPoints {
    std::vector<GiNaC::ex> at;              ///< per coordinate; empty: every one about 0
    std::vector<bool> own;                  ///< the point is a constant of the text's own, with no value given
    std::vector<std::string> latex;         ///< the point as the text writes it ("" about 0)
    std::vector<std::string> deviation;     ///< the text's name for q − point (canonical LaTeX), "" about 0
    GiNaC::exmap in_text;                   ///< q, q̇, q̈ → the text's deviation and its derivatives (for the report)
    GiNaC::ex point(std::size_t k) const { return k < at.size() ? at[k] : GiNaC::ex(0); }
    bool own_point(std::size_t k) const { return k < own.size() && own[k]; }
};

/**
 * The coordinates the prose around file offset `at` calls small ("for small θ", "small \theta", "θ ≪ 1",
 * "small oscillations", "small angles": then every coordinate), by their name, LaTeX or Unicode letter, in the
 * paragraph of `at` (to the blank line before it and after it). Indices into model.coordinates.
 */
std::vector<std::size_t> small_coordinates_in_prose(const Derivation& d, std::size_t at, const Model& model,
                                                    const ExpansionPoints& points = {});

/**
 * Where the text, before file offset `at`, says the motion is small ("makes small oscillations", "small
 * angles", "small amplitude", "small vibrations", "small displacements", or "approximating" a sine, cosine or
 * tangent: `approximating $\sin\varphi = \varphi$`), as a file offset; std::nullopt when it does not. An equation after it that would disagree is compared as the approximation it may be.
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
    bool dropped_order_0 = false;  ///< about a point of the text's own: the reference's order 0 left out
};

/**
 * Compares a ≈ b about q = points (0 by default) for the coordinates `small` (each q − point, q̇, q̈ of the same
 * small order ε): the
 * order k is the highest degree in ε of a side that is a polynomial in them; a − b must vanish to order k, or
 * (with accelerations) equal c·EL_i (c constant) to order k, c from the acceleration coefficients at q = 0, or —
 * with one acceleration alone, the others eliminated — c·(q̈_i − (M⁻¹f)_i), q̈_i solved from the equations.
 * `reference_side` (0: a, 1: b, −1: none) is the side that holds eomgen's value (a label), for an
 * approximation without accelerations that disagrees. `same(x, y)` decides equality (numerically). About a
 * point of the text's own with no value (`\phi = \phi_0 + \tilde\phi`), an equation with no term of order 0 is
 * compared with the reference's terms of order 1 and up: the text takes its point where they vanish (an
 * equilibrium), and `dropped_order_0` says so.
 */
ApproxVerdict compare_approximation(const GiNaC::ex& a, const GiNaC::ex& b, int reference_side, const Model& model,
                                    const std::vector<GiNaC::ex>& motion, const std::vector<std::size_t>& small,
                                    const std::function<bool(const GiNaC::ex&, const GiNaC::ex&)>& same,
                                    const ExpansionPoints& points = {});

/**
 * The verdict on a ≈ b (a link at file offset `at`, its sides' LaTeX `sources`): the small coordinates are
 * those the prose names (small_coordinates_in_prose), or, when `implied`, every coordinate a − b holds. Agrees
 * "to first order in $\theta$", or disagrees "at first order" with the expanded reference as the correction
 * (written with `\approx`). False when it does not apply (no side polynomial in the small coordinates, or
 * nothing to compare a disagreement with).
 */
bool check_approximation(const Derivation& d, const Model& model, const std::vector<GiNaC::ex>& motion, std::size_t at,
                         const std::pair<std::string, std::string>& sources, const GiNaC::ex& a, const GiNaC::ex& b,
                         int reference_side, bool implied, Comparisons& cmp, EquationCheck& r,
                         const ExpansionPoints& points = {});

}  // namespace eomgen::checker
