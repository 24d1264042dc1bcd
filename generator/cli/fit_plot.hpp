/** @file fit_plot.hpp  `eomgen fit --plot`: the data against the fitted model, and the residuals (gnuplot). */
#pragma once

#include "cli/plot.hpp"

#include <string>
#include <vector>

namespace eomgen::cli {

/// What the fit's plot shows: the fitted CSV (fit_command.cpp's `--csv` layout: [experiment,] t, then per measured
/// column NAME, NAME_model, NAME_residual) and its columns with their units.
struct FitPlotRequest {
    std::string csv;
    std::string output;  ///< FILE.png or FILE.svg
    std::string title;
    std::vector<PlotColumn> columns;  ///< the measured columns, in the CSV's order
    std::size_t experiments = 1;
    std::string time_unit;  ///< "s", or "" for a model without units
};

/// A panel per measured column (the data as points, the fit as a line, per experiment) and one of the residuals;
/// throws as plot() does.
void plot_fit(const FitPlotRequest& request);

}  // namespace eomgen::cli
