/** @file latex_equations.cpp  The derived mechanics as LaTeX blocks (see latex_equations.hpp). */
#include "cli/latex_equations.hpp"

#include "codegen/cpp_emitter.hpp"
#include "codegen/math_printer.hpp"
#include "mechanics/bodies.hpp"
#include "mechanics/trig_rewrite.hpp"
#include "text/escape.hpp"

#include <algorithm>

namespace eomgen::cli {

using text::latex_text;

namespace {

void add(LatexBlock& b, std::string row, std::string note = "") {
    b.rows.push_back(std::move(row));
    b.notes.push_back(std::move(note));
}

}  // namespace

MultiplierTable multiplier_table(const Model& model, const Equations& eq, const Hamiltonian* h) {
    MultiplierTable m{codegen::symbol_table(model), {}};
    for (std::size_t i = 0; h && i < h->p.size(); ++i) {
        const std::string name = "p_" + model.coordinates[i].name;
        m.table.info.push_back({codegen::SymbolKind::Constant, int(i + 1), name, name,
                                "p_{" + model.coordinates[i].latex + "}", ""});
        m.table.exprs.push_back(h->p[i]);
    }
    for (std::size_t k = 0; k < eq.constraints.size(); ++k) {
        const std::string& name = eq.constraints[k].name;
        // The Hamiltonian's own multipliers where it is given: its equations hold them (ṗ = −∂H/∂q + Aᵀλ).
        m.lambda.push_back(h && k < h->lambda.size() ? h->lambda[k] : GiNaC::symbol("lambda_" + name));
        m.table.info.push_back({codegen::SymbolKind::Constant, int(k + 1), "lambda_" + name, "lambda_" + name,
                                "\\lambda_{\\text{" + latex_text(name) + "}}", ""});
        m.table.exprs.push_back(m.lambda.back());
    }
    return m;
}

std::vector<LatexBlock> latex_equations(const Model& model, const Equations& eq) {
    const Hamiltonian ham = derive_hamiltonian(model, eq);
    MultiplierTable mt = multiplier_table(model, eq, &ham);
    codegen::MathPrinter pr(mt.table);
    const trig::Hints hints = trig::model_hints(model);
    pr.prefer_angles(hints.angles);
    auto P = [&pr, &hints](const GiNaC::ex& e) {
        return pr.print(trig::readable(e, hints), codegen::MathStyle::Latex);
    };
    const std::size_t n = model.dof();
    std::vector<LatexBlock> blocks;

    LatexBlock energies{"energies and the Lagrangian", {}, {}};
    add(energies, "T &= " + P(eq.T));
    add(energies, "V &= " + P(eq.V));
    add(energies, "L &= " + P(eq.L));
    blocks.push_back(std::move(energies));

    if (!eq.bodies.empty() || !eq.springs.empty()) {
        LatexBlock shares{"each body's and spring's share", {}, {}};
        for (const BodyEnergy& b : eq.bodies) {
            add(shares, "T_{\\text{" + latex_text(b.name) + "}} &= " + P(b.T));
            add(shares, "V_{\\text{" + latex_text(b.name) + "}} &= " + P(b.V));
        }
        for (const SpringEnergy& sp : eq.springs) add(shares, "V_{\\text{" + latex_text(sp.name) + "}} &= " + P(sp.V));
        blocks.push_back(std::move(shares));
    }
    for (const Body& body : model.bodies) {
        const BodyDynamics d = body_dynamics(model, body);
        if (d.omega_body.is_zero_matrix()) continue;
        LatexBlock euler{"Euler's equations of " + latex_text(body.name) +
                             ": N' = I omega-dot' + omega' x I omega' (body axes, about the centre of mass)",
                         {}, {}};
        for (unsigned k = 0; k < 3; ++k) add(euler, "N'_{" + std::to_string(k + 1) + "} &= " + P(d.euler_torque(k, 0)));
        blocks.push_back(std::move(euler));
    }
    if (!eq.constraints.empty()) {
        LatexBlock constraints{"constraints, and their rows of A q'' = gamma (A over the velocities)", {}, {}};
        for (const ConstraintEquations& c : eq.constraints) {
            const bool holonomic = c.kind == ConstraintKind::Holonomic;
            const std::string name = latex_text(c.name);
            add(constraints, P(holonomic ? c.position : c.velocity) + " &= 0",
                name + (holonomic ? " (holonomic)" : " (nonholonomic)"));
            std::string row = "A_{\\text{" + name + "}} &= \\begin{pmatrix}";
            for (std::size_t i = 0; i < c.jacobian.size(); ++i) row += (i ? " & " : " ") + P(c.jacobian[i]);
            add(constraints, row + " \\end{pmatrix}");
            add(constraints, "\\gamma_{\\text{" + name + "}} &= " + P(c.gamma));
        }
        blocks.push_back(std::move(constraints));
    }
    // Euler-Lagrange equations, with Q - dR/dq' + A^T lambda on the right when forces or constraints act.
    LatexBlock lagrange{"Euler-Lagrange equations", {}, {}};
    for (std::size_t i = 0; i < n; ++i) {
        GiNaC::ex rhs = eq.generalized_forces[i];
        for (std::size_t k = 0; k < eq.constraints.size(); ++k) rhs += eq.constraints[k].jacobian[i] * mt.lambda[k];
        add(lagrange, P(eq.euler_lagrange[i]) + " &= " + P(rhs));
    }
    blocks.push_back(std::move(lagrange));

    LatexBlock mass{"mass-matrix form M(q,t) q'' = f(q,q',t), M symmetric", {}, {}};
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i; j < n; ++j)
            add(mass, "M_{" + model.coordinates[i].latex + " " + model.coordinates[j].latex + "} &= " +
                          P(eq.M(unsigned(i), unsigned(j))));
    for (std::size_t i = 0; i < n; ++i) add(mass, "f_{" + model.coordinates[i].latex + "} &= " + P(eq.f[i]));
    blocks.push_back(std::move(mass));

    LatexBlock momenta{"energy function and momenta", {}, {}};
    add(momenta, "h &= " + P(eq.energy));
    for (std::size_t i = 0; i < n; ++i) add(momenta, "p_{" + model.coordinates[i].latex + "} &= " + P(eq.momenta[i]));
    blocks.push_back(std::move(momenta));

    LatexBlock hamilton{"Hamiltonian H(q, p, t) = p q' - L and Hamilton's equations (partial derivatives at fixed p)",
                        {}, {}};
    if (ham.symbolic) {
        add(hamilton, "H &= " + P(ham.H));
        for (std::size_t i = 0; i < n; ++i) {
            const std::string& q = model.coordinates[i].latex;
            add(hamilton, "\\dot{" + q + "} &= \\frac{\\partial H}{\\partial p_{" + q + "}} = " + P(ham.qdot[i]));
            add(hamilton, "\\dot{p}_{" + q + "} &= -\\frac{\\partial H}{\\partial " + q + "}" +
                              (eq.constraints.empty() ? "" : " + (A^T \\lambda)_{" + q + "}") + " = " + P(ham.pdot[i]));
        }
    } else {
        add(hamilton, "H &= h, \\quad \\dot q = M^{-1}(p - b)", latex_text(ham.why_not_symbolic));
    }
    blocks.push_back(std::move(hamilton));

    if (!eq.conserved.empty()) {
        LatexBlock conserved{kConservedBlock, {}, {}};
        for (const ConservedQuantity& c : eq.conserved)
            add(conserved, c.latex + " &= \\text{const}", latex_text(c.reason));
        blocks.push_back(std::move(conserved));
    }
    if (!model.results.empty()) {
        LatexBlock results{"declared results", {}, {}};
        for (const Result& r : model.results)
            add(results, r.latex + " &= " + P(r.expr.expr),
                latex_text(r.name) + (r.equals.empty() ? "" : ", verified: equals " + latex_text(r.equals)));
        blocks.push_back(std::move(results));
    }
    if (!model.outputs.empty()) {
        LatexBlock outputs{"outputs", {}, {}};
        for (const DeclaredOutput& o : model.outputs)
            add(outputs, o.latex + " &= " + P(o.expr.expr),
                latex_text(o.name) + (o.unit.empty() ? "" : " [" + latex_text(o.unit) + "]"));
        blocks.push_back(std::move(outputs));
    }
    return blocks;
}

std::string latex_fragment(const Model& model, const std::vector<LatexBlock>& blocks) {
    std::string out = "% " + model.name + ": " + latex_text(model.title) +
                      (model.source.empty() ? "" : " (" + latex_text(model.source) + ")") +
                      "\n% needs \\usepackage{amsmath} (or eomgen show --latex --standalone for a whole document)\n";
    for (const LatexBlock& b : blocks) {
        out += "% " + b.title + "\n\\begin{align}\n";
        for (std::size_t i = 0; i < b.rows.size(); ++i) {
            out += b.rows[i] + (i + 1 < b.rows.size() ? " \\\\" : "");
            if (!b.notes[i].empty()) out += "  % " + b.notes[i];
            out += "\n";
        }
        out += "\\end{align}\n";
    }
    return out;
}

std::string latex_document(const Model& model, const std::string& body, const std::string& preamble_extra) {
    return "% Generated by eomgen from the model '" + model.name + "'; compile with pdflatex.\n"
           "\\documentclass[11pt]{article}\n\\usepackage[utf8]{inputenc}\n\\usepackage[T1]{fontenc}\n"
           "\\usepackage{amsmath}\n\\usepackage[margin=2cm]{geometry}\n" +
           preamble_extra + "\\allowdisplaybreaks\n\\title{" + latex_text(model.title.empty() ? model.name : model.title) +
           "}\n\\author{}\n\\date{}\n\\begin{document}\n\\maketitle\n" + body + "\\end{document}\n";
}

std::string markdown_display(const LatexBlock& block) {
    std::string inside = "\\begin{aligned}";
    for (std::size_t i = 0; i < block.rows.size(); ++i) inside += (i ? " \\\\ " : " ") + block.rows[i];
    return text::markdown_math(inside + " \\end{aligned}");
}

}  // namespace eomgen::cli
