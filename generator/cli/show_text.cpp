/** @file show_text.cpp  The derived mechanics as plain text (show_text.hpp). */
#include "cli/show_text.hpp"

#include "cli/latex_equations.hpp"
#include "codegen/cpp_emitter.hpp"
#include "codegen/math_printer.hpp"
#include "mechanics/bodies.hpp"
#include "mechanics/hamiltonian.hpp"
#include "mechanics/quantity_units.hpp"
#include "mechanics/trig_rewrite.hpp"
#include "model/dimensions.hpp"
#include "text/escape.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>

namespace eomgen::cli {
namespace {

std::string rule(const std::string& title) { return "\n" + title + "\n" + std::string(title.size(), '-') + "\n"; }

/// "  [J]" after a quantity of unit J; nothing where it has none.
std::string in_unit(const std::string& unit) { return unit.empty() ? "" : "  [" + unit + "]"; }

void show_constraints(const eomgen::Model& model, const eomgen::Equations& eq, eomgen::codegen::MathPrinter& pr,
                      const std::vector<GiNaC::symbol>& lambda, const eomgen::QuantityUnits& units, std::ostream& os) {
    using eomgen::codegen::MathStyle;
    const eomgen::trig::Hints hints = eomgen::trig::model_hints(model);
    pr.prefer_angles(hints.angles);
    auto P = [&pr, &hints](const GiNaC::ex& e) {
        return pr.print(eomgen::trig::readable(e, hints), MathStyle::Text);
    };
    os << rule("Constraints  M q'' = f + A^T lambda,  A q'' = gamma  (c = A q' + b = 0)");
    for (std::size_t k = 0; k < eq.constraints.size(); ++k) {
        const eomgen::ConstraintEquations& c = eq.constraints[k];
        const bool holonomic = c.kind == eomgen::ConstraintKind::Holonomic;
        os << "  " << c.name << " (" << (holonomic ? "holonomic" : "nonholonomic") << "): "
           << P(holonomic ? c.position : c.velocity) << " = 0"
           << (units.multipliers[k].empty() ? "" : "  (its multiplier in " + units.multipliers[k] + ")") << "\n";
        if (holonomic) os << "    velocity level: " << P(c.velocity) << " = 0\n";
        os << "    A = [";
        for (std::size_t i = 0; i < c.jacobian.size(); ++i) os << (i ? ", " : "") << P(c.jacobian[i]);
        os << "]  over (";
        for (std::size_t i = 0; i < model.dof(); ++i) os << (i ? ", " : "") << model.coordinates[i].name << "'";
        os << ")\n    gamma = " << P(c.gamma) << "\n";
        if (!holonomic) os << "    integrability: " << c.verdict << "\n";
    }
    if (!eq.frobenius.empty()) os << "  " << eq.frobenius << "\n";
    os << rule("Equations of motion with multipliers  d/dt(dL/dq') - dL/dq = Q - dR/dq' + A^T lambda");
    for (std::size_t i = 0; i < model.dof(); ++i) {
        GiNaC::ex rhs = eq.generalized_forces[i];
        for (std::size_t k = 0; k < eq.constraints.size(); ++k) rhs += eq.constraints[k].jacobian[i] * lambda[k];
        os << "  [" << model.coordinates[i].name << "]  " << P(eq.euler_lagrange[i]) << " = " << P(rhs)
           << in_unit(units.equations[i]) << "\n";
    }
}


}  // namespace

void show_text(const Model& model, const Equations& eq, std::ostream& os, const std::string& equilibria) {
    using eomgen::codegen::MathStyle;
    const eomgen::Hamiltonian ham = eomgen::derive_hamiltonian(model, eq);
    eomgen::cli::MultiplierTable mt = eomgen::cli::multiplier_table(model, eq, &ham);
    eomgen::codegen::MathPrinter pr(mt.table);
    const eomgen::trig::Hints hints = eomgen::trig::model_hints(model);
    pr.prefer_angles(hints.angles);
    auto P = [&pr, &hints](const GiNaC::ex& e) {
        return pr.print(eomgen::trig::readable(e, hints), MathStyle::Text);
    };
    const eomgen::QuantityUnits units = eomgen::quantity_units(model, eq);
    os << model.name << ": " << model.title;
    if (!model.source.empty()) os << " (" << model.source << ")";
    os << "\n";
    os << rule("Coordinates");
    for (const eomgen::Coordinate& c : model.coordinates) {
        const std::string unit = c.unit.empty() ? "" : " " + c.unit;
        const std::string rate_unit = c.unit.empty() ? "" : c.unit == "1" ? " 1/s" : " " + c.unit + "/s";
        os << "  " << c.name << "  (q(0) = " << eomgen::codegen::shortest_decimal(c.initial) << unit
           << ", q'(0) = " << eomgen::codegen::shortest_decimal(c.rate) << rate_unit << ")"
           << (c.description.empty() ? "" : "  " + c.description) << "\n";
    }
    os << rule("Parameters");
    for (const eomgen::Parameter& p : model.parameters)
        os << "  " << p.name << " = " << eomgen::codegen::shortest_decimal(p.value) << (p.unit.empty() || p.unit == "1" ? "" : " " + p.unit)
           << (p.given.empty() ? "" : "  (given as " + p.given + ")")
           << (p.description.empty() ? "" : "  (" + p.description + ")") << "\n";
    if (!eq.bodies.empty()) {
        os << rule("Bodies  T_b = m v_c^2/2 + w'.I.w'/2,  V_b = -m g.r_c");
        for (const eomgen::BodyEnergy& b : eq.bodies)
            os << "  " << b.name << ":\n    T_" << b.name << " = " << P(b.T) << "\n    V_" << b.name << " = " << P(b.V)
               << "\n";
        if (!model.T.expr.is_zero() || !model.V.expr.is_zero())
            os << "  explicit [lagrangian]:\n    T = " << P(model.T.expr) << "\n    V = " << P(model.V.expr) << "\n";
    }
    if (!eq.springs.empty()) {
        os << rule("Springs  V_s = k (|d| - l0)^2 / 2");
        for (const eomgen::SpringEnergy& s : eq.springs)
            os << "  " << s.name << ":\n    length = " << P(s.length) << "\n    V_" << s.name << " = " << P(s.V) << "\n";
    }
    if (!model.bodies.empty()) {
        os << rule("Euler's equations  N' = I w'_dot + w' x (I w')  (body axes, about the centre of mass)");
        for (const eomgen::Body& body : model.bodies) {
            const eomgen::BodyDynamics d = eomgen::body_dynamics(model, body);
            if (d.omega_body.is_zero_matrix()) {
                os << "  " << body.name << ": does not rotate\n";
                continue;
            }
            os << "  " << body.name << ":\n";
            for (unsigned k = 0; k < 3; ++k)
                os << "    w'_" << k + 1 << " = " << P(d.omega_body(k, 0)) << "\n";
            for (unsigned k = 0; k < 3; ++k)
                os << "    N'_" << k + 1 << " = " << P(d.euler_torque(k, 0)) << "\n";
        }
    }
    const std::string J = in_unit(units.energy);
    os << rule("Energies");
    os << "  T = " << P(eq.T) << J << "\n  V = " << P(eq.V) << J << "\n  L = T - V = " << P(eq.L) << J << "\n";
    os << rule("Euler-Lagrange equations  d/dt(dL/dq') - dL/dq = 0");
    for (std::size_t i = 0; i < model.dof(); ++i)
        os << "  [" << model.coordinates[i].name << "]  " << P(eq.euler_lagrange[i]) << " = 0"
           << in_unit(units.equations[i]) << "\n";
    os << rule("Mass-matrix form  M(q,t) q'' = f(q,q',t)");
    for (std::size_t i = 0; i < model.dof(); ++i)
        for (std::size_t j = i; j < model.dof(); ++j)
            os << "  M[" << model.coordinates[i].name << "," << model.coordinates[j].name
               << "] = " << P(eq.M(unsigned(i), unsigned(j))) << "\n";
    for (std::size_t i = 0; i < model.dof(); ++i)
        os << "  f[" << model.coordinates[i].name << "] = " << P(eq.f[i]) << "\n";
    if (!eq.constraints.empty() || std::any_of(eq.generalized_forces.begin(), eq.generalized_forces.end(),
                                                [](const GiNaC::ex& q) { return !q.is_zero(); }))
        show_constraints(model, eq, pr, mt.lambda, units, os);
    os << rule("Energy function and momenta");
    os << "  h = sum q' dL/dq' - L = " << P(eq.energy) << J << "\n";
    for (std::size_t i = 0; i < model.dof(); ++i)
        os << "  p_" << model.coordinates[i].name << " = dL/d" << model.coordinates[i].name << "' = " << P(eq.momenta[i])
           << in_unit(units.momenta[i]) << "\n";
    os << rule("Hamiltonian  H(q,p,t) = p.q' - L,  Hamilton's equations  q' = dH/dp, p' = -dH/dq (+ Q)");
    if (ham.symbolic) {
        os << "  H = " << P(ham.H) << J << "\n";
        for (std::size_t i = 0; i < model.dof(); ++i) {
            const std::string& q = model.coordinates[i].name;
            os << "  " << q << "' = dH/dp_" << q << " = " << P(ham.qdot[i]) << "\n";
            os << "  p_" << q << "' = -dH/d" << q << (eq.constraints.empty() ? "" : " + (A^T lambda)_" + q) << " = "
               << P(ham.pdot[i]) << "\n";
        }
    } else {
        os << "  H = h with q' = M^-1 (p - b): " << ham.why_not_symbolic << "\n";
    }
    os << rule("Conserved quantities");
    if (eq.conserved.empty()) os << "  none found\n";
    for (std::size_t k = 0; k < eq.conserved.size(); ++k)
        os << "  " << eq.conserved[k].name << (units.conserved[k].empty() ? "" : " [" + units.conserved[k] + "]") << ": " << eq.conserved[k].reason << "\n";
    for (std::size_t i = 0; i < model.dof(); ++i)
        if (!eq.cyclic[i])
            os << "  " << model.coordinates[i].name << " is not cyclic\n";
        else if (std::none_of(eq.conserved.begin(), eq.conserved.end(),
                              [&](const auto& c) { return c.name == "p_" + model.coordinates[i].name; }))
            os << "  " << model.coordinates[i].name << " is cyclic, but p_" << model.coordinates[i].name
               << " is not conserved: a force or a constraint acts along it\n";
    if (!model.results.empty()) {
        os << rule("Declared results  [[results]]");
        for (const eomgen::Result& r : model.results) {
            os << "  " << r.name << ": " << r.latex << " = " << P(r.expr.expr) << "\n";
            if (!r.equals.empty())
                os << "    verified: equals " << r.equals << (r.on_constraints ? " on the constraints" : "") << "\n";
            if (!r.description.empty()) os << "    " << r.description << "\n";
        }
    }
    if (!model.outputs.empty()) {
        os << rule("Outputs  [outputs], recorded beside the state by `eomgen run` and eomgen-sim");
        for (std::size_t k = 0; k < model.outputs.size(); ++k) {
            const eomgen::DeclaredOutput& o = model.outputs[k];
            os << "  " << o.name << " = " << P(o.expr.expr) << in_unit(units.outputs[k]) << "\n";
            if (!o.description.empty()) os << "    " << o.description << "\n";
        }
    }
    if (!equilibria.empty()) {
        os << rule("Equilibria and small oscillations  (with the parameters' values; eomgen modes for M0, K0, shapes)");
        os << equilibria;
    }
    if (!eq.warnings.empty()) {
        os << rule("Warnings");
        for (const std::string& w : eq.warnings) os << "  " << w << "\n";
    }
}

EquationsText equations_text(const Model& model, const Equations& eq) {
    const Hamiltonian ham = derive_hamiltonian(model, eq);
    MultiplierTable mt = multiplier_table(model, eq, &ham);
    codegen::MathPrinter pr(mt.table);
    const trig::Hints hints = trig::model_hints(model);
    pr.prefer_angles(hints.angles);
    auto P = [&pr, &hints](const GiNaC::ex& e) { return pr.print(trig::readable(e, hints), codegen::MathStyle::Text); };
    EquationsText out{P(eq.T), P(eq.V), P(eq.L), P(eq.energy), {}, {}, {}, {}, {}};
    for (std::size_t i = 0; i < model.dof(); ++i) {
        GiNaC::ex rhs = eq.generalized_forces[i];
        for (std::size_t k = 0; k < eq.constraints.size(); ++k) rhs += eq.constraints[k].jacobian[i] * mt.lambda[k];
        out.euler_lagrange.push_back(P(eq.euler_lagrange[i]));
        out.forces.push_back(P(rhs));
        out.f.push_back(P(eq.f[i]));
        out.momenta.push_back(P(eq.momenta[i]));
        std::vector<std::string> row;
        for (std::size_t j = 0; j < model.dof(); ++j) row.push_back(P(eq.M(unsigned(i), unsigned(j))));
        out.M.push_back(std::move(row));
    }
    return out;
}

}  // namespace eomgen::cli
