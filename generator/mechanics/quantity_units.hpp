/**
 * @file quantity_units.hpp  The SI units of what the mechanics stage derives (issue 29): the state, h, the
 * momenta, each Euler–Lagrange equation, the conserved quantities, the multipliers and the declared outputs.
 *
 * They follow from the model file's declared units (model/dimensions.hpp): h is an energy where T and V have
 * units, p_i = ∂L/∂q̇_i is an energy times a time per unit of q_i, the equation of q_i an energy per unit of q_i
 * (a force for a length, a torque for an angle), a multiplier an energy per unit of its constraint. A quantity
 * with a symbol of no declared unit has none (""): a model file without units gets no units, as before.
 * Plain data for the stages after this one (codegen's header, `eomgen show`).
 */
#pragma once

#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <string>
#include <vector>

namespace eomgen {

struct QuantityUnits {
    std::vector<std::string> state;        ///< 2 nq: each q ("rad", "m"), then each q̇ ("rad/s", "m/s")
    std::vector<std::string> parameters;   ///< each parameter's SI unit ("N/m", "rad")
    std::string energy;                    ///< h (and T, V, the work of the forces): "J"
    std::vector<std::string> momenta;      ///< p_i: "kg m^2/s" for an angle, "kg m/s" for a length
    std::vector<std::string> equations;    ///< of each Euler–Lagrange equation: "N m" for an angle, "N" for a length
    std::vector<std::string> conserved;    ///< each conserved quantity's, in Equations::conserved's order
    std::vector<std::string> multipliers;  ///< each constraint's multiplier λ_k
    std::vector<std::string> outputs;      ///< each declared output's: its `unit` as declared, else its SI unit
    /// Whether any of them is known (the file declares units).
    bool any() const;
};

/// The units of `eq`'s quantities from `model`'s declared units.
QuantityUnits quantity_units(const Model& model, const Equations& eq);

}  // namespace eomgen
