/**
 * @file fit_data.hpp  A measured time series for `eomgen fit`: a CSV whose first column is t and whose other columns
 * are states of the model (coordinates or NAME_dot), as `eomgen run --csv` writes them ("psi [rad]": a unit in
 * brackets must be the state's SI unit, the one eomgen writes). Everything that does not fit the model file is an
 * error with its place, path:line:col: an unknown column, a unit other than the state's, a cell that is not a
 * finite number (NaN, empty), times that do not increase or start before 0.
 */
#pragma once

#include <Eigen/Core>

#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen::cli {

/// The data file does not fit the model (exit 2 of eomgen fit), "path:line:col: message".
struct FitDataError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// What a data file's columns may be: the model's states, then its declared outputs, with their SI units ("" where
/// none is declared).
struct Measurable {
    std::vector<std::string> names, units;
    std::size_t states = 0;  ///< names[i] is a state for i < states, output i − states after
};

/// One experiment's measurements: y(j, c) is column c (Measurable index[c]) at t[j].
struct MeasuredSeries {
    std::string path;
    std::vector<double> t;
    std::vector<std::string> names;
    std::vector<int> index;
    Eigen::MatrixXd y;
};

/// Reads `path` against what the model can be measured by.
MeasuredSeries read_measured(const std::string& path, const Measurable& measurable);

}  // namespace eomgen::cli
