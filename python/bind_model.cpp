/** @file bind_model.cpp  The model and its mechanics for Python (binding.hpp): the file's description, the equations
 * as text and LaTeX, equilibria and modes, a derivation checked. */
#include "binding.hpp"

#include "checker/checker.hpp"
#include "checker/derivation.hpp"
#include "checker/report.hpp"
#include "cli/latex_equations.hpp"
#include "cli/model_unit_values.hpp"
#include "cli/show_text.hpp"
#include "codegen/math_printer.hpp"
#include "mechanics/small_oscillations.hpp"

#include <pybind11/complex.h>

#include <complex>
#include <sstream>

namespace eomgen::python {

py::dict describe(const LoadedModel& m) {
    const Model& model = m.model();
    py::dict d;
    d["name"] = model.name;
    d["title"] = model.title;
    d["source"] = model.source;
    d["path"] = m.path();
    py::list coordinates, parameters, outputs, constraints;
    for (const Coordinate& c : model.coordinates) {
        py::dict e;
        e["name"] = c.name;
        e["latex"] = c.latex;
        e["unit"] = c.unit;
        e["initial"] = c.initial;
        e["rate"] = c.rate;
        e["description"] = c.description;
        coordinates.append(e);
    }
    for (const Parameter& p : model.parameters) {
        py::dict e;
        e["name"] = p.name;
        e["latex"] = p.latex;
        e["unit"] = p.unit;
        e["value"] = p.value;
        e["description"] = p.description;
        parameters.append(e);
    }
    for (const DeclaredOutput& o : model.outputs) outputs.append(o.name);
    for (const auto& c : model.constraints) constraints.append(c.name);
    d["coordinates"] = coordinates;
    d["parameters"] = parameters;
    d["outputs"] = outputs;
    d["constraints"] = constraints;
    return d;
}

py::dict equations(LoadedModel& m) {
    const cli::EquationsText e = cli::equations_text(m.model(), m.equations());
    py::dict d;
    d["T"] = e.T;
    d["V"] = e.V;
    d["L"] = e.L;
    d["h"] = e.h;
    d["euler_lagrange"] = e.euler_lagrange;
    d["forces"] = e.forces;
    d["M"] = e.M;
    d["f"] = e.f;
    d["momenta"] = e.momenta;
    d["warnings"] = m.equations().warnings;
    return d;
}

std::string show(LoadedModel& m) {
    std::ostringstream os;
    cli::show_text(m.model(), m.equations(), os);
    return os.str();
}

/// The LaTeX of `show --latex` (align environments) and, for a notebook, one `$$ \begin{aligned} … $$` display per
/// block under its title.
py::tuple latex(LoadedModel& m) {
    const std::vector<cli::LatexBlock> blocks = cli::latex_equations(m.model(), m.equations());
    std::string displays;
    for (const cli::LatexBlock& b : blocks)
        displays += "$$\\textbf{" + b.title + "}$$\n" + cli::markdown_display(b) + "\n";
    return py::make_tuple(cli::latex_fragment(m.model(), blocks), displays);
}

/// NAME=VALUE assignments (a number in the declared unit, or with its own) as NAME -> SI value.
std::map<std::string, double> si_map(const LoadedModel& m, const std::vector<std::string>& assignments, bool state,
                                     const char* what) {
    std::map<std::string, double> out;
    for (const std::string& a : assignments) {
        std::string si;
        try {
            si = cli::assignment_in_si(cli::declared_units(m.model()), a, state, what);
        } catch (const std::invalid_argument& e) {
            throw sim::UsageError(e.what());
        }
        out.insert(sim::parse_assignment(si, what));
    }
    return out;
}

py::array_t<double> matrix(const std::vector<std::vector<double>>& rows) {
    const std::size_t r = rows.size(), c = r ? rows[0].size() : 0;
    std::vector<double> flat;
    for (const auto& row : rows) flat.insert(flat.end(), row.begin(), row.end());
    return matrix(flat, r, c);
}

/// `eomgen modes`: the equilibria (exact where found), the linearization about each (M, K, C, G, A, B), the normal
/// modes and eigenvalues, the stability; exact values printed in the model file's language.
py::dict modes(LoadedModel& m, const std::vector<std::string>& set, const std::vector<std::vector<std::string>>& at,
               const std::vector<std::string>& momentum, const std::vector<std::string>& inputs) {
    ModesOptions options;
    options.set = si_map(m, set, false, "set");
    for (const auto& guess : at) options.at.push_back(si_map(m, guess, true, "at"));
    for (const std::string& p : momentum) options.momentum.insert(sim::parse_assignment(p, "momentum"));  // SI
    options.inputs = inputs;
    ModesResult r;
    try {
        r = small_oscillations(m.model(), m.equations(), options);
    } catch (const ModesError& e) {
        throw sim::UsageError(e.what());
    }
    codegen::SymbolTable table = codegen::symbol_table(m.model());
    int k = 0;
    for (const auto& [symbol, latex] : r.momentum_symbols) {
        table.info.push_back({codegen::SymbolKind::Constant, ++k, symbol.get_name(), symbol.get_name(), latex, ""});
        table.exprs.push_back(symbol);
    }
    codegen::MathPrinter printer(table);
    auto text = [&printer](const std::optional<GiNaC::ex>& e) -> py::object {
        if (!e) return py::none();
        return py::str(printer.print(*e, codegen::MathStyle::Text));
    };
    py::list equilibria;
    for (const Equilibrium& e : r.equilibria) {
        py::dict d;
        d["q"] = e.q;
        py::list exact;
        for (const auto& x : e.exact) exact.append(text(x));
        d["exact"] = exact;
        d["M"] = matrix(e.M);
        d["K"] = matrix(e.K);
        d["C"] = matrix(e.C);
        d["G"] = matrix(e.G);
        d["A"] = matrix(e.A);
        d["B"] = matrix(e.B);
        d["multipliers"] = e.multipliers;
        d["tangent"] = matrix(e.tangent);
        py::list normal_modes;
        for (const NormalMode& mode : e.modes) normal_modes.append(py::make_tuple(mode.omega2, text(mode.omega2_exact), mode.shape));
        d["modes"] = normal_modes;
        d["eigenvalues"] = e.eigenvalues;
        d["stability"] = std::string(stability_name(e.stability));
        d["growth_rate"] = e.growth_rate;
        d["gyroscopic"] = e.gyroscopic;
        d["damped"] = e.damped;
        equilibria.append(d);
    }
    py::dict d;
    d["coordinates"] = r.coordinates;
    d["reduced"] = r.reduced;
    d["constraints"] = r.constraints;
    d["V_eff"] = printer.print(r.V_eff, codegen::MathStyle::Text);
    d["equilibria"] = equilibria;
    d["notes"] = r.notes;
    return d;
}

py::dict check(LoadedModel& m, const std::string& text, const std::string& path,
               const std::vector<std::string>& sections, const std::vector<std::pair<std::string, double>>& set) {
    const checker::Derivation derivation = checker::parse_derivation(text, path);
    checker::CheckOptions options;
    options.sections = sections;
    options.set = set;
    checker::CheckReport report = checker::check_derivation(m.model(), m.equations(), derivation, options);
    report.model_path = m.path();
    report.model_title = m.model().title;
    report.derivation_path = path;
    py::list rows;
    for (const checker::EquationCheck& c : report.equations) {
        py::dict r;
        r["verdict"] = std::string(checker::verdict_name(c.verdict));
        r["role"] = std::string(checker::role_name(c.role));
        r["line"] = c.where.line;
        r["column"] = c.where.column;
        r["section"] = c.section;
        r["equation"] = c.equation;
        r["compared_with"] = c.compared_with;
        r["reason"] = c.reason;
        r["difference"] = c.difference;
        r["wrong_terms"] = c.wrong_terms;
        r["corrected"] = c.corrected;
        r["notes"] = c.notes;
        rows.append(r);
    }
    py::list problems;
    for (const auto& p : report.problems)
        problems.append(py::make_tuple(p.where.line, p.where.column, p.message));
    py::dict d;
    d["equations"] = rows;
    d["problems"] = problems;
    d["text"] = checker::format_text(report);
    d["markdown"] = checker::format_markdown(report);
    d["json"] = checker::format_json(report);
    return d;
}

}  // namespace eomgen::python
