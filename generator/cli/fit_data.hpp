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

/// One experiment's measurements: y(j, c) is column c (state state_index[c]) at t[j].
struct MeasuredSeries {
    std::string path;
    std::vector<double> t;
    std::vector<std::string> names;
    std::vector<int> state_index;
    Eigen::MatrixXd y;
};

/// Reads `path` against the model's state names and their SI units ("" where none is declared).
MeasuredSeries read_measured(const std::string& path, const std::vector<std::string>& state_names,
                             const std::vector<std::string>& state_units);

}  // namespace eomgen::cli
