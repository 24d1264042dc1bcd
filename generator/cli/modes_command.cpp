/** @file modes_command.cpp  `eomgen modes`: the equilibria and their normal modes as text, Markdown or JSON. */
#include "cli/modes_command.hpp"
#include "cli/model_unit_values.hpp"
#include "cli/plot.hpp"
#include "cli/steady_modes.hpp"
#include "model/dimensions.hpp"

#include "codegen/cpp_emitter.hpp"
#include "codegen/math_printer.hpp"
#include "eomgen/simulation.hpp"
#include "mechanics/lagrangian.hpp"
#include "mechanics/small_oscillations.hpp"
#include "model/model_file.hpp"
#include "output/atomic_file.hpp"
#include "text/escape.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace eomgen::cli {

namespace {

std::string number(double v) {
    if (v == 0) return "0";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string json_number(double v) { return std::isfinite(v) ? number(v) : "null"; }

std::string complex_text(std::complex<double> z) {
    const double re = std::abs(z.real()) < 1e-12 * (1 + std::abs(z.imag())) ? 0 : z.real();
    const double im = std::abs(z.imag()) < 1e-12 * (1 + std::abs(z.real())) ? 0 : z.imag();
    if (im == 0) return number(re);
    return (re == 0 ? "" : number(re) + (im < 0 ? " - " : " + ")) + (re == 0 && im < 0 ? "-" : "") +
           number(std::abs(im)) + "i";
}

/// The printer of the model's symbols and the reduced momenta.
struct Printer {
    Printer(const Model& model, const ModesResult& r) : table(codegen::symbol_table(model)) {
        int k = 0;
        for (const auto& [s, latex] : r.momentum_symbols) {
            table.info.push_back({codegen::SymbolKind::Constant, ++k, s.get_name(), s.get_name(), latex, ""});
            table.exprs.push_back(s);
        }
        printer.emplace(table);
    }
    std::string text(const GiNaC::ex& e) { return printer->print(e, codegen::MathStyle::Text); }
    std::string latex(const GiNaC::ex& e) { return printer->print(e, codegen::MathStyle::Latex); }
    codegen::SymbolTable table;
    std::optional<codegen::MathPrinter> printer;
};

std::string matrix_text(const std::vector<std::vector<double>>& m) {
    std::string s = "[";
    for (std::size_t i = 0; i < m.size(); ++i) {
        s += i ? "; " : "";
        for (std::size_t j = 0; j < m[i].size(); ++j) s += (j ? ", " : "") + number(m[i][j]);
    }
    return s + "]";
}

std::string matrix_json(const std::vector<std::vector<double>>& m) {
    std::string s = "[";
    for (std::size_t i = 0; i < m.size(); ++i) {
        s += i ? ", [" : "[";
        for (std::size_t j = 0; j < m[i].size(); ++j) s += (j ? ", " : "") + json_number(m[i][j]);
        s += "]";
    }
    return s + "]";
}


/// " rad" for a coordinate in rad, "" where it has no unit.
std::string coordinate_unit(const Model& model, const std::string& name) {
    for (const Coordinate& c : model.coordinates)
        if (c.name == name && !c.unit.empty() && c.unit != "1") return " " + c.unit;
    return "";
}

std::string format_text(const Model& model, const ModesResult& r, Printer& p) {
    std::ostringstream os;
    os << model.name << ": " << model.title << "\n";
    if (!r.reduced.empty()) {
        os << "reduced (Routh): ";
        for (std::size_t k = 0; k < r.reduced.size(); ++k)
            os << (k ? ", " : "") << r.reduced[k] << " with p_" << r.reduced[k] << " given";
        os << "\n";
    }
    os << "V_eff = " << p.text(r.V_eff) << "\n";
    if (!r.constraints.empty()) {
        os << "on the constraints:";
        for (const std::string& c : r.constraints) os << " " << c << " = 0;";
        os << " the modes are those of the motion on them\n";
    }
    if (r.equilibria.empty()) os << "\nno equilibrium\n";
    for (std::size_t k = 0; k < r.equilibria.size(); ++k) {
        const Equilibrium& e = r.equilibria[k];
        os << "\nequilibrium " << k + 1 << ":";
        for (std::size_t i = 0; i < e.q.size(); ++i) {
            os << (i ? "," : "") << " " << r.coordinates[i] << " = " << number(e.q[i]) << coordinate_unit(model, r.coordinates[i]);
            if (e.exact[i] && !GiNaC::is_a<GiNaC::numeric>(*e.exact[i])) os << " (= " << p.text(*e.exact[i]) << ")";
        }
        os << "\n  " << stability_name(e.stability);
        if (e.stability == Stability::Unstable) os << ": perturbations grow as exp(" << number(e.growth_rate) << " t)";
        for (std::size_t c = 0; c < e.multipliers.size(); ++c)
            os << "\n  multiplier lambda_" << r.constraints[c] << " = " << number(e.multipliers[c])
               << (r.multiplier_units[c].empty() ? "" : " " + r.multiplier_units[c]);
        os << "\n  M0 = " << matrix_text(e.M) << "\n  K0 = " << matrix_text(e.K)
           << (e.multipliers.empty() ? "" : "  (with the constraints' curvature: K - sum lambda_k d2g_k/dq2)") << "\n";
        if (!e.multipliers.empty()) os << "  tangent space (columns) = " << matrix_text(e.tangent) << "\n";
        if (e.gyroscopic) os << "  G0 = " << matrix_text(e.G) << "  (gyroscopic)\n";
        if (e.damped) os << "  C0 = " << matrix_text(e.C) << "  (damping)\n";
        if (!e.B.empty() && !e.B[0].empty()) os << "  A = " << matrix_text(e.A) << "\n  B = " << matrix_text(e.B) << "  (x = [q, q'], u = inputs)\n";
        if (!e.gyroscopic && !e.damped) {
            for (std::size_t m = 0; m < e.modes.size(); ++m) {
                const NormalMode& mode = e.modes[m];
                os << "  mode " << m + 1 << ": ";
                const bool si = has_declared_units(model);
                if (mode.omega2 > 0 && si)
                    os << "omega = " << number(std::sqrt(mode.omega2)) << " rad/s, period "
                       << number(2 * M_PI / std::sqrt(mode.omega2)) << " s";
                else if (mode.omega2 >= 0)
                    os << "omega = " << number(std::sqrt(mode.omega2));
                else
                    os << "grows at rate " << number(std::sqrt(-mode.omega2)) << (si ? " 1/s" : "");
                os << "  (omega^2 = " << number(mode.omega2);
                if (mode.omega2_exact && !GiNaC::is_a<GiNaC::numeric>(*mode.omega2_exact))
                    os << " = " << p.text(*mode.omega2_exact);
                os << ")  shape (";
                for (std::size_t i = 0; i < mode.shape.size(); ++i)
                    os << (i ? ", " : "") << r.coordinates[i] << ": " << number(mode.shape[i]);
                os << ")\n";
            }
        }
        os << "  eigenvalues of the first-order system:";
        for (const auto& z : e.eigenvalues) os << " " << complex_text(z) << ";";
        os << "\n";
    }
    for (const std::string& n : r.notes) os << "\nnote: " << n << "\n";
    return os.str();
}

std::string format_markdown(const Model& model, const ModesResult& r, Printer& p) {
    using text::markdown_math;
    using text::markdown_text;
    std::ostringstream md;
    md << "# Small oscillations of " << markdown_text(model.title.empty() ? model.name : model.title) << "\n\n";
    if (!r.reduced.empty()) {
        md << "Reduced by Routh's procedure over";
        for (const std::string& c : r.reduced) md << " `" << c << "`";
        md << ", with their momenta given.\n\n";
    }
    md << "$$V_{\\mathrm{eff}} = " << markdown_math(p.latex(r.V_eff)) << "$$\n";
    for (std::size_t k = 0; k < r.equilibria.size(); ++k) {
        const Equilibrium& e = r.equilibria[k];
        md << "\n## Equilibrium " << k + 1 << ": " << stability_name(e.stability) << "\n\n| coordinate | value | exact |\n|---|---|---|\n";
        for (std::size_t i = 0; i < e.q.size(); ++i)
            md << "| $" << markdown_math(r.latex[i]) << "$ | " << number(e.q[i]) << " | "
               << (e.exact[i] ? "$" + markdown_math(p.latex(*e.exact[i])) + "$" : "") << " |\n";
        if (e.stability == Stability::Unstable)
            md << "\nPerturbations grow as $e^{" << number(e.growth_rate) << " t}$.\n";
        if (!e.multipliers.empty()) {
            md << "\n| constraint | multiplier λ at rest |\n|---|---|\n";
            for (std::size_t c = 0; c < e.multipliers.size(); ++c)
                md << "| " << markdown_text(r.constraints[c]) << " | " << number(e.multipliers[c])
                   << (r.multiplier_units[c].empty() ? "" : " " + markdown_text(r.multiplier_units[c])) << " |\n";
        }
        if (!e.gyroscopic && !e.damped) {
            md << "\n| mode | ω | ω² | exact ω² | shape |\n|---|---|---|---|---|\n";
            for (std::size_t m = 0; m < e.modes.size(); ++m) {
                const NormalMode& mode = e.modes[m];
                md << "| " << m + 1 << " | " << (mode.omega2 >= 0 ? number(std::sqrt(mode.omega2)) : "–") << " | "
                   << number(mode.omega2) << " | "
                   << (mode.omega2_exact ? "$" + markdown_math(p.latex(*mode.omega2_exact)) + "$" : "") << " | ";
                for (std::size_t i = 0; i < mode.shape.size(); ++i) md << (i ? ", " : "") << number(mode.shape[i]);
                md << " |\n";
            }
        } else {
            md << "\n" << (e.gyroscopic ? "Gyroscopic" : "") << (e.gyroscopic && e.damped ? " and damping" : e.damped ? "Damping" : "")
               << " terms: the motion follows the eigenvalues of the first-order system:";
            for (const auto& z : e.eigenvalues) md << " " << complex_text(z) << ";";
            md << "\n";
        }
    }
    for (const std::string& n : r.notes) md << "\n> " << markdown_text(n) << "\n";
    return md.str();
}

std::string format_json(const Model& model, const ModesResult& r, Printer& p, const std::vector<std::string>& inputs) {
    using text::json_string;
    std::ostringstream js;
    js << "{\"model\": " << json_string(model.name) << ", \"coordinates\": [";
    for (std::size_t i = 0; i < r.coordinates.size(); ++i) js << (i ? ", " : "") << json_string(r.coordinates[i]);
    // Each coordinate's SI unit ("rad", "m"), null where the file declares none: the unit of q in "equilibria".
    js << "], \"units\": {";
    for (std::size_t i = 0; i < r.coordinates.size(); ++i) {
        const std::string u = coordinate_unit(model, r.coordinates[i]);
        js << (i ? ", " : "") << json_string(r.coordinates[i]) << ": " << (u.empty() ? "null" : json_string(u.substr(1)));
    }
    js << "}, \"multiplier_units\": {";
    for (std::size_t c = 0; c < r.constraints.size(); ++c)
        js << (c ? ", " : "") << json_string(r.constraints[c]) << ": "
           << (r.multiplier_units[c].empty() ? "null" : json_string(r.multiplier_units[c]));
    js << "}, \"reduced\": [";
    for (std::size_t i = 0; i < r.reduced.size(); ++i) js << (i ? ", " : "") << json_string(r.reduced[i]);
    js << "], \"inputs\": [";
    for (std::size_t i = 0; i < inputs.size(); ++i) js << (i ? ", " : "") << json_string(inputs[i]);
    js << "], \"constraints\": [";
    for (std::size_t i = 0; i < r.constraints.size(); ++i) js << (i ? ", " : "") << json_string(r.constraints[i]);
    js << "], \"V_eff\": " << json_string(p.latex(r.V_eff)) << ", \"equilibria\": [";
    for (std::size_t k = 0; k < r.equilibria.size(); ++k) {
        const Equilibrium& e = r.equilibria[k];
        js << (k ? ", " : "") << "{\"q\": {";
        for (std::size_t i = 0; i < e.q.size(); ++i) js << (i ? ", " : "") << json_string(r.coordinates[i]) << ": " << json_number(e.q[i]);
        js << "}, \"exact\": {";
        bool first = true;
        for (std::size_t i = 0; i < e.q.size(); ++i)
            if (e.exact[i]) {
                js << (first ? "" : ", ") << json_string(r.coordinates[i]) << ": " << json_string(p.latex(*e.exact[i]));
                first = false;
            }
        js << "}, \"stable\": " << (e.stability == Stability::Stable || e.stability == Stability::GyroscopicallyStable ? "true" : "false")
           << ", \"stability\": " << json_string(stability_name(e.stability)) << ", \"growth_rate\": " << json_number(e.growth_rate)
           << ", \"M\": " << matrix_json(e.M) << ", \"K\": " << matrix_json(e.K) << ", \"C\": " << matrix_json(e.C)
           << ", \"G\": " << matrix_json(e.G) << ", \"A\": " << matrix_json(e.A) << ", \"B\": " << matrix_json(e.B)
           << ", \"multipliers\": {";
        for (std::size_t c = 0; c < e.multipliers.size(); ++c)
            js << (c ? ", " : "") << json_string(r.constraints[c]) << ": " << json_number(e.multipliers[c]);
        js << "}, \"tangent\": " << matrix_json(e.tangent) << ", \"modes\": [";
        for (std::size_t m = 0; m < e.modes.size(); ++m) {
            const NormalMode& mode = e.modes[m];
            js << (m ? ", " : "") << "{\"omega\": " << (mode.omega2 >= 0 ? json_number(std::sqrt(mode.omega2)) : "null")
               << ", \"omega_unit\": " << (has_declared_units(model) ? "\"rad/s\"" : "null")
               << ", \"omega2\": " << json_number(mode.omega2) << ", \"omega2_exact\": "
               << (mode.omega2_exact ? json_string(p.latex(*mode.omega2_exact)) : "null") << ", \"shape\": {";
            for (std::size_t i = 0; i < mode.shape.size(); ++i)
                js << (i ? ", " : "") << json_string(r.coordinates[i]) << ": " << json_number(mode.shape[i]);
            js << "}}";
        }
        js << "], \"eigenvalues\": [";
        for (std::size_t m = 0; m < e.eigenvalues.size(); ++m)
            js << (m ? ", " : "") << "[" << json_number(e.eigenvalues[m].real()) << ", " << json_number(e.eigenvalues[m].imag()) << "]";
        js << "]}";
    }
    js << "], \"notes\": [";
    for (std::size_t i = 0; i < r.notes.size(); ++i) js << (i ? ", " : "") << json_string(r.notes[i]);
    js << "]}\n";
    return js.str();
}

/// A motion of the model file ([[motions]]) usable as a steady motion: its conditions all give velocities, in the
/// parameters only (no constants of the motion, no coordinates, no t).
bool steady_capable(const Model& model, const Motion& m) {
    if (!m.constants.empty() || m.conditions.empty()) return false;
    for (const MotionCondition& c : m.conditions) {
        if (!c.velocity || c.value.expr.has(model.t)) return false;
        for (const Coordinate& q : model.coordinates)
            if (c.value.expr.has(q.q) || c.value.expr.has(q.qd)) return false;
    }
    return true;
}

/// The rates of the steady motion `name` declares (--motion), or, without --motion, of the first steady-capable
/// motion of a nonholonomic model (whose equilibria are not isolated: a bicycle, a rolling coin); its name, or ""
/// when none is used.
std::string declared_steady_motion(const Model& model, const std::string& name, std::vector<std::string>& rates) {
    const bool nonholonomic = std::any_of(model.constraints.begin(), model.constraints.end(),
                                          [](const Constraint& c) { return c.kind == ConstraintKind::Nonholonomic; });
    for (const Motion& m : model.motions) {
        if (!name.empty() ? m.name != name : !nonholonomic || !steady_capable(model, m)) continue;
        if (!steady_capable(model, m))
            throw ModesError("--motion " + name + ": a steady motion gives rates only (\"q' = expression in the parameters\"), "
                             "and '" + m.name + "' has other conditions");
        for (const MotionCondition& c : m.conditions) {
            const std::size_t a = c.value.text.find_first_not_of(' '), b = c.value.text.find_last_not_of(' ');
            rates.push_back(model.coordinates[c.coordinate].name + "_dot=" +
                            (a == std::string::npos ? c.value.text : c.value.text.substr(a, b - a + 1)));
        }
        return m.name;
    }
    if (!name.empty()) throw ModesError("--motion " + name + ": the model declares no [[motions]] of that name");
    return "";
}

std::pair<std::string, double> assignment(const std::string& text, const char* option) {
    try {
        return eomgen::sim::parse_assignment(text, option);
    } catch (const eomgen::sim::UsageError& e) {
        throw ModesError(e.what());
    }
}

}  // namespace

std::string modes_markdown(const Model& model, const ModesResult& result) {
    Printer printer(model, result);
    return format_markdown(model, result, printer);
}

std::vector<std::string> modes_summary(const Model& model, const ModesResult& r) {
    const std::string per_second = has_declared_units(model) ? " 1/s" : "", rad_per_second = has_declared_units(model) ? " rad/s" : "";
    std::vector<std::string> lines;
    for (const Equilibrium& e : r.equilibria) {
        std::string line;
        for (std::size_t i = 0; i < e.q.size(); ++i)
            line += (i ? ", " : "") + r.coordinates[i] + " = " + number(e.q[i]) + coordinate_unit(model, r.coordinates[i]);
        for (std::size_t c = 0; c < e.multipliers.size(); ++c)
            line += (c ? ", " : " (") + std::string("lambda_") + r.constraints[c] + " = " + number(e.multipliers[c]) +
                    (r.multiplier_units[c].empty() ? "" : " " + r.multiplier_units[c]) +
                    (c + 1 == e.multipliers.size() ? ")" : "");
        line += std::string(": ") + stability_name(e.stability);
        if (e.stability == Stability::Unstable) line += ", growth rate " + number(e.growth_rate) + per_second;
        if (!e.gyroscopic && !e.damped) {
            line += "; omega =";
            for (std::size_t m = 0; m < e.modes.size(); ++m)
                line += (m ? ", " : " ") + (e.modes[m].omega2 >= 0 ? number(std::sqrt(e.modes[m].omega2))
                                                                   : "i " + number(std::sqrt(-e.modes[m].omega2)));
            if (!e.modes.empty()) line += rad_per_second;
        }
        lines.push_back(line);
    }
    return lines;
}

std::string modes_show_section(const Model& model, const Equations& eq) {
    // A scan with many coordinates can take seconds: show stays quick, modes is there for more.
    constexpr std::size_t kMaxCoordinates = 8;
    if (model.dof() > kMaxCoordinates)
        return "  " + std::to_string(model.dof()) + " coordinates: run `eomgen modes` for the equilibria\n";
    try {
        const ModesResult result = small_oscillations(model, eq, {});
        std::string out;
        for (const std::string& line : modes_summary(model, result)) out += "  " + line + "\n";
        for (const std::string& note : result.notes) out += "  note: " + note + "\n";
        return out.empty() ? "  none found\n" : out;
    } catch (const ModesError& e) {
        return "  none: " + std::string(e.what()) + "\n";
    }
}

ModesCommand::ModesCommand(CLI::App& app) {
    command_ = app.add_subcommand("modes", "Equilibria, linearization, normal modes and stability (small oscillations)");
    command_->add_option("model", model_, "Model file (.toml)")->required()->check(CLI::ExistingFile);
    command_->add_option("--set", set_, "Parameter value, NAME=VALUE (repeatable)");
    command_->add_option("--at", at_, "A starting guess, q=v[,q2=v...] (repeatable; coordinates not named start "
                                      "at the model's initial values)");
    command_->add_option("--momentum", momentum_, "Reduce a cyclic coordinate q with its momentum given, p_q=VALUE "
                                                  "(Routh; repeatable), e.g. a top's p_phi and p_psi");
    command_->add_option("--input", inputs_, "A parameter taken as a control input u (e.g. a torque in [forces]): "
                                             "B of x' = A x + B u (repeatable)");
    command_->add_option("--format", format_, "text, markdown or json")
        ->check(CLI::IsMember({"text", "markdown", "json"}))
        ->capture_default_str();
    command_->add_option("-o,--output", output_, "Write to FILE instead of standard output");
    command_->add_option("--steady", steady_, "About a steady motion: the rate of a coordinate the equations do not "
                                              "depend on, NAME_dot=EXPR in the parameters (repeatable), e.g. "
                                              "thetaR_dot=-v/rR; the other such rates and the other coordinates are found");
    command_->add_option("--motion", motion_, "About a steady motion the model file declares ([[motions]] whose "
                                              "conditions give rates, q' = EXPR); a nonholonomic model's first one is "
                                              "used without --steady or --motion");
    command_->add_option("--speed", speed_, "With --steady: split C = P C1 and K = g K0 + P^2 K2 by this parameter "
                                            "(default: the one parameter of --steady the equations do not hold, v in -v/rR)");
    command_->add_option("--sweep", sweep_, "With --steady: eigenvalues against a parameter, NAME=START:STOP:COUNT, and "
                                            "the values where the stability changes");
    command_->add_option("--plot", plot_, "With --sweep: the eigenvalues' real and imaginary parts against the "
                                          "parameter (root locus), FILE.png or FILE.svg (gnuplot)");
}

bool ModesCommand::selected() const { return command_->parsed(); }

int ModesCommand::run() const {
    const Model model = load_model(model_);
    const Equations eq = derive_equations(model);
    ModesOptions options;
    ModesResult result;
    std::string steady;  // the report about a steady motion (--steady), else empty
    try {
        for (const std::string& s : set_) {
            try {  // a bare number in the parameter's declared unit, or with its own ("45 deg")
                options.set.insert(assignment(assignment_in_si(declared_units(model), s, false, "--set"), "--set"));
            } catch (const std::invalid_argument& e) {
                throw ModesError(e.what());
            }
        }
        for (const std::string& s : momentum_) options.momentum.insert(assignment(s, "--momentum"));
        for (const std::string& guess : at_) {
            std::map<std::string, double> g;
            std::istringstream parts(guess);
            for (std::string part; std::getline(parts, part, ',');) g.insert(assignment(part, "--at"));
            options.at.push_back(g);
        }
        options.inputs = inputs_;
        std::vector<std::string> steady_rates = steady_;
        std::string from_motion;
        if (steady_rates.empty()) from_motion = declared_steady_motion(model, motion_, steady_rates);
        if (!steady_rates.empty() || !sweep_.empty() || !speed_.empty() || !plot_.empty()) {
            if (steady_rates.empty())
                throw ModesError("--speed and --sweep go with --steady NAME_dot=EXPR (or --motion NAME)");
            if (format_ == "markdown") throw ModesError("--steady writes text or json");
            if (!momentum_.empty() || !inputs_.empty()) throw ModesError("--momentum and --input do not go with --steady");
            SteadyRequest request;
            request.steady = steady_rates;
            request.motion = from_motion;
            request.set = options.set;
            for (const auto& g : options.at) request.at.insert(g.begin(), g.end());
            request.speed = speed_;
            request.sweep = sweep_;
            request.plot = plot_;
            if (!plot_.empty() && !plot_format_problem(plot_).empty()) throw ModesError("--plot: " + plot_format_problem(plot_));
            request.format = format_;
            steady = steady_modes(model, eq, request);
        } else {
            result = small_oscillations(model, eq, options);
        }
    } catch (const ModesError& e) {
        std::cerr << "eomgen modes: " << e.what() << "\n";
        return 2;
    }
    Printer printer(model, result);
    const std::string out = !steady.empty()         ? steady
                            : format_ == "json"     ? format_json(model, result, printer, inputs_)
                            : format_ == "markdown" ? format_markdown(model, result, printer)
                                                    : format_text(model, result, printer);
    if (output_.empty()) {
        std::cout << out;
        return 0;
    }
    try {
        output::write_atomically(output_, out);
    } catch (const output::WriteError& e) {
        std::cerr << "eomgen modes: " << e.what() << "\n";
        return 3;
    }
    return 0;
}

}  // namespace eomgen::cli
