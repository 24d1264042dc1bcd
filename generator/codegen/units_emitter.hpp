/**
 * @file units_emitter.hpp  The units of a generated model's columns (issue 29): the SI unit of each state,
 * parameter, conserved quantity, output and multiplier and of h, which the runtime writes into CSV headers
 * (`psi [rad]`) and its reports, and the units the model file declares (`deg`), in which eomgen-sim reads bare
 * numbers of --set and --init as `eomgen run` does. "" where the file declares none.
 */
#pragma once

#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <string>

namespace eomgen::codegen {

/// The members of struct Model holding the units (static constexpr arrays of C++ string literals, escaped).
std::string emit_unit_arrays(const Model& model, const Equations& eq);

}  // namespace eomgen::codegen
