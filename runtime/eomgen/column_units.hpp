/**
 * @file column_units.hpp  The units of a model's values as the runtime writes them (issue 29): a CSV header
 * `psi [rad]`, a report's `m = 30 kg`. A generated header declares them (state_units, param_units,
 * conserved_units, output_units, multiplier_units, energy_unit: SI, "" where the model file declares none;
 * param_declared_units and coordinate_declared_units: the file's own, `deg`); a header made before units has
 * none, and every unit here is then "".
 */
#pragma once

#include <cstddef>
#include <string>
#include <type_traits>

namespace eomgen {

/// M declares the units of its values (every header eomgen generates since units were added does).
template <class M, class = void>
struct declares_units : std::false_type {};
template <class M>
struct declares_units<M, std::void_t<decltype(M::state_units)>> : std::true_type {};

namespace units_detail {
inline std::string text(const char* s) { return s ? std::string(s) : std::string(); }
}  // namespace units_detail

/// The SI unit of state i (q, then q̇): "rad", "m/s"; "" where none is declared.
template <class M>
std::string state_unit(std::size_t i) {
    if constexpr (declares_units<M>::value) return units_detail::text(M::state_units[i]);
    else return "";
}
template <class M>
std::string param_unit(std::size_t i) {
    if constexpr (declares_units<M>::value) return units_detail::text(M::param_units[i]);
    else return "";
}
template <class M>
std::string conserved_unit(std::size_t i) {
    if constexpr (declares_units<M>::value) return units_detail::text(M::conserved_units[i]);
    else return "";
}
template <class M>
std::string output_unit(std::size_t i) {
    if constexpr (declares_units<M>::value) return units_detail::text(M::output_units[i]);
    else return "";
}
/// The unit of h (and of the work of the forces): "J".
template <class M>
std::string energy_unit() {
    if constexpr (declares_units<M>::value) return units_detail::text(M::energy_unit);
    else return "";
}
/// The unit of constraint k's multiplier (M constrained).
template <class M>
std::string multiplier_unit(std::size_t k) {
    if constexpr (declares_units<M>::value) return units_detail::text(M::multiplier_units[k]);
    else return "";
}
/// The unit the model file declares for parameter i (`deg`), in which a bare number of --set is.
template <class M>
std::string declared_param_unit(std::size_t i) {
    if constexpr (declares_units<M>::value) return units_detail::text(M::param_declared_units[i]);
    else return "";
}
/// The unit the model file declares for coordinate i, in which a bare number of --init is (and per second for q̇).
template <class M>
std::string declared_coordinate_unit(std::size_t i) {
    if constexpr (declares_units<M>::value) return units_detail::text(M::coordinate_declared_units[i]);
    else return "";
}

/// The unit of t: "s" where the model declares units (its values are then SI), else "".
template <class M>
std::string time_unit() {
    if (!energy_unit<M>().empty()) return "s";
    for (std::size_t i = 0; i < M::state_names.size(); ++i)
        if (!state_unit<M>(i).empty()) return "s";
    return "";
}

/// "psi [rad]", or the name alone where it has no unit.
inline std::string with_unit(const std::string& name, const std::string& unit) {
    return unit.empty() ? name : name + " [" + unit + "]";
}

/// The name of a column whose header may carry its unit: "psi [rad]" → "psi", "psi" → "psi".
inline std::string column_name(const std::string& header) {
    const std::size_t open = header.rfind(" [");
    if (open == std::string::npos || header.empty() || header.back() != ']') return header;
    return header.substr(0, open);
}

}  // namespace eomgen
