/** @file main.cpp  The `eomgen` command: generate C++ from model files, show the derived mechanics. */
#include "codegen/cpp_emitter.hpp"
#include "codegen/math_printer.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"
#include "model/names.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

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

/// Writes `text` to `path` through a temporary in the same directory and a rename, so a reader never
/// sees a half-written file and a failure leaves the old file in place.
void write_atomically(const std::filesystem::path& path, const std::string& text) {
    const std::filesystem::path tmp = path.string() + ".tmp." + std::to_string(::getpid());
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw IoError("cannot write " + tmp.string());
        out << text;
        out.flush();
        if (!out) {
            std::filesystem::remove(tmp);
            throw IoError("cannot write " + tmp.string());
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp);
        throw IoError("cannot rename " + tmp.string() + " to " + path.string() + ": " + ec.message());
    }
}

int generate(const std::vector<std::string>& models, const std::string& out_dir, const std::string& name) {
    // Derive everything first: one bad model writes nothing at all.
    std::vector<std::pair<std::filesystem::path, std::string>> outputs;
    for (const std::string& path : models) {
        eomgen::Model model = eomgen::load_model(path);
        if (!name.empty()) model.name = name;
        const eomgen::Equations eq = eomgen::derive_equations(model);
        for (const std::string& w : eq.warnings) std::cerr << path << ": warning: " << w << "\n";
        const std::string header =
            eomgen::codegen::emit_model_header(model, eq, std::filesystem::path(path).filename().string());
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

std::string rule(const std::string& title) { return "\n" + title + "\n" + std::string(title.size(), '-') + "\n"; }

void show_text(const eomgen::Model& model, const eomgen::Equations& eq, std::ostream& os) {
    using eomgen::codegen::MathStyle;
    eomgen::codegen::MathPrinter pr(eomgen::codegen::symbol_table(model));
    auto P = [&pr](const GiNaC::ex& e) { return pr.print(e.expand(), MathStyle::Text); };
    os << model.name << ": " << model.title;
    if (!model.source.empty()) os << " (" << model.source << ")";
    os << "\n";
    os << rule("Coordinates");
    for (const eomgen::Coordinate& c : model.coordinates)
        os << "  " << c.name << "  (q(0) = " << eomgen::codegen::shortest_decimal(c.initial)
           << ", q'(0) = " << eomgen::codegen::shortest_decimal(c.rate) << ")\n";
    os << rule("Parameters");
    for (const eomgen::Parameter& p : model.parameters)
        os << "  " << p.name << " = " << eomgen::codegen::shortest_decimal(p.value) << (p.unit.empty() ? "" : " " + p.unit)
           << (p.description.empty() ? "" : "  (" + p.description + ")") << "\n";
    os << rule("Energies");
    os << "  T = " << P(eq.T) << "\n  V = " << P(eq.V) << "\n  L = T - V = " << P(eq.L) << "\n";
    os << rule("Euler-Lagrange equations  d/dt(dL/dq') - dL/dq = 0");
    for (std::size_t i = 0; i < model.dof(); ++i)
        os << "  [" << model.coordinates[i].name << "]  " << P(eq.euler_lagrange[i]) << " = 0\n";
    os << rule("Mass-matrix form  M(q,t) q'' = f(q,q',t)");
    for (std::size_t i = 0; i < model.dof(); ++i)
        for (std::size_t j = i; j < model.dof(); ++j)
            os << "  M[" << model.coordinates[i].name << "," << model.coordinates[j].name
               << "] = " << P(eq.M(unsigned(i), unsigned(j))) << "\n";
    for (std::size_t i = 0; i < model.dof(); ++i)
        os << "  f[" << model.coordinates[i].name << "] = " << P(eq.f[i]) << "\n";
    os << rule("Energy function and momenta");
    os << "  h = sum q' dL/dq' - L = " << P(eq.energy) << "\n";
    for (std::size_t i = 0; i < model.dof(); ++i)
        os << "  p_" << model.coordinates[i].name << " = dL/d" << model.coordinates[i].name << "' = " << P(eq.momenta[i])
           << "\n";
    os << rule("Conserved quantities");
    if (eq.conserved.empty()) os << "  none found (L depends on t explicitly and no coordinate is cyclic)\n";
    for (const eomgen::ConservedQuantity& c : eq.conserved) os << "  " << c.name << ": " << c.reason << "\n";
    for (std::size_t i = 0; i < model.dof(); ++i)
        if (!eq.cyclic[i]) os << "  " << model.coordinates[i].name << " is not cyclic\n";
    if (!eq.warnings.empty()) {
        os << rule("Warnings");
        for (const std::string& w : eq.warnings) os << "  " << w << "\n";
    }
}

void show_latex(const eomgen::Model& model, const eomgen::Equations& eq, std::ostream& os) {
    using eomgen::codegen::MathStyle;
    eomgen::codegen::MathPrinter pr(eomgen::codegen::symbol_table(model));
    auto P = [&pr](const GiNaC::ex& e) { return pr.print(e.expand(), MathStyle::Latex); };
    os << "% " << model.name << ": " << model.title << (model.source.empty() ? "" : " (" + model.source + ")") << "\n";
    os << "\\begin{align}\n";
    os << "T &= " << P(eq.T) << " \\\\\n";
    os << "V &= " << P(eq.V) << " \\\\\n";
    os << "L &= " << P(eq.L) << "\n\\end{align}\n";
    os << "% Euler-Lagrange equations\n\\begin{align}\n";
    for (std::size_t i = 0; i < model.dof(); ++i)
        os << P(eq.euler_lagrange[i]) << " &= 0" << (i + 1 < model.dof() ? " \\\\" : "") << "\n";
    os << "\\end{align}\n% energy function and momenta\n\\begin{align}\n";
    os << "h &= " << P(eq.energy);
    for (std::size_t i = 0; i < model.dof(); ++i)
        os << " \\\\\np_{" << model.coordinates[i].latex << "} &= " << P(eq.momenta[i]);
    os << "\n\\end{align}\n";
    for (const eomgen::ConservedQuantity& c : eq.conserved) os << "% conserved: " << c.latex << " (" << c.reason << ")\n";
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"eomgen: equations of motion from a Lagrangian, as fast C++.\n"
                 "Exit codes: 0 ok, 1 model error (file:line:col: message), 2 usage, 3 file I/O."};
    app.set_version_flag("--version", std::string("eomgen ") + EOMGEN_VERSION);
    app.require_subcommand(1);

    std::vector<std::string> gen_models;
    std::string out_dir = "generated";
    CLI::App* gen = app.add_subcommand("generate", "Derive each model and write <out>/<name>.hpp");
    gen->add_option("models", gen_models, "Model files (.toml)")->required()->check(CLI::ExistingFile);
    gen->add_option("-o,--output", out_dir, "Output directory")->capture_default_str();
    std::string gen_name;
    gen->add_option("--name", gen_name, "Model name (namespace, file name) instead of the file's; one model only");

    std::string show_model;
    bool latex = false;
    CLI::App* show = app.add_subcommand("show", "Print T, V, L, the equations, h, momenta and conserved quantities");
    show->add_option("model", show_model, "Model file (.toml)")->required()->check(CLI::ExistingFile);
    show->add_flag("--latex", latex, "Print LaTeX instead of plain text");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kExitOk : kExitUsage;
    }

    try {
        if (*gen) {
            if (!gen_name.empty() && gen_models.size() != 1) {
                std::cerr << "eomgen generate: --name needs exactly one model file\n";
                return kExitUsage;
            }
            if (!gen_name.empty() && !eomgen::name_problem(gen_name).empty()) {
                std::cerr << "eomgen generate: --name " << gen_name << ": " << eomgen::name_problem(gen_name) << "\n";
                return kExitUsage;
            }
            return generate(gen_models, out_dir, gen_name);
        }
        if (*show) {
            const eomgen::Model model = eomgen::load_model(show_model);
            const eomgen::Equations eq = eomgen::derive_equations(model);
            if (latex)
                show_latex(model, eq, std::cout);
            else
                show_text(model, eq, std::cout);
            return kExitOk;
        }
    } catch (const eomgen::ModelError& e) {
        std::cerr << e.what() << "\n";
        return kExitModelError;
    } catch (const IoError& e) {
        std::cerr << "eomgen: " << e.what() << "\n";
        return kExitIo;
    } catch (const std::exception& e) {
        std::cerr << "eomgen: internal error: " << e.what() << "\n";
        return 4;
    }
    return kExitUsage;
}
