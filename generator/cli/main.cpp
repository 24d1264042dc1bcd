/** @file main.cpp  The `eomgen` command: generate C++ from model files, show the derived mechanics. */
#include "cli/check_command.hpp"
#include "cli/fit_command.hpp"
#include "cli/latex_equations.hpp"
#include "cli/modes_command.hpp"
#include "cli/report_command.hpp"
#include "cli/run_command.hpp"
#include "cli/show_text.hpp"
#include "codegen/cpp_emitter.hpp"
#include "codegen/generation_timings.hpp"
#include "codegen/math_printer.hpp"
#include "mechanics/lagrangian.hpp"
#include "mechanics/quantity_units.hpp"
#include "mechanics/trig_rewrite.hpp"
#include "model/dimensions.hpp"
#include "model/families.hpp"
#include "model/model_file.hpp"
#include "model/names.hpp"
#include "output/atomic_file.hpp"
#include "text/escape.hpp"

#include <CLI/CLI.hpp>
#include <cln/version.h>
#include <fmt/format.h>
#include <ginac/version.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

#ifndef EOMGEN_VERSION
#define EOMGEN_VERSION "0.0.0"
#endif

namespace {

// Exit codes, as documented in README and `eomgen --help`.
constexpr int kExitOk = 0;
constexpr int kExitModelError = 1;  // a model file is wrong: file:line:col: message on stderr
constexpr int kExitUsage = 2;       // the command line is wrong
constexpr int kExitIo = 3;          // a file could not be read or written

struct IoError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// output::write_atomically, its failures reported as IoError (exit 3).
void write_atomically(const std::filesystem::path& path, const std::string& text) {
    try {
        eomgen::output::write_atomically(path, text);
    } catch (const eomgen::output::WriteError& e) {
        throw IoError(e.what());
    }
}

/// `--with` of generate: the optional functions asked for on the command line, added to each model's [generate].
struct WithFunctions {
    bool jacobians = false, stiffness = false;
};

WithFunctions parse_with(const std::vector<std::string>& items) {
    WithFunctions w;
    for (const std::string& item : items) {
        if (item == "jacobians" || item == "all") w.jacobians = true;
        if (item == "stiffness" || item == "all") w.stiffness = true;
    }
    return w;
}

int generate(const std::vector<std::string>& models, const std::vector<std::string>& families,
             const std::string& out_dir, const std::string& name, const WithFunctions& with, bool timings) {
    // Derive everything first: one bad model writes nothing at all.
    std::vector<std::pair<std::filesystem::path, std::string>> outputs;
    std::vector<std::string> sources = models;
    for (const std::string& f : families) sources.push_back("--family " + f);
    for (const std::string& path : sources) {
        // A family (--family pendulum:n=20) is model-file text made in memory, read like a file.
        const bool family = path.rfind("--family ", 0) == 0;
        eomgen::Model model = family ? eomgen::parse_model(eomgen::family_model_text(eomgen::parse_family_spec(
                                                               path.substr(9))),
                                                           path)
                                     : eomgen::load_model(path);
        if (!name.empty()) model.name = name;
        // Analytic Jacobians are for unconstrained models: asked for on the command line for several models, the
        // constrained ones go without (eomgen::model_jacobian differentiates them by forward AD) and say so.
        model.generate.stiffness = model.generate.stiffness || with.stiffness;
        if (with.jacobians && !model.constraints.empty())
            std::cerr << path << ": note: --with jacobians: none for a model with constraints (forward AD through rhs())\n";
        model.generate.jacobians = model.generate.jacobians || (with.jacobians && model.constraints.empty());
        eomgen::codegen::GenerationTimings phases;
        eomgen::codegen::PhaseClock clock(timings ? &phases : nullptr);
        const eomgen::Equations eq = eomgen::derive_equations(model);
        clock.lap("derive");
        for (const std::string& w : eq.warnings) std::cerr << path << ": warning: " << w << "\n";
        if (!eomgen::has_declared_units(model)) std::cerr << path << ": " << eomgen::kNoUnitsNote << "\n";
        const std::string header = eomgen::codegen::emit_model_header(
            model, eq, std::filesystem::path(path).filename().string(), timings ? &phases : nullptr);
        if (timings) std::cerr << phases.table(path);
        outputs.emplace_back(std::filesystem::path(out_dir) / (model.name + ".hpp"), header);
    }
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec) throw IoError("cannot create directory " + out_dir + ": " + ec.message());
    for (const auto& [path, text] : outputs) {
        // Leave an identical file untouched so that build systems do not rebuild what did not change.
        std::ifstream in(path, std::ios::binary);
        std::stringstream old;
        if (in) old << in.rdbuf();
        if (in && old.str() == text) continue;
        write_atomically(path, text);
    }
    return kExitOk;
}


}  // namespace

int main(int argc, char** argv) {
    eomgen::output::guard_runtime_temporaries();  // the CSVs of run and report, as AtomicFile's own files
    CLI::App app{"eomgen: equations of motion from a Lagrangian, as fast C++.\n"
                 "Exit codes: 0 ok, 1 model error (file:line:col: message), 2 usage (run: or the simulation failed),\n"
                 "3 file I/O or cache, 4 the C++ compiler is missing or failed (run, report), 5 check: a disagreement."};
    app.set_version_flag("--version", fmt::format("eomgen {} (GiNaC {}.{}.{}, CLN {}.{}.{})", EOMGEN_VERSION,
                                                  GINACLIB_MAJOR_VERSION, GINACLIB_MINOR_VERSION,
                                                  GINACLIB_MICRO_VERSION, CL_VERSION_MAJOR, CL_VERSION_MINOR,
                                                  CL_VERSION_PATCHLEVEL));
    app.require_subcommand(1);

    std::vector<std::string> gen_models;
    std::string out_dir = "generated";
    CLI::App* gen = app.add_subcommand("generate", "Derive each model and write <out>/<name>.hpp");
    gen->add_option("models", gen_models, "Model files (.toml)")->check(CLI::ExistingFile);
    std::vector<std::string> gen_families;
    gen->add_option("--family", gen_families, "A model family instead of a file: pendulum:n=N or rods:n=N (n-link chains)")
        ->check([](const std::string& s) {
            try {
                eomgen::parse_family_spec(s);
                return std::string();
            } catch (const std::invalid_argument& e) {
                return std::string(e.what());
            }
        });
    gen->add_option("-o,--output", out_dir, "Output directory")->capture_default_str();
    std::string gen_name;
    gen->add_option("--name", gen_name, "Model name (namespace, file name) instead of the file's; one model only");
    std::vector<std::string> gen_with;
    gen->add_option("--with", gen_with,
                    "Optional functions besides the model files' [generate]: jacobians (analytic state_jacobian() and "
                    "parameter_jacobian(), unconstrained models), stiffness (K, C, G about rest), all")
        ->allow_extra_args(false)  // one value per --with (a list with commas): a model file after it is not one
        ->delimiter(',')
        ->check(CLI::IsMember({"jacobians", "stiffness", "all"}));
    bool gen_timings = false;
    gen->add_flag("--timings", gen_timings,
                  "Print each phase's time and the peak memory so far on stderr (derive, each function's CSE and emission)");

    std::string show_model;
    bool latex = false;
    CLI::App* show = app.add_subcommand("show", "Print T, V, L, the equations, h, momenta and conserved quantities");
    show->add_option("model", show_model, "Model file (.toml)")->required()->check(CLI::ExistingFile);
    show->add_flag("--latex", latex, "Print LaTeX instead of plain text (align environments: needs amsmath)");
    bool standalone = false;
    show->add_flag("--standalone", standalone, "With --latex: a complete document that pdflatex compiles");

    const eomgen::cli::CheckCommand check(app);  // `eomgen check MODEL DERIVATION.md`, see docs/checker.md
    eomgen::cli::RunCommand run(app);               // `eomgen run MODEL.toml`, `eomgen cache clear`
    eomgen::cli::ReportCommand report(app);         // `eomgen report MODEL.toml`
    const eomgen::cli::ModesCommand modes(app);     // `eomgen modes MODEL.toml`
#if EOMGEN_HAVE_CERES
    eomgen::cli::FitCommand fit(app);               // `eomgen fit MODEL.toml DATA.csv --free NAME`
#else
    // Without Ceres: the command is known, and says why it cannot run.
    CLI::App* fit_missing = app.add_subcommand("fit", "Fit a model file to measured data (needs Ceres: libceres-dev)");
    fit_missing->allow_extras();
#endif

    // A mistyped command: name it, with the closest one (CLI11 would say only "A subcommand is required").
    if (argc >= 2 && argv[1][0] != '-') {
        std::vector<std::string> commands;
        for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
            commands.push_back(sub->get_name());
        if (std::find(commands.begin(), commands.end(), argv[1]) == commands.end()) {
            const std::string near = eomgen::closest_name(argv[1], commands);
            std::cerr << "eomgen: unknown command '" << argv[1] << "'"
                      << (near.empty() ? "" : "; did you mean '" + near + "'?") << " (eomgen --help lists them)\n";
            return kExitUsage;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // A model file, derivation or map file that is not there is a file problem (3), not a usage one.
        const bool missing_file =
            dynamic_cast<const CLI::ValidationError*>(&e) && std::string(e.what()).find("does not exist") != std::string::npos;
        const int code = app.exit(e);
        return code == 0 ? kExitOk : missing_file ? kExitIo : kExitUsage;
    }

    try {
        if (*gen) {
            if (gen_models.empty() && gen_families.empty()) {
                std::cerr << "eomgen generate: give model files or --family\n";
                return kExitUsage;
            }
            if (!gen_name.empty() && gen_models.size() + gen_families.size() != 1) {
                std::cerr << "eomgen generate: --name needs exactly one model file\n";
                return kExitUsage;
            }
            if (!gen_name.empty() && !eomgen::name_problem(gen_name).empty()) {
                std::cerr << "eomgen generate: --name " << gen_name << ": " << eomgen::name_problem(gen_name) << "\n";
                return kExitUsage;
            }
            return generate(gen_models, gen_families, out_dir, gen_name, parse_with(gen_with), gen_timings);
        }
        if (*show) {
            if (standalone && !latex) {
                std::cerr << "eomgen show: --standalone needs --latex\n";
                return kExitUsage;
            }
            const eomgen::Model model = eomgen::load_model(show_model);
            const eomgen::Equations eq = eomgen::derive_equations(model);
            if (!eomgen::has_declared_units(model)) std::cerr << show_model << ": " << eomgen::kNoUnitsNote << "\n";
            if (latex) {
                const std::string fragment =
                    eomgen::cli::latex_fragment(model, eomgen::cli::latex_equations(model, eq));
                std::cout << (standalone ? eomgen::cli::latex_document(model, fragment) : fragment);
            } else {
                eomgen::cli::show_text(model, eq, std::cout, eomgen::cli::modes_show_section(model, eq));
            }
            return kExitOk;
        }
        if (check.selected()) return check.run();
        if (run.selected()) return run.run();
        if (report.selected()) return report.run();
        if (modes.selected()) return modes.run();
#if EOMGEN_HAVE_CERES
        if (fit.selected()) return fit.run();
#else
        if (fit_missing->parsed()) {
            std::cerr << "eomgen fit: this eomgen was built without Ceres (install libceres-dev and build again)\n";
            return kExitUsage;
        }
#endif
    } catch (const eomgen::ModelError& e) {
        std::cerr << e.what() << "\n";
        return kExitModelError;
    } catch (const IoError& e) {
        std::cerr << "eomgen: " << e.what() << "\n";
        return kExitIo;
    } catch (const std::exception& e) {
        std::cerr << "eomgen: internal error: " << e.what() << "\n";
        return 70;  // EX_SOFTWARE: 4 is the compiler's failure in `eomgen run`
    }
    return kExitUsage;
}
