/** @file plot.hpp  `--plot`: a run's CSV drawn by gnuplot (PNG or SVG), started without a shell. */
#pragma once

#include <string>
#include <vector>

namespace eomgen::cli {

struct PlotRequest {
    std::string csv;                     ///< the run's samples (eomgen::write_csv's format)
    std::string output;                  ///< FILE.png or FILE.svg
    std::string title;                   ///< the model's title (escaped for gnuplot here)
    std::vector<std::string> coordinates;
    std::vector<std::string> units;      ///< per coordinate, may be empty
    std::vector<std::string> invariants; ///< CSV columns whose relative drift is drawn: energy, conserved
    std::vector<std::string> residuals;  ///< residual_<constraint> columns
    std::string phase;                   ///< a coordinate for q' against q, or ""
};

/// Writes the plot; throws std::runtime_error with gnuplot's message when it fails.
void plot(const PlotRequest& request);

/// A gnuplot single-quoted string: the only special character there is ' itself, written twice.
std::string gnuplot_string(const std::string& s);

}  // namespace eomgen::cli
