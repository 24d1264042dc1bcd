/** @file interpreted_model.cpp  A derived model's tapes, names and units (interpreted_model.hpp). */
#include "interpreter/interpreted_model.hpp"

#include "codegen/cpp_emitter.hpp"
#include "codegen/math_printer.hpp"
#include "codegen/switching_emitter.hpp"
#include "mechanics/quantity_units.hpp"

#include <algorithm>

namespace eomgen::interpreter {

InterpretedModel interpret(const Model& model, const Equations& eq) {
    InterpretedModel m;
    m.name = model.name;
    m.title = model.title;
    m.source = model.source;
    const std::size_t n = model.dof();
    m.nq = static_cast<int>(n);
    m.explicit_time = eq.explicit_time;
    m.has_generalized_forces = std::any_of(eq.generalized_forces.begin(), eq.generalized_forces.end(),
                                           [](const GiNaC::ex& q) { return !q.is_zero(); });
    m.has_power = eq.constraints.empty() && (m.has_generalized_forces || eq.explicit_time);
    for (const Coordinate& c : model.coordinates) m.state_names.push_back(c.name);
    for (const Coordinate& c : model.coordinates) m.state_names.push_back(c.name + "_dot");
    for (const Coordinate& c : model.coordinates) m.default_state.push_back(c.initial);
    for (const Coordinate& c : model.coordinates) m.default_state.push_back(c.rate);
    for (const Parameter& p : model.parameters) {
        m.param_names.push_back(p.name);
        m.param_defaults.push_back(p.value);
        m.param_declared_units.push_back(p.declared_unit ? p.declared_unit->text : "");
    }
    for (const Coordinate& c : model.coordinates)
        m.coordinate_declared_units.push_back(c.declared_unit ? c.declared_unit->text : "");
    for (const ConservedQuantity& c : eq.conserved) m.conserved_names.push_back(c.name);
    for (const DeclaredOutput& o : model.outputs) m.output_names.push_back(o.name);
    for (const ConstraintEquations& c : eq.constraints) {
        m.constraint_names.push_back(c.name);
        m.constraint_is_holonomic.push_back(c.kind == ConstraintKind::Holonomic);
    }
    m.baumgarte_alpha = model.baumgarte_alpha;
    m.baumgarte_beta = model.baumgarte_beta;
    const QuantityUnits u = quantity_units(model, eq);
    m.energy_unit = u.energy;
    m.state_units = u.state;
    m.param_units = u.parameters;
    m.conserved_units = u.conserved;
    m.output_units = u.outputs;
    m.multiplier_units = u.multipliers;

    const codegen::SymbolTable table = codegen::symbol_table(model);
    auto record = [&table](const std::vector<GiNaC::ex>& values) { return record_tape(table, values); };
    std::vector<GiNaC::ex> mass_force, momenta, gradient, conserved, outputs;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) mass_force.push_back(eq.M(static_cast<unsigned>(i), static_cast<unsigned>(j)));
    for (std::size_t i = 0; i < n; ++i) {
        mass_force.push_back(eq.f[i]);
        momenta.push_back(eq.momenta[i]);
        gradient.push_back(eq.dLdq[i]);
    }
    for (const ConservedQuantity& c : eq.conserved) conserved.push_back(c.value);
    for (const DeclaredOutput& o : model.outputs) outputs.push_back(o.expr.expr);
    m.dynamics = record(mass_force);
    m.energy = record({eq.energy});
    m.conserved = record(conserved);
    m.outputs = record(outputs);
    m.momenta = record(momenta);
    m.lagrangian_gradient = record(gradient);
    if (m.has_power) {
        GiNaC::ex P = -eq.L.diff(model.t);
        for (std::size_t i = 0; i < n; ++i) P += eq.generalized_forces[i] * model.coordinates[i].qd;
        m.power = record({P});
    }
    codegen::MathPrinter printer(table);
    const codegen::SwitchingCode switches = codegen::switching_code(model, eq, printer);
    m.switch_names = switches.names;
    std::vector<GiNaC::ex> surfaces;
    for (const SwitchingSurface& s : switches.surfaces) surfaces.push_back(s.s);
    m.switching = record(surfaces);
    if (!eq.constraints.empty()) {
        std::vector<GiNaC::ex> all = mass_force;
        for (const ConstraintEquations& c : eq.constraints)
            for (std::size_t i = 0; i < n; ++i) all.push_back(c.jacobian[i]);
        for (const ConstraintEquations& c : eq.constraints) all.push_back(c.gamma);
        for (const ConstraintEquations& c : eq.constraints) all.push_back(c.position);
        for (const ConstraintEquations& c : eq.constraints) all.push_back(c.velocity);
        m.constrained = record(all);
    }
    return m;
}

}  // namespace eomgen::interpreter
