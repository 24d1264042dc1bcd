/** @file plot.cpp  gnuplot script for a run's CSV: coordinates, invariant drift, residuals, phase portrait. */
#include "cli/plot.hpp"

#include "cli/process.hpp"

#include "eomgen/column_units.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>


namespace eomgen::cli {
namespace fs = std::filesystem;
namespace {

std::vector<std::string> csv_header(const std::string& csv) {
    std::ifstream in(csv);
    std::string line;
    if (!std::getline(in, line)) throw std::runtime_error("cannot read " + csv);
    std::vector<std::string> names;
    std::istringstream fields(line);
    // The names without their units ("psi [rad]" is the column psi); the labels take units from the model.
    for (std::string f; std::getline(fields, f, ',');) names.push_back(eomgen::column_name(f));
    return names;
}

int column(const std::vector<std::string>& header, const std::string& name) {
    for (std::size_t i = 0; i < header.size(); ++i)
        if (header[i] == name) return static_cast<int>(i) + 1;  // gnuplot counts from 1
    throw std::runtime_error("the CSV has no column '" + name + "'");
}

/// An axis label or a curve's title: "x_bob [m]", or the name alone when it has no unit.
std::string labelled(const PlotColumn& c) {
    return c.unit.empty() ? c.name : c.name + " [" + c.unit + "]";
}

}  // namespace

std::string rate_unit(const std::string& unit) {
    if (unit.empty()) return "";
    return unit == "1" ? "1/s" : unit + "/s";
}

std::string gnuplot_string(const std::string& s) {
    std::string out = "'";
    for (const char c : s) {
        if (c == '\n' || c == '\r') {
            out += ' ';
            continue;
        }
        if (c == '\'') out += '\'';
        out += c;
    }
    return out + "'";
}

void plot(const PlotRequest& r) {
    const std::vector<std::string> header = csv_header(r.csv);
    if (const std::string problem = plot_format_problem(r.output); !problem.empty())
        throw std::invalid_argument(problem);
    const std::string ext = fs::path(r.output).extension().string();
    std::vector<std::string> invariants, residuals;
    auto is_output = [&r](const std::string& name) {
        return std::any_of(r.outputs.begin(), r.outputs.end(),
                           [&](const PlotColumn& o) { return o.name == name; });
    };
    // Where the CSV has the work of the forces, h is not conserved: its panel shows the balance h - h0 - W.
    const bool balance = std::find(header.begin(), header.end(), "work") != header.end();
    for (std::size_t i = static_cast<std::size_t>(column(header, "energy")) - 1; i < header.size(); ++i) {
        if (is_output(header[i]) || header[i] == "work") continue;
        if (header[i].rfind("residual_", 0) == 0)
            residuals.push_back(header[i]);
        else if (header[i].rfind("lambda_", 0) != 0)
            invariants.push_back(header[i]);
    }
    const int rows = 2 + (r.outputs.empty() ? 0 : 1) + (residuals.empty() ? 0 : 1) +
                     (r.phase.empty() ? 0 : 1) + static_cast<int>(r.xy.size());
    std::ostringstream gp;
    gp << "set datafile separator ','\n";
    gp << (ext == ".png" ? "set terminal pngcairo size 1000," : "set terminal svg size 1000,") << 300 * rows
       << " noenhanced\n";
    gp << "set output " << gnuplot_string(r.output) << "\n";
    gp << "set multiplot layout " << rows << ",1 title " << gnuplot_string(r.title) << "\n";
    gp << "set key outside right\nset grid\nset xlabel 't [s]'\n";
    // Coordinates against t; the axis carries their unit when they share one, else each curve its own.
    const bool q_one_unit = std::all_of(r.coordinates.begin(), r.coordinates.end(),
                                        [&r](const PlotColumn& c) { return c.unit == r.coordinates[0].unit; });
    gp << "set ylabel " << gnuplot_string(q_one_unit && !r.coordinates.empty() ? labelled({"q", r.coordinates[0].unit}) : "q")
       << "\nplot ";
    for (std::size_t i = 0; i < r.coordinates.size(); ++i)
        gp << (i ? ", " : "") << gnuplot_string(r.csv) << " every ::1 using 1:" << column(header, r.coordinates[i].name)
           << " with lines title " << gnuplot_string(q_one_unit ? r.coordinates[i].name : labelled(r.coordinates[i]));
    gp << "\n";
    // Declared outputs against t; the axis carries their unit when they share one.
    if (!r.outputs.empty()) {
        const bool one_unit = std::all_of(r.outputs.begin(), r.outputs.end(),
                                          [&r](const PlotColumn& o) { return o.unit == r.outputs[0].unit; });
        gp << "set ylabel " << gnuplot_string(one_unit ? labelled({"outputs", r.outputs[0].unit}) : "outputs")
           << "\nplot ";
        for (std::size_t i = 0; i < r.outputs.size(); ++i)
            gp << (i ? ", " : "") << gnuplot_string(r.csv)
               << " every ::1 using 1:" << column(header, r.outputs[i].name) << " with lines title "
               << gnuplot_string(one_unit ? r.outputs[i].name : labelled(r.outputs[i]));
        gp << "\n";
    }
    // Relative drift of each invariant, from its first sample, on a log scale (floored at 1e-17 so that an
    // exactly kept quantity still draws).
    for (std::size_t k = 0; k < invariants.size(); ++k)
        gp << "stats " << gnuplot_string(r.csv) << " every ::1::1 using " << column(header, invariants[k])
           << " name 'I" << k << "' nooutput\n";
    gp << "set logscale y\nset format y '%.0e'\nset ylabel 'relative drift (floor 1e-17)'\nplot ";
    for (std::size_t k = 0; k < invariants.size(); ++k) {
        const std::string first = "I" + std::to_string(k) + "_min";
        const bool h = balance && invariants[k] == "energy";  // h − h0 − W: the energy balance
        gp << (k ? ", " : "") << gnuplot_string(r.csv) << " every ::1 using 1:(abs($" << column(header, invariants[k])
           << " - " << first << (h ? " - $" + std::to_string(column(header, "work")) : std::string()) << ")/(abs("
           << first << ") > 1e-300 ? abs(" << first << ") : 1) + 1e-17) with lines title "
           << gnuplot_string(h ? "energy balance h - h0 - W" : invariants[k]);
    }
    gp << "\n";
    if (!residuals.empty()) {
        gp << "set ylabel 'constraint residual'\nplot ";
        for (std::size_t k = 0; k < residuals.size(); ++k)
            gp << (k ? ", " : "") << gnuplot_string(r.csv) << " every ::1 using 1:(abs($"
               << column(header, residuals[k]) << ") + 1e-17) with lines title " << gnuplot_string(residuals[k]);
        gp << "\n";
    }
    gp << "unset logscale y\nset format y '% h'\n";
    if (!r.phase.empty()) {
        std::string unit;
        for (const PlotColumn& c : r.coordinates)
            if (c.name == r.phase) unit = c.unit;
        gp << "set xlabel " << gnuplot_string(labelled({r.phase, unit})) << "\nset ylabel "
           << gnuplot_string(labelled({r.phase + "_dot", rate_unit(unit)})) << "\n";
        gp << "plot " << gnuplot_string(r.csv) << " every ::1 using " << column(header, r.phase) << ":"
           << column(header, r.phase + "_dot") << " with lines title 'phase portrait'\n";
    }
    // y against x (e.g. the path of a point from two outputs), to scale when both are in one unit.
    for (const auto& [x, y] : r.xy) {
        const bool to_scale = !x.unit.empty() && x.unit == y.unit;
        gp << "set xlabel " << gnuplot_string(labelled(x)) << "\nset ylabel " << gnuplot_string(labelled(y))
           << "\n"
           << (to_scale ? "set size ratio -1\n" : "");
        gp << "plot " << gnuplot_string(r.csv) << " every ::1 using " << column(header, x.name) << ":"
           << column(header, y.name) << " with lines title " << gnuplot_string(y.name + " against " + x.name)
           << "\n"
           << (to_scale ? "set size noratio\n" : "");
    }
    gp << "unset multiplot\n";

    run_gnuplot(gp.str(), r.output);
}

void run_gnuplot(const std::string& script_text, const std::string& output) {
    // The script goes to a private temporary file; gnuplot gets it as an argument (no shell).
    const TempDir dir(fs::temp_directory_path(), "eomgen-plot.");
    const fs::path script = dir.path() / "plot.gp", log = dir.path() / "gnuplot.log";
    std::ofstream(script) << script_text;
    int status = 0;
    try {
        status = run_program({"gnuplot", script.string()}, log);
    } catch (const ProgramNotStarted& e) {
        throw std::runtime_error(std::string("cannot start gnuplot: ") + e.what() + " (install gnuplot-nox)");
    }
    if (status != 0 || !fs::exists(output))
        throw std::runtime_error("gnuplot failed to draw " + output + ": " + read_file(log));
}

void plot_table(const TablePlotRequest& r) {
    if (const std::string problem = plot_format_problem(r.output); !problem.empty())
        throw std::invalid_argument(problem);
    const std::vector<std::string> header = csv_header(r.csv);
    const int x = column(header, r.x.name), y = column(header, r.y.name), status = column(header, r.status);
    const std::string ext = fs::path(r.output).extension().string();
    std::ostringstream gp;
    gp << "set datafile separator ','\n";
    gp << (ext == ".png" ? "set terminal pngcairo size 1000,600" : "set terminal svg size 1000,600") << " noenhanced\n";
    gp << "set output " << gnuplot_string(r.output) << "\n";
    gp << "set title " << gnuplot_string(r.title) << "\nset grid\nset key top right\n";
    gp << "set xlabel " << gnuplot_string(labelled(r.x)) << "\nset ylabel " << gnuplot_string(labelled(r.y)) << "\n";
    // Failed members have no y: their rows are left out (NaN is not drawn), and the key counts them.
    gp << "plot " << gnuplot_string(r.csv) << " every ::1 using " << x << ":(strcol(" << status
       << ") eq 'ok' ? column(" << y << ") : NaN) with " << (r.lines ? "linespoints" : "points")
       << " pointtype 7 pointsize 0.6 title " << gnuplot_string(r.key) << "\n";
    run_gnuplot(gp.str(), r.output);
}

std::string plot_format_problem(const std::string& output) {
    const std::string ext = fs::path(output).extension().string();
    if (ext == ".png" || ext == ".svg") return {};
    return "--plot " + output + ": the file name must end in .png or .svg";
}

}  // namespace eomgen::cli
