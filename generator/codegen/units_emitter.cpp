/** @file units_emitter.cpp  The units of a generated model's columns (units_emitter.hpp). */
#include "codegen/units_emitter.hpp"

#include "mechanics/quantity_units.hpp"
#include "text/escape.hpp"

#include <sstream>
#include <vector>

namespace eomgen::codegen {
namespace {

std::string strings(const std::vector<std::string>& v) {
    std::string s = "{";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + text::cpp_string(v[i]);
    return s + "}";
}

}  // namespace

std::string emit_unit_arrays(const Model& model, const Equations& eq) {
    const QuantityUnits u = quantity_units(model, eq);
    std::vector<std::string> declared_params, declared_coordinates;
    for (const Parameter& p : model.parameters) declared_params.push_back(p.declared_unit ? p.declared_unit->text : "");
    for (const Coordinate& c : model.coordinates)
        declared_coordinates.push_back(c.declared_unit ? c.declared_unit->text : "");
    std::ostringstream os;
    os << "    /// The SI unit of each value the runtime writes (\"\" where the model file declares none): the CSV's\n"
          "    /// headers, `psi [rad]`.\n";
    os << "    static constexpr const char* energy_unit = " << text::cpp_string(u.energy) << ";\n";
    os << "    static constexpr std::array<const char*, nx> state_units" << strings(u.state) << ";\n";
    os << "    static constexpr std::array<const char*, n_params> param_units" << strings(u.parameters) << ";\n";
    os << "    static constexpr std::array<const char*, n_conserved> conserved_units" << strings(u.conserved) << ";\n";
    os << "    static constexpr std::array<const char*, n_outputs> output_units" << strings(u.outputs) << ";\n";
    if (!eq.constraints.empty())
        os << "    static constexpr std::array<const char*, n_constraints> multiplier_units" << strings(u.multipliers)
           << ";\n";
    os << "    /// The units the model file declares, in which a bare number of --set or --init is (`deg`).\n";
    os << "    static constexpr std::array<const char*, n_params> param_declared_units" << strings(declared_params) << ";\n";
    os << "    static constexpr std::array<const char*, nq> coordinate_declared_units" << strings(declared_coordinates)
       << ";\n";
    return os.str();
}

}  // namespace eomgen::codegen
