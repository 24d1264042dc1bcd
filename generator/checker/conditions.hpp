/** @file conditions.hpp  Rows that set values rather than claim an equation: the conditions of a particular motion
 * ("the top is started with θ = π/3, θ̇ = 0"), the problem's data and assumptions ("with m₁ = m₂ = m"). Such a
 * row is not judged as an equation of motion (issue 28). */
#pragma once

#include "checker/derivation.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>
#include <string>

namespace eomgen::checker {

/**
 * The cue of the sentence that leads into the math at `offset` (the prose of its paragraph before the math,
 * from the last sentence end): "started", "initial", "with", "let", "assume", "keep", … as written; empty when
 * the sentence has none.
 */
std::string condition_cue(const Derivation& d, std::size_t offset);


/**
 * True when `a = b` (as parsed, before labels are replaced) sets a value: one side is a single name (a
 * coordinate, a velocity, a parameter or a name of the text's own) and the other holds no coordinate, velocity
 * or acceleration, and neither holds an acceleration.
 */
bool sets_a_value(const GiNaC::ex& a, const GiNaC::ex& b, const Model& model);

/**
 * True when `a = b` names an instant: one side is the model's time t, the other a number or a single symbol that is
 * no symbol of the model (`t = 0`, `t = 20` for a plotted interval, `t = t_c` for the arrival time). Not an
 * equation of the motion. (A time the text works out, `t = 1.51\sqrt{w/g}`, holds parameters: not an instant.)
 */
bool names_an_instant(const GiNaC::ex& a, const GiNaC::ex& b, const Model& model);

/**
 * True when `name = value` gives a coordinate's initial value: `name` (canonical LaTeX) is a coordinate's name with
 * the subscript 0 (`x_{0}`, `\theta_{0}`), or it or its rate at 0 (`\theta(0)`, `\dot{x}(0)`), and `value` a number
 * (`x_0 = 1`, "start at distance 1", `\theta(0) = 0`).
 */
bool sets_initial_value(const std::string& name, const GiNaC::ex& value, const Model& model);

}  // namespace eomgen::checker
