/** @file shadowed_labels.hpp  A letter that is both a parameter of the model and one of eomgen's labels (a cart-pole
 * whose rod length is L, as its Lagrangian is): read as the label where only the label makes sense. */
#pragma once

#include "checker/latex_parser.hpp"
#include "checker/sample_points.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace eomgen::checker {

/// What a parameter's letter reads as where it is a label: the label's symbol, and what it is ("L").
struct ShadowedLabel {
    GiNaC::ex label;
    std::string what;
};

/// The note said where a parameter's letter is read as its label.
std::string shadowed_label_note(const GiNaC::ex& parameter, const ShadowedLabel& label);

/**
 * `\frac{\partial L}{\partial \dot x}` with a parameter L: a parameter's derivative by a coordinate or a velocity
 * is 0, which no text writes; it is the label's. Returns `e` with each such ∂ (pdiff) of a shadowed parameter
 * taken of its label instead, and adds a note for each label read so.
 */
GiNaC::ex labels_under_derivatives(const GiNaC::ex& e, const detail::ExMap<ShadowedLabel>& shadowed,
                                   const Model& model, std::vector<std::string>& notes);

/**
 * `L = T - V`, `L = \frac12 M\dot x^2 - \dots` with a parameter L: a bare parameter on the left of `=` whose other
 * sides hold velocities or labels (an energy; a length or a mass never equals one) is the label. Returns the
 * label for `first` (the first side's value), or nullptr when it is the parameter there.
 */
const ShadowedLabel* label_on_the_left(const GiNaC::ex& first, const std::vector<GiNaC::ex>& others,
                                       const detail::ExMap<ShadowedLabel>& shadowed, const detail::ExSet& labels,
                                       const Model& model);

}  // namespace eomgen::checker
