/** @file report_command.hpp  `eomgen report MODEL.toml`: one document a person hands to a colleague. */
#pragma once

#include "eomgen/simulation.hpp"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace eomgen::cli {

/**
 * Registers `report` on the `eomgen` command line:
 *
 *     eomgen report MODEL.toml [-o DIR] [--derivation TEXT.md ...] [--format markdown|latex]
 *                   [eomgen-sim's options but --csv] [--no-simulation] [--no-cache | --interpret] [--quiet | --progress]
 *
 * Writes DIR/<name>.md (or .tex: a complete document for pdflatex) with the model (coordinates, parameters
 * and units), T and V, the equations (latex_equations.hpp: the ones `show --latex` prints), conserved
 * quantities and why, warnings, a default simulation (compiled as by `eomgen run`) with its plot
 * DIR/<name>.png, its samples DIR/<name>.csv and the measured drift of each invariant, and the checker's
 * verdicts on each derivation given. DIR defaults to <name>-report.
 *
 * Returns 0; 1 for a model error; 2 for a usage error, or when the simulation failed (the report is written
 * and says how); 3 when a file cannot be read or written; 4 when the compiler is missing or fails.
 */
class ReportCommand {
  public:
    explicit ReportCommand(CLI::App& app);
    bool selected() const;
    int run();

  private:
    CLI::App* report_ = nullptr;
    std::string model_path_, out_dir_, format_ = "markdown";
    std::vector<std::string> derivations_;
    eomgen::sim::Options options_;
    bool no_simulation_ = false, no_cache_ = false, quiet_ = false, progress_ = false, interpret_ = false;
};

}  // namespace eomgen::cli
