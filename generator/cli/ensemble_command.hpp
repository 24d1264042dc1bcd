/**
 * @file ensemble_command.hpp  `eomgen run MODEL --sweep ... | --sample N --dist ...`: an ensemble of the
 * model loaded as a TableModel, one CSV row per member (`--out`, else stdout), `--plot` of a result against
 * a swept value, on `--threads` threads and, under mpirun, across the ranks (ensemble_mpi.hpp).
 */
#pragma once

#include "cli/ensemble_design.hpp"
#include "eomgen/simulation.hpp"
#include "model/model.hpp"

#include <string>
#include <vector>

namespace eomgen::cli {

struct EnsembleRequest {
    const Model* model = nullptr;   ///< for the title and the outputs' units
    eomgen::sim::Options options;   ///< every member's: --set and --init are the defaults the design varies
    EnsembleDesign::Request design;
    unsigned threads = 0;           ///< 0: every core
    std::string out;                ///< the table: FILE.csv, FILE.h5 (HDF5, where built with it), "" for stdout
    std::string model_path, model_hash;  ///< recorded in an HDF5 table's metadata
    std::string plot;               ///< FILE.png or FILE.svg, or ""
    std::vector<std::string> plot_xy;  ///< at most one X,Y: the columns plotted (default: the first varied one, t)
    bool progress = false;
};

/// The table's columns: member, the varied values (a state's initial value as `q(0)`), status (ok or
/// failed), stopped (the --until event or t_end), t, the state, energy, the model's outputs, then for each
/// --sensitivities column BY: dX/dBY of each state, dY/dBY of each output, and with --until dt/dBY; message.
std::vector<std::string> ensemble_columns(const EnsembleDesign& design, const std::vector<std::string>& states,
                                          const std::vector<std::string>& outputs,
                                          const std::vector<std::string>& sensitivities = {},
                                          bool with_event_time = false);

/// False in a rank other than 0 of an MPI job (its launcher's OMPI_COMM_WORLD_RANK, PMI_RANK or PMIX_RANK),
/// so that a mistake every rank finds is said once.
bool first_rank();

/**
 * Runs the ensemble with the model bound to TableModel (TableModel::bind). Returns 0 when the table is
 * written (members that failed are rows that say so), 2 for a bad option (the message on stderr), 3 when
 * the table or the plot cannot be written.
 */
int run_ensemble(const EnsembleRequest& request);

}  // namespace eomgen::cli
