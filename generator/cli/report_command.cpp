/** @file report_command.cpp  `eomgen report`: model, equations, a simulation with its drift, checked derivations. */
#include "cli/report_command.hpp"
#include "table_driver.hpp"  // the driver for TableModel, compiled once

#include "checker/checker.hpp"
#include "checker/derivation.hpp"
#include "checker/report.hpp"
#include "cli/compiled_model.hpp"
#include "cli/model_functions.hpp"
#include "cli/latex_equations.hpp"
#include "cli/modes_command.hpp"
#include "cli/animate.hpp"
#include "cli/capture.hpp"
#include "cli/plot.hpp"
#include "output/sample_table.hpp"
#include "cli/model_unit_values.hpp"
#include "cli/process.hpp"
#include "cli/run_command.hpp"
#include "codegen/cpp_emitter.hpp"
#include "eomgen/model_table.hpp"
#include "mechanics/small_oscillations.hpp"
#include "model/model_file.hpp"
#include "options.hpp"
#include "output/atomic_file.hpp"
#include "text/escape.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include <unistd.h>

#ifndef EOMGEN_VERSION
#define EOMGEN_VERSION "0.0.0"
#endif

namespace eomgen::cli {
namespace fs = std::filesystem;

namespace {

/// How an invariant held along the simulation, from its CSV column.
struct Drift {
    std::string name;   ///< the CSV column: energy, p_phi, ...
    std::string latex;  ///< its symbol: h, p_{\phi}
    double initial = 0, worst = 0;
    bool relative = true;  ///< |c − c0|/|c0|, or absolute where c0 is (nearly) 0
    bool conserved = true;  ///< false for h of a model whose L depends on t, or that forces act on
};

struct Simulation {
    bool ran = false;
    int code = 0;
    std::string summary, errors;  ///< what the driver printed on stdout and stderr
    std::string csv, plot;         ///< file names in the report's directory ("" when not written)
    std::string animation;         ///< the page that plays the run, where the model has a drawing ("" else)
    std::vector<Drift> drifts;
    std::vector<std::pair<std::string, double>> residuals;  ///< constraint, largest residual
};


void measure(const Model& model, const Equations& eq, Simulation& sim, const fs::path& csv) {
    // The headers carry units ("energy [J]"), which the table takes off: a model with units has its drift too.
    output::SampleTable table;
    try {
        table = output::read_sample_table(csv.string());
    } catch (const std::runtime_error&) {
        return;
    }
    const std::vector<std::vector<double>>& rows = table.rows;
    if (rows.empty()) return;
    auto column = [&](const std::string& name) { return table.column(name); };
    auto drift_of = [&](const std::string& name, const std::string& latex, bool conserved) {
        const int j = column(name);
        if (j < 0) return;
        Drift d{name, latex, rows.front()[std::size_t(j)], 0, true, conserved};
        d.relative = std::abs(d.initial) >= 1e-12;
        for (const auto& row : rows) {
            const double change = std::abs(row[std::size_t(j)] - d.initial);
            d.worst = std::max(d.worst, d.relative ? change / std::abs(d.initial) : change);
        }
        sim.drifts.push_back(d);
    };
    const bool h_conserved = std::any_of(eq.conserved.begin(), eq.conserved.end(),
                                         [](const ConservedQuantity& c) { return c.name == "h"; });
    drift_of("energy", "h", h_conserved);
    for (const ConservedQuantity& c : eq.conserved)
        if (c.name != "h") drift_of(c.name, c.latex, true);
    for (const Constraint& c : model.constraints) {
        const int j = column("residual_" + c.name);
        if (j < 0) continue;
        double worst = 0;
        for (const auto& row : rows) worst = std::max(worst, std::abs(row[std::size_t(j)]));
        sim.residuals.emplace_back(c.name, worst);
    }
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

/// The lines of `s` (line breaks of any kind end a line), for writing text as a code block or verbatim.
std::vector<std::string> lines_of(const std::string& s) {
    std::vector<std::string> lines;
    std::string line;
    for (const char c : s) {
        if (c == '\n' || c == '\r' || c == '\v' || c == '\f') {
            lines.push_back(line);
            line.clear();
        } else {
            line += c;
        }
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

struct Checked {
    std::string path;
    checker::CheckReport report;
};

/// The small oscillations (mechanics/small_oscillations.hpp) at the report's parameter values, or why not.
struct Modes {
    std::optional<ModesResult> result;
    std::string why_not;
};

Modes small_oscillations_of(const Model& model, const Equations& eq, const sim::Options& o) {
    Modes m;
    try {
        ModesOptions options;
        for (const std::string& s : o.set)
            options.set.insert(sim::parse_assignment(assignment_in_si(declared_units(model), s, false, "--set"), "--set"));
        m.result = small_oscillations(model, eq, options);
    } catch (const std::exception& e) {
        m.why_not = e.what();
    }
    return m;
}

// ---------------------------------------------------------------- Markdown

std::string markdown(const Model& model, const Equations& eq, const std::vector<LatexBlock>& blocks,
                     const Simulation& sim, const std::vector<Checked>& checks, const sim::Options& o,
                     const Modes& modes) {
    using text::markdown_math;
    using text::markdown_text;
    std::ostringstream md;
    md << "# " << markdown_text(model.title.empty() ? model.name : model.title) << "\n\n";
    md << "Model `" << model.name << "`" << (model.source.empty() ? "" : ", " + markdown_text(model.source))
       << ". Report written by eomgen " << EOMGEN_VERSION << " from " << markdown_text(fs::path(model.path).filename().string())
       << ".\n\n";
    if (!model.description.empty()) md << markdown_text(model.description) << "\n\n";

    md << "## Model\n\n| coordinate | | q(0) | q̇(0) |\n|---|---|---|---|\n";
    for (const Coordinate& c : model.coordinates)
        md << "| `" << c.name << "` | $" << markdown_math(c.latex) << "$ | " << codegen::shortest_decimal(c.initial)
           << (c.unit.empty() || c.unit == "1" ? "" : " " + markdown_text(c.unit)) << " | "
           << codegen::shortest_decimal(c.rate)
           << (c.unit.empty() ? "" : " " + markdown_text(c.unit == "1" ? "1/s" : c.unit + "/s")) << " |\n";
    if (!model.parameters.empty()) {
        md << "\n| parameter | | value | unit | description |\n|---|---|---|---|---|\n";
        for (const Parameter& p : model.parameters)
            md << "| `" << p.name << "` | $" << markdown_math(p.latex) << "$ | " << codegen::shortest_decimal(p.value)
               << (p.given.empty() ? "" : " (given as " + markdown_text(p.given) + ")") << " | "
               << markdown_text(p.unit) << " | " << markdown_text(p.description) << " |\n";
    }
    md << "\n## Equations\n\nDerived by eomgen (the same as `eomgen show --latex`).\n\n";
    for (const LatexBlock& b : blocks) {
        if (b.title == kConservedBlock) continue;  // listed below with the reasons
        md << "**" << markdown_text(b.title) << "**\n\n$$" << markdown_display(b) << "$$\n\n";
    }
    md << "## Conserved quantities\n\n";
    if (eq.conserved.empty()) md << "None found.\n";
    for (const ConservedQuantity& c : eq.conserved)
        md << "- $" << markdown_math(c.latex) << "$: " << markdown_text(c.reason) << "\n";
    if (!eq.warnings.empty()) {
        md << "\n## Warnings\n\n";
        for (const std::string& w : eq.warnings) md << "- " << markdown_text(w) << "\n";
    }
    md << "\n## Simulation\n\n";
    if (!sim.ran) {
        md << "Not run (`--no-simulation`).\n";
    } else {
        md << "From the model's initial state" << (o.set.empty() && o.init.empty() ? "" : " with the options below")
           << " to t = " << o.t_end << ", method " << markdown_text(o.method)
           << (eomgen::sim::takes_tolerances(o.method) ? ", rtol " + number(o.rtol) + ", atol " + number(o.atol) : "") << ".";
        if (sim.code != 0) md << " **The simulation failed**:";
        md << "\n\n";
        for (const std::string& line : lines_of(sim.summary + sim.errors)) md << "    " << line << "\n";
        if (!sim.drifts.empty()) {
            md << "\n| invariant | at t = 0 | largest change along the run |\n|---|---|---|\n";
            for (const Drift& d : sim.drifts)
                md << "| $" << markdown_math(d.latex) << "$ | " << number(d.initial) << " | " << number(d.worst)
                   << (d.relative ? " (relative)" : " (absolute: it starts at 0)")
                   << (d.conserved ? "" : "; not conserved by this model") << " |\n";
        }
        if (!sim.residuals.empty()) {
            md << "\n| constraint | largest residual after projection |\n|---|---|\n";
            for (const auto& [name, worst] : sim.residuals)
                md << "| " << markdown_text(name) << " | " << number(worst) << " |\n";
        }
        if (!sim.plot.empty()) md << "\n![coordinates, invariants and residuals against t](" << sim.plot << ")\n";
        if (!sim.animation.empty())
            md << "\nThe motion, to play in a browser: [" << sim.animation << "](" << sim.animation << ").\n";
        if (!sim.csv.empty()) md << "\nSamples: [" << sim.csv << "](" << sim.csv << ").\n";
    }
    md << "\n## Small oscillations\n\n";
    if (!modes.result) {
        md << "Not computed: " << markdown_text(modes.why_not) << "\n";
    } else {
        md << "Equilibria, their stability and normal modes (`eomgen modes`, docs/modes.md).\n\n";
        for (const std::string& line : lines_of(modes_markdown(model, *modes.result)))
            if (line.rfind("# ", 0) != 0) md << (line.rfind('#', 0) == 0 ? "#" + line : line) << "\n";
    }
    for (const Checked& c : checks) {
        md << "\n## Derivation " << markdown_text(fs::path(c.path).filename().string()) << "\n\n";
        // The checker's own Markdown (its headings one level down, under this one).
        for (const std::string& line : lines_of(checker::format_markdown(c.report)))
            md << (line.rfind('#', 0) == 0 ? "##" + line : line) << "\n";
    }
    return md.str();
}

// ---------------------------------------------------------------- LaTeX

std::string latex(const Model& model, const Equations& eq, const std::vector<LatexBlock>& blocks,
                  const Simulation& sim, const std::vector<Checked>& checks, const sim::Options& o,
                  const Modes& modes) {
    using text::latex_text;
    std::ostringstream tex;
    tex << "Model \\texttt{" << latex_text(model.name) << "}"
        << (model.source.empty() ? "" : ", " + latex_text(model.source)) << ". Report written by eomgen "
        << EOMGEN_VERSION << ".\n\n";
    if (!model.description.empty()) tex << latex_text(model.description) << "\n\n";
    tex << "\\section*{Model}\n\\begin{tabular}{llrr}\ncoordinate & & $q(0)$ & $\\dot q(0)$ \\\\ \\hline\n";
    for (const Coordinate& c : model.coordinates)
        tex << "\\texttt{" << latex_text(c.name) << "} & $" << c.latex << "$ & " << codegen::shortest_decimal(c.initial)
            << " & " << codegen::shortest_decimal(c.rate) << " \\\\\n";
    tex << "\\end{tabular}\n\n";
    if (!model.parameters.empty()) {
        tex << "\\begin{tabular}{llrll}\nparameter & & value & unit & description \\\\ \\hline\n";
        for (const Parameter& p : model.parameters)
            tex << "\\texttt{" << latex_text(p.name) << "} & $" << p.latex << "$ & " << codegen::shortest_decimal(p.value)
                << (p.given.empty() ? "" : " (given as " + latex_text(p.given) + ")") << " & " << latex_text(p.unit) << " & " << latex_text(p.description) << " \\\\\n";
        tex << "\\end{tabular}\n";
    }
    tex << "\\section*{Equations}\n";
    for (const LatexBlock& b : blocks) {
        if (b.title == kConservedBlock) continue;  // listed below with the reasons
        tex << "\\paragraph{" << latex_text(b.title) << "}\n\\begin{align}\n";
        for (std::size_t i = 0; i < b.rows.size(); ++i)
            tex << b.rows[i] << (b.notes[i].empty() ? "" : " && \\text{" + b.notes[i] + "}")
                << (i + 1 < b.rows.size() ? " \\\\" : "") << "\n";
        tex << "\\end{align}\n";
    }
    tex << "\\section*{Conserved quantities}\n";
    if (eq.conserved.empty()) tex << "None found.\n";
    else {
        tex << "\\begin{itemize}\n";
        for (const ConservedQuantity& c : eq.conserved) tex << "\\item $" << c.latex << "$: " << latex_text(c.reason) << "\n";
        tex << "\\end{itemize}\n";
    }
    if (!eq.warnings.empty()) {
        tex << "\\section*{Warnings}\n\\begin{itemize}\n";
        for (const std::string& w : eq.warnings) tex << "\\item " << latex_text(w) << "\n";
        tex << "\\end{itemize}\n";
    }
    tex << "\\section*{Simulation}\n";
    if (!sim.ran) {
        tex << "Not run.\n";
    } else {
        tex << "From the model's initial state to $t = " << o.t_end << "$, method " << latex_text(o.method) << ".";
        if (sim.code != 0) tex << " \\textbf{The simulation failed}:";
        tex << "\n\n{\\small\\noindent";
        for (const std::string& line : lines_of(sim.summary + sim.errors))
            tex << "\\texttt{" << latex_text(line) << "}\\\\\n";
        tex << "}\n";
        if (!sim.drifts.empty()) {
            tex << "\n\\begin{tabular}{lll}\ninvariant & at $t = 0$ & largest change \\\\ \\hline\n";
            for (const Drift& d : sim.drifts)
                tex << "$" << d.latex << "$ & " << latex_text(number(d.initial)) << " & " << latex_text(number(d.worst))
                    << (d.relative ? " (relative)" : " (absolute)") << (d.conserved ? "" : ", not conserved") << " \\\\\n";
            tex << "\\end{tabular}\n";
        }
        if (!sim.residuals.empty()) {
            tex << "\n\\begin{tabular}{ll}\nconstraint & largest residual \\\\ \\hline\n";
            for (const auto& [name, worst] : sim.residuals)
                tex << latex_text(name) << " & " << latex_text(number(worst)) << " \\\\\n";
            tex << "\\end{tabular}\n";
        }
        if (!sim.plot.empty())
            tex << "\n\\begin{center}\\includegraphics[width=\\textwidth]{" << latex_text(sim.plot) << "}\\end{center}\n";
        if (!sim.animation.empty())
            tex << "\nThe motion, to play in a browser: \\texttt{" << latex_text(sim.animation) << "}, beside this file.\n";
    }
    tex << "\\section*{Small oscillations}\n";
    if (!modes.result) {
        tex << "Not computed: " << latex_text(modes.why_not) << "\n";
    } else {
        tex << "\\begin{itemize}\n";
        for (const std::string& line : modes_summary(model, *modes.result)) tex << "\\item " << latex_text(line) << "\n";
        if (modes.result->equilibria.empty()) tex << "\\item no equilibrium found\n";
        tex << "\\end{itemize}\n";
    }
    // A derivation's text is a stranger's LaTeX: shown as escaped text here, never compiled.
    for (const Checked& c : checks) {
        tex << "\\section*{Derivation " << latex_text(fs::path(c.path).filename().string()) << "}\n";
        tex << latex_text(checker::summary_line(c.report)) << ".\n";
        tex << "\\begin{itemize}\n";
        for (const checker::EquationCheck& e : c.report.equations) {
            tex << "\\item line " << e.where.line << ": \\textbf{" << latex_text(checker::verdict_shown(e)) << "} \\texttt{"
                << latex_text(e.equation) << "}";
            if (e.verdict == checker::Verdict::Disagrees && !e.corrected.empty())
                tex << "; corrected: \\texttt{" << latex_text(e.corrected) << "}";
            else if (!e.reason.empty())
                tex << " (" << latex_text(e.reason) << ")";
            tex << "\n";
        }
        tex << "\\end{itemize}\n";
    }
    return latex_document(model, tex.str(), "\\usepackage{graphicx}\n");
}

}  // namespace

ReportCommand::ReportCommand(CLI::App& app) {
    report_ = app.add_subcommand("report", "Write one document about a model: equations, a simulation with its "
                                           "plot and drift, checked derivations");
    report_->add_option("model", model_path_, "Model file (.toml)")->required()->check(CLI::ExistingFile);
    report_->add_option("-o,--output", out_dir_, "Directory for the report and its files (default <name>-report)");
    report_->add_option("--derivation", derivations_, "A derivation (Markdown + LaTeX) to check; may be repeated")
        ->check(CLI::ExistingFile);
    report_->add_option("--format", format_, "markdown (<name>.md) or latex (<name>.tex, a complete document)")
        ->check(CLI::IsMember({"markdown", "latex"}))
        ->capture_default_str();
    eomgen::sim::add_options(*report_, options_);
    report_->remove_option(report_->get_option("--csv"));  // the report writes its own, beside itself
    report_->add_flag("--no-simulation", no_simulation_, "Leave the simulation out (no compiler needed)");
    report_->add_flag("--no-cache", no_cache_, "Compile afresh and keep nothing in the cache");
    report_->add_flag("--interpret", interpret_,
                      "Simulate on eomgen's interpreter instead of compiling the model (as eomgen run --interpret)");
    report_->add_flag("--quiet", quiet_, "No progress messages on stderr");
    report_->add_flag("--progress", progress_, "Progress messages on stderr even when it is not a terminal");
}

bool ReportCommand::selected() const { return report_->parsed(); }

int ReportCommand::run() {
    const bool show_progress = !quiet_ && (progress_ || ::isatty(STDERR_FILENO));
    const auto start = std::chrono::steady_clock::now();
    auto progress = [&](const std::string& what) {
        if (!show_progress) return;
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "eomgen report: [%.1f s] %s\n", s, what.c_str());
    };
    try {
        eomgen::sim::check_options(options_);
        if (!options_.sensitivities.empty())
            throw eomgen::sim::UsageError("--sensitivities is an option of eomgen run (and eomgen-sim), not of the report");
    } catch (const std::exception& e) {
        std::cerr << "eomgen report: " << e.what() << "\n";
        return 2;
    }
    const std::string text = read_model_file(model_path_);
    const Model model = parse_model(text, model_path_);
    progress("deriving " + model_path_);
    const Equations eq = derive_equations(model);
    for (const std::string& w : eq.warnings) std::cerr << model_path_ << ": warning: " << w << "\n";

    // The derivations are read and checked before anything is written: a bad one writes nothing.
    std::vector<Checked> checks;
    try {
        for (const std::string& path : derivations_) {
            progress("checking " + path);
            const checker::Derivation d = checker::read_derivation(path);
            checks.push_back({path, checker::check_derivation(model, eq, d, {})});
        }
    } catch (const checker::CheckError& e) {
        std::cerr << "eomgen report: " << e.what() << "\n";
        return 2;
    } catch (const std::runtime_error& e) {
        std::cerr << "eomgen report: " << e.what() << "\n";
        return 3;
    }

    const fs::path dir = out_dir_.empty() ? fs::path(model.name + "-report") : fs::path(out_dir_);
    // The directory is made once the compiler has succeeded: a failure leaves nothing behind.
    auto make_directory = [&dir] {
        std::error_code ec;
        fs::create_directories(dir, ec);
        if (ec || !fs::is_directory(dir)) {
            std::cerr << "eomgen report: cannot create the directory " << dir.string()
                      << (ec ? ": " + ec.message() : "") << "\n";
            return false;
        }
        return true;
    };

    Simulation sim;
    std::unique_ptr<interpreter::InterpretedTable> interpreted;  // with --interpret: what TableModel is bound to
    if (!no_simulation_) {
        if (interpret_) {
            interpreted = std::make_unique<interpreter::InterpretedTable>(interpreter::interpret(model, eq));
            eomgen::TableModel::bind(interpreted->table());
        } else {
            try {
                CompileRequest request{text, model.name,
                                       [&] {
                                           return header_to_compile(model, eq, fs::path(model_path_).filename().string(),
                                                                    options_.method == "radau5");
                                       },
                                       !no_cache_, progress};
                request.jacobian = options_.method == "radau5";
                const CompiledModel compiled = compile_model(request);
                eomgen::TableModel::bind(*compiled.table);
            } catch (const CompileError& e) {
                std::cerr << "eomgen report: " << e.what() << "\n  command: " << e.command << "\n  log: " << e.log
                          << "\n";
                return kExitCompiler;
            } catch (const std::runtime_error& e) {  // the cache or a temporary directory
                std::cerr << "eomgen report: " << e.what() << "\n";
                return 3;
            }
        }
        if (!make_directory()) return 3;
        eomgen::sim::Options o = options_;
        o.model = model.name;
        // A bare number in the parameter's declared unit, or with its own ("45 deg"); SI for the driver.
        if (!options_in_si(declared_units(model), o.set, o.init, "eomgen report")) return 2;
        sim.csv = model.name + ".csv";
        o.csv = (dir / sim.csv).string();
        progress("integrating");
        {
            Capture capture;
            sim.code = eomgen::sim::run_reporting<eomgen::TableModel>(o, "eomgen report");
            sim.summary = capture.out();
            sim.errors = capture.err();
        }
        sim.ran = true;
        if (sim.code == eomgen::sim::kExitOutput) {
            std::cerr << sim.errors;
            return 3;
        }
        if (sim.code == eomgen::sim::kExitOk) {
            measure(model, eq, sim, o.csv);
            sim.plot = model.name + ".png";
            progress("plotting");
            try {
                plot(default_plot(model, o.csv, (dir / sim.plot).string()));
            } catch (const std::exception& e) {
                std::cerr << "eomgen report: no plot: " << e.what() << "\n";
                sim.plot.clear();
            }
            // The motion as a page beside the plot, from the same samples, where the model says what to draw.
            std::optional<animation::Scene> scene;
            try {
                scene = animation::build_scene(model);
            } catch (const ModelError&) {  // nothing to draw: a report without an animation
            }
            if (scene) {
                progress("animating");
                sim.animation = model.name + ".html";
                if (write_animation(model, *scene, o, (dir / sim.animation).string(), "eomgen report") != 0)
                    sim.animation.clear();
            }
        } else {
            std::cerr << sim.errors;
            sim.csv.clear();
        }
    }

    if (!sim.ran && !make_directory()) return 3;
    const std::vector<LatexBlock> blocks = latex_equations(model, eq);
    const bool tex = format_ == "latex";
    const fs::path file = dir / (model.name + (tex ? ".tex" : ".md"));
    try {
        const Modes modes = small_oscillations_of(model, eq, options_);
        output::write_atomically(file, tex ? latex(model, eq, blocks, sim, checks, options_, modes)
                                           : markdown(model, eq, blocks, sim, checks, options_, modes));
    } catch (const output::WriteError& e) {
        std::cerr << "eomgen report: " << e.what() << "\n";
        return 3;
    }
    std::cout << "report:  " << file.string() << "\n";
    if (sim.ran && sim.code != 0) {
        std::cerr << "eomgen report: the simulation failed; the report says how\n";
        return 2;
    }
    return 0;
}

}  // namespace eomgen::cli
