/** @file run_command.hpp  `eomgen run MODEL.toml [options]` and `eomgen cache clear`. */
#pragma once

#include "cli/ensemble_design.hpp"
#include "cli/plot.hpp"
#include "eomgen/simulation.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace eomgen::cli {

/// Exit code when the C++ compiler is missing or fails (the message names the command and its log).
constexpr int kExitCompiler = 4;

/// The plot of a run of `model` whose samples are in `csv`: coordinates, invariants, residuals, outputs.
PlotRequest default_plot(const Model& model, const std::string& csv, const std::string& output);

/**
 * Registers `run` and `cache` on the `eomgen` command line:
 *
 *     eomgen run MODEL.toml [eomgen-sim's options] [--plot FILE.png|FILE.svg] [--plot-phase q]
 *                [--plot-xy X,Y ...] [--animate FILE.html [--fps N]] [--no-cache | --interpret] [--quiet | --progress]
 *     eomgen run MODEL.toml (--sweep NAME=START:STOP:COUNT ... | --sample N --dist NAME=uniform(a,b) ...
 *                [--seed S]) [--threads N] [--out FILE.csv] [--plot FILE.png [--plot-xy X,Y]] [options]
 *     eomgen cache clear
 *
 * run() derives the model, emits its header, compiles it with the simulation driver into a cached shared
 * object (compiled_model.hpp), loads it and integrates, once or, with --sweep or --sample, as an ensemble
 * (ensemble_command.hpp); with --interpret the derived equations run on eomgen's interpreter instead
 * (interpreter/interpreted_table.hpp), nothing compiled. Returns 0; 1 for a model error (thrown as
 * ModelError, as for `show`); 2 for a bad option value or a failed simulation (the message says which, with
 * t and the state); 3 when a file or the cache cannot be used; 4 when the compiler is missing or fails.
 */
class RunCommand {
  public:
    explicit RunCommand(CLI::App& app);
    bool selected() const;
    int run();

  private:
    int run_model();
    CLI::App* run_ = nullptr;
    CLI::App* cache_ = nullptr;
    CLI::App* clear_ = nullptr;
    std::string model_path_, plot_, plot_phase_, animate_;
    double fps_ = 60;
    std::vector<std::string> plot_xy_;
    eomgen::sim::Options options_;
    bool no_cache_ = false, quiet_ = false, progress_ = false, interpret_ = false;
    EnsembleDesign::Request design_;
    unsigned threads_ = 0;
    std::string out_;
};

}  // namespace eomgen::cli
