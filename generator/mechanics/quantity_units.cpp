/** @file quantity_units.cpp  The SI units of the derived quantities (quantity_units.hpp). */
#include "mechanics/quantity_units.hpp"

#include "model/dimensions.hpp"

#include <algorithm>

namespace eomgen {
namespace {

using DimsMap = std::map<GiNaC::ex, Dims, GiNaC::ex_is_less>;

/// The dimension of e, or nothing where a symbol has no unit, e is 0 or inconsistent in itself.
std::optional<Dims> dims_of(const GiNaC::ex& e, const DimsMap& symbols) {
    try {
        return dimension_of(e, symbols);
    } catch (const DimensionError&) {
        return std::nullopt;  // the file reader reports what is wrong at its place; here it has no unit
    }
}

}  // namespace

bool QuantityUnits::any() const {
    auto some = [](const std::vector<std::string>& v) {
        return std::any_of(v.begin(), v.end(), [](const std::string& s) { return !s.empty(); });
    };
    return !energy.empty() || some(state) || some(parameters) || some(momenta) || some(conserved) ||
           some(multipliers) || some(outputs);
}

QuantityUnits quantity_units(const Model& model, const Equations& eq) {
    QuantityUnits u;
    const DimsMap symbols = symbol_dimensions(model);
    const Dims second{{0, 0, 1, 0, 0, 0, 0}};
    const std::size_t n = model.coordinates.size();
    u.state.resize(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const Coordinate& c = model.coordinates[i];
        if (!c.declared_unit) continue;
        const bool angle = c.unit == "rad";
        u.state[i] = angle ? "rad" : si_unit_text(Dims::of(c.declared_unit->dimension));
        u.state[n + i] = angle ? "rad/s" : si_unit_text(Dims::of(c.declared_unit->dimension) - second);
        if (u.state[i].empty()) u.state[n + i] = "1/s";  // a pure number's rate
    }
    for (const Parameter& p : model.parameters)
        u.parameters.push_back((p.declared_unit || p.value_unit) && p.unit != "1" ? p.unit : "");

    // h: an energy when every symbol of T and V has a unit (the file reader has checked each of their terms).
    const std::optional<Dims> T = dims_of(eq.T, symbols), V = dims_of(eq.V, symbols);
    const bool energy = T && *T == energy_dims() && (eq.V.is_zero() || (V && *V == energy_dims()));
    if (energy) u.energy = "J";

    // Per coordinate: p_i is J s per unit of q_i, the equation J per unit of q_i; "N m" where q_i is an angle.
    for (std::size_t i = 0; i < n; ++i) {
        const Coordinate& c = model.coordinates[i];
        const auto q = symbols.find(c.q);
        if (!energy || q == symbols.end()) {
            u.momenta.emplace_back();
            u.equations.emplace_back();
            continue;
        }
        u.momenta.push_back(si_unit_text(energy_dims() + second - q->second));
        u.equations.push_back(q->second.dimensionless() ? "N m" : si_unit_text(energy_dims() - q->second));
    }
    for (const ConservedQuantity& c : eq.conserved) {
        if (c.name == "h") {
            u.conserved.push_back(u.energy);
            continue;
        }
        const std::optional<Dims> d = dims_of(c.value, symbols);
        u.conserved.push_back(d ? si_unit_text(*d) : "");
    }
    // λ_k: Aᵀλ is a generalized force, so λ is an energy per unit of g (holonomic) or per unit of c times a
    // time (nonholonomic, c = a q̇ + b).
    for (std::size_t k = 0; k < eq.constraints.size(); ++k) {
        const ConstraintEquations& c = eq.constraints[k];
        const bool holonomic = c.kind == ConstraintKind::Holonomic;
        std::optional<Dims> g = dims_of(holonomic ? c.position : c.velocity, symbols);
        if (!energy || !g) {
            u.multipliers.emplace_back();
            continue;
        }
        u.multipliers.push_back(si_unit_text(energy_dims() - *g - (holonomic ? Dims{} : second)));
    }
    for (const DeclaredOutput& o : model.outputs) {
        if (!o.unit.empty()) {
            u.outputs.push_back(o.unit);  // the file's unit, which the value is recorded in
            continue;
        }
        const std::optional<Dims> d = dims_of(o.expr.expr, symbols);
        u.outputs.push_back(d ? si_unit_text(*d) : "");
    }
    return u;
}

}  // namespace eomgen
