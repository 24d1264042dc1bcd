/** @file unit_values.hpp  Command-line values (--set NAME=VALUE, --init NAME=VALUE) in the model's units. */
#pragma once

#include "model/model.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen::cli {

/// "alpha=45" for a parameter whose file declares unit = "deg" is 45 degrees; "alpha=45 deg", "alpha=45deg",
/// "l=20 cm" carry their own unit (read by UDUNITS-2, of the declared dimension where one is declared). The
/// result is "NAME=VALUE" with VALUE in SI, as the generated code works; a name the model does not have is left
/// for the runtime to report. Throws std::invalid_argument with `option` and the reason.
std::string assignment_in_si(const Model& model, const std::string& text, bool state, const char* option);

/// Each of `assignments` through assignment_in_si.
void assignments_in_si(const Model& model, std::vector<std::string>& assignments, bool state, const char* option);

/// --set (`set`) and --init (`init`) through assignment_in_si; false, with "<program>: reason" on stderr, for a
/// value eomgen cannot take.
bool options_in_si(const Model& model, std::vector<std::string>& set, std::vector<std::string>& init,
                   const char* program);

}  // namespace eomgen::cli
