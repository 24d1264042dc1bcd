/** @file model_unit_values.hpp  unit_values.hpp for a model file's Model: its parameters' and coordinates'
 * declared units. */
#pragma once

#include "cli/unit_values.hpp"
#include "model/model.hpp"

namespace eomgen::cli {

inline DeclaredUnits declared_units(const Model& model) {
    DeclaredUnits d;
    for (const Parameter& p : model.parameters) d.parameters.push_back({p.name, p.declared_unit});
    for (const Coordinate& c : model.coordinates) d.coordinates.push_back({c.name, c.declared_unit});
    return d;
}

}  // namespace eomgen::cli
