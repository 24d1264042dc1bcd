/** @file switching_emitter.cpp  A header's switching surfaces (switching_emitter.hpp). */
#include "codegen/switching_emitter.hpp"

#include "text/escape.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace eomgen::codegen {
namespace {

/// Whether the header's expressions can hold abs, sign, heaviside, max or min: its T, V, forces, constraints and
/// outputs (everything else is derived from them).
bool uses_nonsmooth(const Model& model, const Equations& eq) {
    std::vector<GiNaC::ex> exprs{eq.L, eq.energy};
    exprs.insert(exprs.end(), eq.f.begin(), eq.f.end());
    exprs.insert(exprs.end(), eq.generalized_forces.begin(), eq.generalized_forces.end());
    for (const ConstraintEquations& c : eq.constraints) exprs.insert(exprs.end(), {c.position, c.velocity});
    for (const DeclaredOutput& o : model.outputs) exprs.push_back(o.expr.expr);
    return contains_nonsmooth(exprs);  // the f_i share most of their subexpressions: each looked at once
}

/// A switching surface's function as printed (sign(v - x'), max(a, b)), without the sign that an odd function's
/// printed form may carry in front (-sign(x' - v) is the same surface).
std::string switch_name(const SwitchingSurface& w, MathPrinter& printer) {
    const std::string s = printer.print(w.function, MathStyle::Text);
    return s.rfind('-', 0) == 0 ? s.substr(1) : s;
}

/// The switching surfaces of the dynamics (M, f, the constraints' terms): where rhs() has a kink or a jump.
std::vector<SwitchingSurface> dynamics_switches(const Equations& eq) {
    std::vector<GiNaC::ex> exprs(eq.f.begin(), eq.f.end());
    for (unsigned i = 0; i < eq.M.rows(); ++i)
        for (unsigned j = 0; j < eq.M.cols(); ++j) exprs.push_back(eq.M(i, j));
    for (const ConstraintEquations& c : eq.constraints) {
        exprs.push_back(c.gamma);
        exprs.insert(exprs.end(), c.jacobian.begin(), c.jacobian.end());
    }
    return switching_surfaces(exprs);
}

}  // namespace

void canonical_switches(std::vector<SwitchingSurface> found, MathPrinter& printer, SwitchingCode& c) {
    std::vector<std::pair<std::string, SwitchingSurface>> named;
    for (SwitchingSurface& w : found) {
        std::string best;
        for (const GiNaC::ex& f : w.functions.empty() ? std::vector<GiNaC::ex>{w.function} : w.functions) {
            SwitchingSurface one{surface_of(f), f, {f}};
            const std::string name = switch_name(one, printer);
            if (best.empty() || name < best) {
                best = name;
                w.function = f;
                w.s = one.s;
            }
        }
        named.emplace_back(best, std::move(w));
    }
    std::sort(named.begin(), named.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    c.surfaces.clear();
    c.names.clear();
    for (auto& [name, w] : named) {
        c.names.push_back(name);
        c.surfaces.push_back(std::move(w));
    }
}

SwitchingCode switching_code(const Model& model, const Equations& eq, MathPrinter& printer) {
    SwitchingCode c;
    c.include_runtime = uses_nonsmooth(model, eq);
    // M and the constraints' terms are derived from what uses_nonsmooth() reads: without abs, sign, heaviside,
    // max or min there, they have none (and their n² entries need no walk).
    if (!c.include_runtime) return c;
    canonical_switches(dynamics_switches(eq), printer, c);
    return c;
}

std::string SwitchingCode::comment(MathPrinter& printer) const {
    if (empty()) return "";
    std::string s = "\n//\n// Switching surfaces (rhs() has a kink or a jump where one is 0; EventAction::Switch):";
    for (std::size_t k = 0; k < surfaces.size(); ++k)
        s += "\n//   " + text::cpp_comment(printer.print(surfaces[k].s, MathStyle::Text) + " = 0, of " + names[k]);
    return s;
}

std::string SwitchingCode::constants() const {
    if (empty()) return "";
    return "    /// Switching surfaces of rhs() (abs, sign, heaviside, max, min): switching() and switch_names.\n"
           "    static constexpr int n_switches = " +
           std::to_string(surfaces.size()) + ";\n";
}

std::string SwitchingCode::types() const {
    return empty() ? "" : "    using Switches = Eigen::Matrix<Scalar, n_switches, 1>;\n";
}

std::string SwitchingCode::names_array() const {
    if (empty()) return "";
    std::string s = "    static constexpr std::array<const char*, n_switches> switch_names{";
    for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + text::cpp_string(names[i]);
    return s + "};\n";
}

FunctionSpec SwitchingCode::function(const std::pair<std::string, std::string>& t_in,
                                     const std::pair<std::string, std::string>& q_in,
                                     const std::pair<std::string, std::string>& qd_in,
                                     const std::pair<std::string, std::string>& p_in) const {
    std::vector<Output> values;
    for (std::size_t k = 0; k < surfaces.size(); ++k) values.push_back({fmt::format("out_({})", k), surfaces[k].s});
    return {"The switching surfaces' functions s_k (in the order of switch_names): rhs() has a kink or a jump where one "
            "changes sign.",
            "void", "switching", {t_in, q_in, qd_in, p_in}, {{"Switches", "out_"}}, values};
}

}  // namespace eomgen::codegen
