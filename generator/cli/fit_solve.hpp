/**
 * @file fit_solve.hpp  The least-squares problem of `eomgen fit`: the free parameters and initial values that make
 * the model's trajectory (the bound eomgen::TableModel) pass closest to a measured series, weighted, solved by
 * Ceres' Levenberg–Marquardt with the exact Jacobian from the forward sensitivities (sensitivities.hpp); then the
 * standard errors and correlations from J at the solution scaled by the residuals' variance, and the directions
 * the data do not determine (a rank-deficient J).
 */
#pragma once

#include "cli/fit_data.hpp"
#include "eomgen/model_table.hpp"
#include "eomgen/sensitivities.hpp"
#include "eomgen/simulation_options.hpp"

#include <Eigen/Core>

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace eomgen::cli {

/// One unknown of the fit: a parameter shared by every experiment, or one experiment's own parameter or initial
/// value, its start and its bounds.
struct FreeValue {
    std::string name;  ///< as given, "l", "x0:phi"; one of several experiments' own "x0:phi[2]", "c[2]"
    SensitivityColumn column;
    int experiment = -1;  ///< the experiment (index into the data) it belongs to; -1: a parameter every one shares
    double start = 0;
    double lower = -std::numeric_limits<double>::infinity(), upper = std::numeric_limits<double>::infinity();
};

/// One experiment's fixed values: the parameters and initial state after --set and --init, its own
/// (--set K:NAME=V, --init K:NAME=V) included. Each starts its integrations there but for the unknowns.
struct ExperimentStart {
    TableModel::Params params;
    TableModel::State x0;
};

/// The loss each residual r (after --weight) enters the cost with: ½ Σ ρ(r²). Squared is least squares (ρ(s) = s);
/// the robust ones are Ceres' (huber, soft_l1, cauchy, arctan, tukey) with their scale in the residuals' units:
/// residuals below it count as in least squares, larger ones less (huber, soft_l1: linearly; cauchy, arctan:
/// logarithmically or bounded; tukey: not at all beyond the scale).
struct FitLoss {
    std::string name = "squared";
    double scale = 0;
};

/// --loss squared | NAME:SCALE (UsageError for an unknown name or a scale that is not a positive number).
FitLoss parse_loss(const std::string& spec);

/// What the fit found.
struct FitOutcome {
    std::vector<double> estimate;
    std::vector<double> standard_error;  ///< NaN for a value the data do not determine
    Eigen::MatrixXd correlation;         ///< NaN rows and columns where not determined
    /// Directions of the unknowns (in relative changes δθᵢ/θᵢ, unit length) that leave the residuals unchanged to
    /// first order: one per missing rank of J.
    std::vector<Eigen::VectorXd> undetermined;
    Eigen::VectorXd singular_values;  ///< of J with its columns scaled by the estimates (relative sensitivities)
    double solve_seconds = 0;        ///< Ceres' time, the integrations included
    double rms = 0;                   ///< sqrt(Σ r² / n) of the weighted residuals at the solution
    /// The residuals' standard deviation: sqrt(Σ r² / (n − k)); with a robust loss the scale of Huber's M-estimator
    /// covariance, K sqrt(Σ ψ² / (n − k)) / mean ψ' with ψ(r) = ρ'(r²) r (the standard errors are this times those
    /// of least squares at the same J).
    double residual_sigma = 0;
    std::size_t beyond_scale = 0;     ///< residuals larger than the robust loss's scale (0 for squared)
    std::string caveat;               ///< why the standard errors are not given, where they are not (else empty)
    std::size_t residuals = 0, iterations = 0;
    std::size_t trajectories = 0;  ///< the solver's integrations (with sensitivities, or without for differences)
    bool converged = false;
    std::string termination;  ///< Ceres' message
    std::vector<Eigen::MatrixXd> model;  ///< per experiment, the fitted trajectory at its data's times and columns
};

/// `K:REST` (K the place of a data file, from 1): sets `experiment` to K − 1 and returns REST; without such a prefix
/// returns `spec` and leaves `experiment` at −1. UsageError, saying `option spec`, for a K that is no data file's.
std::string experiment_prefix(const std::string& spec, std::size_t experiments, const std::string& option,
                              int& experiment);

/// The unknowns given as --free [K:]NAME[=start][:lo:hi] (UsageError for an unknown name or experiment, a bad number,
/// lo >= hi, a start outside the bounds, a value freed both for every experiment and for one); the start defaults to
/// the model's value (after --set and --init: a shared parameter's from the first experiment, the rest from their
/// own). NAME is one value for every experiment; K:NAME experiment K's own (from 1). With several experiments an
/// initial value x0:STATE is one unknown per experiment, named x0:STATE[e] (e from 1); K:x0:STATE experiment K's
/// only. The shared parameters come first, then each experiment's own parameters and initial values.
std::vector<FreeValue> parse_free(const std::vector<std::string>& specs, const std::vector<ExperimentStart>& starts);

/// Where the solver's Jacobian comes from: the sensitivities (exact), or central differences of whole trajectories
/// (Ceres' numeric differentiation; for comparison, docs/benchmarks.md section 10).
enum class FitJacobian { Sensitivities, Differences };

/// Fits the bound TableModel to the experiments `data` (experiment e from starts[e] but for the unknowns) with the
/// run's options (method, tolerances), each column weighted by weights[name] (default 1), each residual entering by
/// `loss`. Throws sim::UsageError for a problem with more unknowns than residuals or a method without error control,
/// and what integrate_sensitivities refuses.
FitOutcome fit(const sim::Options& options, const std::vector<ExperimentStart>& starts,
               const std::vector<FreeValue>& free, const std::vector<MeasuredSeries>& data,
               const std::map<std::string, double>& weights, std::size_t max_iterations, const FitLoss& loss = {},
               FitJacobian jacobian = FitJacobian::Sensitivities);

}  // namespace eomgen::cli
