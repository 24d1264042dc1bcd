/** @file fit_command.hpp  `eomgen fit MODEL DATA.csv --free NAME[=start][:lo:hi] ...` (docs/sensitivities.md, "Fitting"). */
#pragma once

#include "eomgen/simulation_options.hpp"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace eomgen::cli {

/**
 * Registers `fit` on the `eomgen` command line:
 *
 *     eomgen fit MODEL.toml DATA.csv [DATA2.csv ...] --free NAME[=start][:lo:hi] ... [--weight COLUMN=W ...] [--format text|json]
 *                [--csv FILE] [--plot FILE.png|FILE.svg] [--max-iterations N] [--set ...] [--init ...] [--method M] [--rtol R] [--atol A]
 *                [--max-steps N] [--jacobian sensitivities|differences] [--loss squared|NAME:SCALE] [--no-cache | --interpret] [--quiet]
 *
 * Each data file is one experiment: the same parameters and initial state but for what it sets itself
 * (--set K:NAME=V, --init K:NAME=V for the K-th file) and the initial values freed with --free x0:STATE, which are
 * fitted per experiment (each from its own initial value unless --free gives a start). --loss names a robust loss
 * (fit_solve.hpp's FitLoss) for data with outliers.
 * run() compiles the model with its Jacobians (as `eomgen run --sensitivities`), reads the data (fit_data.hpp), fits
 * (fit_solve.hpp) and prints the estimates with their standard errors, the correlations, the residuals' RMS and
 * the directions the data do not determine. Returns 0; 1 for a model error; 2 for a bad option, data that do not
 * fit the model file, or a failed simulation; 3 when a file or the cache cannot be used; 4 when the compiler
 * fails; 5 when the fit did not converge (the last estimates are printed).
 */
class FitCommand {
  public:
    explicit FitCommand(CLI::App& app);
    bool selected() const;
    int run();

  private:
    int fit_model();
    CLI::App* fit_ = nullptr;
    std::string model_path_, format_ = "text", csv_, plot_, jacobian_ = "sensitivities", loss_ = "squared";
    std::vector<std::string> data_paths_, free_, weights_;
    eomgen::sim::Options options_;
    std::size_t max_iterations_ = 100;
    bool no_cache_ = false, quiet_ = false, interpret_ = false;
};

}  // namespace eomgen::cli
