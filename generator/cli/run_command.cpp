/** @file run_command.cpp  `eomgen run`: model file → equations → compiled code → trajectory, CSV, plot. */
#include "cli/run_command.hpp"
#include "cli/animate.hpp"
#include "cli/capture.hpp"
#include "table_driver.hpp"  // the driver for TableModel, compiled once
#include "cli/model_unit_values.hpp"

#include "cli/compiled_model.hpp"
#include "cli/model_functions.hpp"
#include "cli/ensemble_command.hpp"
#include "cli/plot.hpp"
#include "cli/process.hpp"
#include "eomgen/model_table.hpp"
#include "eomgen/simulation.hpp"
#include "codegen/cpp_emitter.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"
#include "options.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>

#include <unistd.h>

namespace eomgen::cli {
namespace fs = std::filesystem;

namespace {

/// Why `spec` ("X,Y") names no pair of the run's columns, or "" after appending the pair to `xy`.
std::string xy_problem(const Model& model, const std::string& spec,
                       std::vector<std::pair<PlotColumn, PlotColumn>>& xy) {
    std::vector<PlotColumn> columns;
    for (const Coordinate& c : model.coordinates) columns.push_back({c.name, c.unit});
    for (const Coordinate& c : model.coordinates) columns.push_back({c.name + "_dot", rate_unit(c.unit)});
    for (const DeclaredOutput& o : model.outputs) columns.push_back({o.name, o.unit});
    const std::size_t comma = spec.find(',');
    if (comma == std::string::npos) return "expected X,Y, e.g. x_bob,y_bob";
    const std::string names[2] = {spec.substr(0, comma), spec.substr(comma + 1)};
    PlotColumn found[2];
    for (int k = 0; k < 2; ++k) {
        const std::string& name = names[k];
        const auto it =
            std::find_if(columns.begin(), columns.end(), [&](const PlotColumn& c) { return c.name == name; });
        if (it == columns.end()) {
            std::string known;
            for (const PlotColumn& c : columns) known += (known.empty() ? "" : ", ") + c.name;
            return "no output, coordinate or velocity '" + name + "' (there are " + known + ")";
        }
        found[k] = *it;
    }
    xy.push_back({found[0], found[1]});
    return "";
}

}  // namespace

PlotRequest default_plot(const Model& model, const std::string& csv, const std::string& output) {
    PlotRequest p;
    p.csv = csv;
    p.output = output;
    p.title = model.title.empty() ? model.name : model.title;
    for (const Coordinate& c : model.coordinates) p.coordinates.push_back({c.name, c.unit});
    for (const DeclaredOutput& o : model.outputs) p.outputs.push_back({o.name, o.unit});
    return p;
}

RunCommand::RunCommand(CLI::App& app) {
    run_ = app.add_subcommand("run", "Derive, compile (cached) and integrate any model file; CSV and plot");
    run_->add_option("model", model_path_, "Model file (.toml)")->required()->check(CLI::ExistingFile);
    eomgen::sim::add_options(*run_, options_);
    run_->add_option("--plot", plot_, "Plot to FILE.png or FILE.svg: coordinates, drift of the invariants, "
                                      "constraint residuals (gnuplot)");
    run_->add_option("--plot-phase", plot_phase_, "With --plot: add q' against q for this coordinate");
    run_->add_option("--plot-xy", plot_xy_,
                     "With --plot: add Y against X (X,Y: outputs, coordinates or velocities, "
                     "e.g. x_bob,y_bob); may be repeated");
    run_->add_option("--animate", animate_,
                     "Write an animation of the motion to FILE.html: one self-contained page with a player "
                     "(the model's [[draw]] entries, bodies and springs; docs/animation.md)");
    run_->add_option("--fps", fps_, "With --animate: frames per second of simulated time (default 60)");
    run_->add_flag("--no-cache", no_cache_, "Compile afresh and keep nothing in the cache");
    run_->add_flag("--interpret", interpret_,
                   "Run the derived equations with eomgen's interpreter instead of compiling them: no C++ compiler, "
                   "no wait, each step slower (docs/interpreter.md)");
    run_->add_flag("--quiet", quiet_, "No progress messages on stderr");
    run_->add_flag("--progress", progress_, "Progress messages on stderr even when it is not a terminal");
    // Ensembles (ensemble_command.hpp): many members, one row each.
    run_->add_option("--sweep", design_.sweeps,
                     "Ensemble over NAME (a parameter, or a state's initial value): NAME=START:STOP:COUNT or "
                     "NAME=v1,v2,...; repeatable: the grid of all combinations");
    run_->add_option("--sample", design_.sample, "Monte Carlo ensemble of N members drawn from the --dist's");
    run_->add_option("--dist", design_.dists, "With --sample: NAME=uniform(a,b) or NAME=normal(mu,sigma); repeatable");
    run_->add_option("--seed", design_.seed, "With --sample: the seed of the draws (default 0)")
        ->each([this](const std::string&) { design_.seed_given = true; });
    run_->add_option("--threads", threads_, "Threads of an ensemble (default: every core)");
    run_->add_option("--out", out_, "An ensemble's table (one CSV row per member); default: stdout");
    cache_ = app.add_subcommand("cache", "The cache of compiled models (" "$XDG_CACHE_HOME/eomgen)");
    clear_ = cache_->add_subcommand("clear", "Remove every compiled model from the cache");
    cache_->require_subcommand(1);
}

bool RunCommand::selected() const { return run_->parsed() || cache_->parsed(); }

int RunCommand::run() {
    try {
        if (cache_->parsed()) {
            const std::size_t n = clear_cache();
            std::cout << "eomgen cache clear: removed " << n << " files from " << cache_directory().string() << "\n";
            return 0;
        }
        return run_model();
    } catch (const CompileError& e) {
        std::cerr << "eomgen run: " << e.what() << "\n  command: " << e.command << "\n  log: " << e.log
                  << "\n  (--interpret runs the model without a compiler)\n";
        return kExitCompiler;
    } catch (const CacheError& e) {
        std::cerr << "eomgen run: " << e.what() << "\n";
        return 3;
    } catch (const TempDirError& e) {
        std::cerr << "eomgen run: " << e.what() << "\n";
        return 3;
    }
}

int RunCommand::run_model() {
    const bool show_progress = !quiet_ && (progress_ || ::isatty(STDERR_FILENO));
    const auto start = std::chrono::steady_clock::now();
    auto progress = [&](const std::string& what) {
        if (!show_progress) return;
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "eomgen run: [%.1f s] %s\n", s, what.c_str());
    };
    // Mistakes on the command line are reported before anything slow runs.
    if (const std::string problem = plot_.empty() ? "" : plot_format_problem(plot_); !problem.empty()) {
        std::cerr << "eomgen run: " << problem << "\n";
        return 2;
    }
    if (const std::string problem = animate_.empty() ? "" : animation_request_problem(animate_, fps_); !problem.empty()) {
        std::cerr << "eomgen run: " << problem << "\n";
        return 2;
    }
    // Reading the model is cheap; deriving it is done only when its code is not in the cache.
    const std::string text = read_model_file(model_path_);
    const Model model = parse_model(text, model_path_);
    // What an animation draws, before anything slow runs: a model with nothing to draw is a ModelError here.
    std::optional<animation::Scene> scene;
    if (!animate_.empty()) scene = animation::build_scene(model);
    std::vector<std::pair<PlotColumn, PlotColumn>> xy;
    const bool ensemble = EnsembleDesign::requested(design_);
    // --sweep and --dist values in the declared units (or their own), SI for the ensemble.
    if (ensemble && !ensemble_in_si(declared_units(model), design_.sweeps, design_.dists, "eomgen run")) return 2;
    if (ensemble) {
        // The design's mistakes before the compiler runs (its columns and plot are checked after).
        EnsembleNames names;
        for (const Parameter& p : model.parameters) names.params.push_back(p.name);
        for (const Coordinate& c : model.coordinates) names.states.push_back(c.name);
        for (const Coordinate& c : model.coordinates) names.states.push_back(c.name + "_dot");
        try {
            (void)EnsembleDesign(design_, names);
        } catch (const eomgen::sim::UsageError& e) {
            if (first_rank()) std::cerr << "eomgen run: " << e.what() << "\n";
            return 2;
        }
    }
    for (const std::string& spec : ensemble ? std::vector<std::string>{} : plot_xy_) {
        const std::string problem = plot_.empty() ? "needs --plot" : xy_problem(model, spec, xy);
        if (!problem.empty()) {
            std::cerr << "eomgen run: --plot-xy " << spec << ": " << problem << "\n";
            return 2;
        }
    }
    // The Jacobians ∂ẋ/∂x (radau5) and ∂ẋ/∂p (sensitivities), analytic in the header where the model allows.
    const bool jacobians = options_.method == "radau5" || !options_.sensitivities.empty();
    FunctionsRequest request{&model, text, model_path_, jacobians, interpret_, !no_cache_, progress};
    const ModelFunctions functions = model_functions(request);
    const ModelTable& table = functions.table();

    if (ensemble) {
        if (!plot_phase_.empty()) {
            std::cerr << "eomgen run: --plot-phase draws one run; an ensemble's --plot is a result against a varied value\n";
            return 2;
        }
        eomgen::TableModel::bind(table);
        if (scene) {  // the members overlaid in one page, each run alone; then the ensemble's table as without
            progress("animating the ensemble's members");
            eomgen::sim::Options o = options_;
            o.model = model.name;
            if (!options_in_si(declared_units(model), o.set, o.init, "eomgen run")) return 2;
            o.samples = std::max(o.samples, animation_samples(o.t_end, fps_));
            EnsembleNames names;
            for (const Parameter& p : model.parameters) names.params.push_back(p.name);
            for (const Coordinate& c : model.coordinates) names.states.push_back(c.name);
            for (const Coordinate& c : model.coordinates) names.states.push_back(c.name + "_dot");
            const RunMember member = [](const eomgen::sim::Options& options, std::string& errors) {
                const Capture capture;
                const int code = eomgen::sim::run_reporting<eomgen::TableModel>(options, "eomgen run");
                errors = capture.err();
                return code;
            };
            if (const int code = write_ensemble_animation(model, *scene, o, EnsembleDesign(design_, names), animate_,
                                                          member);
                code != 0)
                return code;
            std::cerr << "animation: " << animate_ << "\n";
        }
        progress("integrating the ensemble");
        EnsembleRequest e{&model, options_, design_, threads_, out_, model_path_, text_hash(text), plot_, plot_xy_,
                          show_progress};
        e.options.model = model.name;
        return run_ensemble(e);
    }
    // Ensemble options without an ensemble are mistakes, not silently ignored.
    for (const auto& [given, option] : {std::pair<bool, const char*>{design_.seed_given, "--seed"},
                                        {threads_ != 0, "--threads"}, {!out_.empty(), "--out"}})
        if (given) {
            std::cerr << "eomgen run: " << option << " needs an ensemble (--sweep or --sample)\n";
            return 2;
        }

    // A plot needs the samples: into a private temporary CSV unless --csv names one.
    eomgen::sim::Options o = options_;
    o.model = model.name;
    // A bare number in the parameter's declared unit, or with its own ("45 deg"); SI for the driver.
    if (!options_in_si(declared_units(model), o.set, o.init, "eomgen run")) return 2;
    if (show_progress)
        o.progress = ::isatty(STDERR_FILENO) ? eomgen::ProgressStyle::Terminal : eomgen::ProgressStyle::Lines;
    if (scene) o.samples = std::max(o.samples, animation_samples(o.t_end, fps_));
    std::optional<TempDir> samples_dir;
    if ((!plot_.empty() || scene) && o.csv.empty()) {
        samples_dir.emplace(fs::temp_directory_path(), "eomgen-run.");
        o.csv = (samples_dir->path() / "samples.csv").string();
        o.report_csv = false;  // removed when the plot is made: not a file to point the user to
    }
    progress("integrating");
    eomgen::TableModel::bind(table);
    const int code = eomgen::sim::run_reporting<eomgen::TableModel>(o, "eomgen run");
    if (code == eomgen::sim::kExitOutput) return 3;  // the CSV could not be written, said on stderr
    if (code != eomgen::sim::kExitOk) return 2;      // a bad option value or a failed simulation, said on stderr

    if (scene) {
        progress("animating");
        if (const int animated = write_animation(model, *scene, o, animate_); animated != 0) return animated;
        std::cout << "animation: " << animate_ << "\n";
    }
    if (!plot_.empty()) {
        PlotRequest p = default_plot(model, o.csv, plot_);
        p.xy = xy;
        if (!plot_phase_.empty()) {
            const bool known = std::any_of(model.coordinates.begin(), model.coordinates.end(),
                                           [&](const Coordinate& c) { return c.name == plot_phase_; });
            if (!known) {
                std::cerr << "eomgen run: --plot-phase " << plot_phase_ << ": no such coordinate\n";
                return 2;
            }
            p.phase = plot_phase_;
        }
        progress("plotting");
        try {
            plot(p);
        } catch (const std::invalid_argument& e) {
            std::cerr << "eomgen run: " << e.what() << "\n";
            return 2;
        } catch (const std::runtime_error& e) {
            std::cerr << "eomgen run: " << e.what() << "\n";
            return 3;
        }
        std::cout << "plot:    " << plot_ << "\n";
    }
    return 0;
}

}  // namespace eomgen::cli
