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

}  // namespace eomgen::checker
