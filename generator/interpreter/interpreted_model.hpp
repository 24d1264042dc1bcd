/**
 * @file interpreted_model.hpp  A derived model as tapes (tape.hpp) instead of a generated header: the functions
 * of docs/generated_code.md recorded from the same expressions, with the names, defaults and units a header holds.
 * Plain data, made once per model; interpreted_table.hpp runs it behind a ModelTable, so that the driver compiled
 * into eomgen integrates it as it does a compiled model. `eomgen run --interpret`, and Python's
 * `simulate(interpret=True)`, use it: no C++ compiler runs.
 *
 * The Jacobians (radau5, sensitivities, fit) are not recorded: those runs compile.
 */
#pragma once

#include "interpreter/tape.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace eomgen::interpreter {

struct InterpretedModel {
    std::string name, title, source;
    int nq = 0;
    bool explicit_time = false, has_generalized_forces = false, has_power = false;
    std::vector<std::string> state_names, param_names, conserved_names, output_names, constraint_names, switch_names;
    std::vector<char> constraint_is_holonomic;
    std::vector<double> param_defaults, default_state;
    double baumgarte_alpha = 0, baumgarte_beta = 0;
    /// As a header's unit arrays (codegen/units_emitter.hpp): SI units of the columns, and the declared ones.
    std::string energy_unit;
    std::vector<std::string> state_units, param_units, conserved_units, output_units, multiplier_units,
        param_declared_units, coordinate_declared_units;

    /// Inputs of every tape: the symbol table's order (each parameter, then q, q̇, q̈ of each coordinate, t, π).
    int n_inputs() const { return static_cast<int>(param_names.size()) + 3 * nq + 2; }  ///< checked by InterpretedTable

    Tape dynamics;             ///< M (nq × nq, row by row), then f
    Tape energy;               ///< h
    Tape conserved;            ///< in the order of conserved_names
    Tape outputs;              ///< the declared outputs
    Tape momenta;              ///< ∂L/∂q̇
    Tape lagrangian_gradient;  ///< ∂L/∂q
    Tape power;                ///< Σ Q_i q̇_i − ∂L/∂t (has_power)
    Tape switching;            ///< the switching surfaces' functions
    /// With constraints: M (row by row), f, A (row by row), γ, the position residuals g, the velocity ones c.
    Tape constrained;
    /// Set by InterpretedTable, distinct for every table made in the process (what a per-thread result is kept for).
    std::uint64_t identity = 0;
};

/// Records the model's tapes from its derived equations. Throws std::runtime_error for an expression generated code
/// cannot express either.
InterpretedModel interpret(const Model& model, const Equations& eq);

}  // namespace eomgen::interpreter
