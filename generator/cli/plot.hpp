/** @file plot.hpp  `--plot`: a run's CSV drawn by gnuplot (PNG or SVG), started without a shell. */
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace eomgen::cli {

/// The unit of q̇ for q in `unit`: "m/s", "rad/s", "1/s" for a dimensionless q; "" when q has none.
std::string rate_unit(const std::string& unit);

/// A column of the CSV with the unit its axis shows ("" when none is given).
struct PlotColumn {
    std::string name;
    std::string unit;
};

struct PlotRequest {
    std::string csv;                     ///< the run's samples (eomgen::write_csv's format)
    std::string output;                  ///< FILE.png or FILE.svg
    std::string title;                   ///< the model's title (escaped for gnuplot here)
    std::vector<PlotColumn> coordinates;  ///< with their SI units (the CSV's values are in SI)
    std::string phase;                   ///< a coordinate for q' against q, or ""
    std::vector<PlotColumn> outputs;     ///< declared outputs: a panel of them against t
    std::vector<std::pair<PlotColumn, PlotColumn>> xy;  ///< (x, y): a panel of y against x for each
};

/// Writes the plot; throws std::runtime_error with gnuplot's message when it fails. The invariants whose
/// drift it draws are the CSV's columns from `energy` on (energy and the conserved quantities) that are not
/// outputs, its residuals the `residual_<constraint>` columns.
void plot(const PlotRequest& request);

/// One column of a table against another, a point per row (an ensemble's result against a swept value).
struct TablePlotRequest {
    std::string csv;     ///< a table with a header row (eomgen::csv_row lines)
    std::string output;  ///< FILE.png or FILE.svg
    std::string title, key;
    PlotColumn x, y;     ///< columns of the table
    std::string status;  ///< the column that says "ok" for rows that have a y (others are left out)
    bool lines = false;  ///< join the points (one swept variable, in order)
};

/// Writes the table's plot; throws as plot() does.
void plot_table(const TablePlotRequest& request);

/// Runs gnuplot on `script`, which draws to `output`; throws std::runtime_error with gnuplot's message.
void run_gnuplot(const std::string& script, const std::string& output);

/// Why `output` cannot be a plot's file name (it must end in .png or .svg), or "" when it can.
std::string plot_format_problem(const std::string& output);

/// A gnuplot single-quoted string: the only special character there is ' itself, written twice.
std::string gnuplot_string(const std::string& s);

}  // namespace eomgen::cli
