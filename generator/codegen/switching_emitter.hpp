/**
 * @file switching_emitter.hpp  What a header holds for a model with abs, sign, heaviside, max or min in its
 * dynamics (docs/generated_code.md, "Switching surfaces"): the opening comment's list of surfaces, n_switches,
 * Switches, switch_names and switching(); and whether it includes eomgen/nonsmooth.hpp.
 */
#pragma once

#include "codegen/cpp_emitter.hpp"
#include "codegen/math_printer.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"
#include "model/nonsmooth.hpp"

#include <string>
#include <vector>

namespace eomgen::codegen {

struct SwitchingCode {
    std::vector<SwitchingSurface> surfaces;  ///< of M, f and the constraints' terms, in order
    std::vector<std::string> names;          ///< switch_names: sign(v - x'), max(a, b)
    bool include_runtime = false;            ///< the header calls eomgen::sign & co. (or abs in any function)

    bool empty() const { return surfaces.empty(); }
    /// The opening comment's lines ("\n//   v - x' = 0, of sign(v - x')"), "" when there are none.
    std::string comment(MathPrinter& printer) const;
    /// n_switches (after has_generalized_forces), Switches (after the other types), switch_names; "" when none.
    std::string constants() const;
    std::string types() const;
    std::string names_array() const;
    /// switching(t, q, q', p, s): s_k, in the order of switch_names.
    FunctionSpec function(const std::pair<std::string, std::string>& t_in, const std::pair<std::string, std::string>& q_in,
                          const std::pair<std::string, std::string>& qd_in,
                          const std::pair<std::string, std::string>& p_in) const;
};

SwitchingCode switching_code(const Model& model, const Equations& eq, MathPrinter& printer);

/**
 * `c.surfaces` and `c.names` from the surfaces `found`, in an order and with names that do not depend on the order
 * they were found in: each surface is named by the function on it whose printed name comes first (max(0, x - a) and
 * heaviside(a - x) share one), its s is that function's (its argument, or a − b), and the surfaces are sorted by
 * name. (GiNaC's stored order of terms, which a walk meets them in, changes from one process to the next.)
 */
void canonical_switches(std::vector<SwitchingSurface> found, MathPrinter& printer, SwitchingCode& c);

}  // namespace eomgen::codegen
