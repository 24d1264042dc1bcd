/**
 * @file unit_values.hpp  Command-line values (--set, --init, --sweep, --dist) in the model's units, for `eomgen run`,
 * `report` and `modes` (from the model file) and eomgen-sim (from the units its generated headers declare). No
 * GiNaC here: eomgen-sim links this and UDUNITS-2 only.
 */
#pragma once

#include "model/units.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen::cli {

/// The units a model declares for its parameters and coordinates: a bare number of --set or --init is in them.
struct DeclaredUnits {
    struct Entry {
        std::string name;
        std::optional<Unit> unit;  ///< nothing where the model declares none (the number is then taken as it is)
    };
    std::vector<Entry> parameters, coordinates;
};

/// From a generated model's names and declared unit texts (`param_declared_units`, `coordinate_declared_units`:
/// "deg", "" for none), each read by UDUNITS-2 again.
DeclaredUnits declared_units(const std::vector<const char*>& param_names, const std::vector<const char*>& param_units,
                             const std::vector<const char*>& coordinate_names,
                             const std::vector<const char*>& coordinate_units);

/// "alpha=45" for a parameter whose file declares unit = "deg" is 45 degrees; "alpha=45 deg", "alpha=45deg",
/// "l=20 cm" carry their own unit (read by UDUNITS-2, of the declared dimension where one is declared). The
/// result is "NAME=VALUE" with VALUE in SI, as the generated code works; a name the model does not have is left
/// for the runtime to report. Throws std::invalid_argument with `option` and the reason.
std::string assignment_in_si(const DeclaredUnits& units, const std::string& text, bool state, const char* option);

/// Each of `assignments` through assignment_in_si.
void assignments_in_si(const DeclaredUnits& units, std::vector<std::string>& assignments, bool state, const char* option);

/// --set (`set`) and --init (`init`) through assignment_in_si; false, with "<program>: reason" on stderr, for a
/// value eomgen cannot take.
bool options_in_si(const DeclaredUnits& units, std::vector<std::string>& set, std::vector<std::string>& init,
                   const char* program);

/// --sweep NAME=START:STOP:COUNT or NAME=v1,v2,... and --dist NAME=uniform(a,b) or NAME=normal(mu,sigma), each number
/// in NAME's declared unit (or with its own, "0deg:90deg:10"), rewritten in SI; false, with "<program>: reason" on
/// stderr, for a value eomgen cannot take. What is not NAME=... of that form is left for the design to report.
bool ensemble_in_si(const DeclaredUnits& units, std::vector<std::string>& sweeps, std::vector<std::string>& dists,
                    const char* program);

}  // namespace eomgen::cli
