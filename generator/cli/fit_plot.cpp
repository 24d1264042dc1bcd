/** @file fit_plot.cpp  The plot of `eomgen fit --plot` (fit_plot.hpp). */
#include "cli/fit_plot.hpp"

#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace eomgen::cli {

void plot_fit(const FitPlotRequest& r) {
    if (const std::string problem = plot_format_problem(r.output); !problem.empty()) throw std::invalid_argument(problem);
    const bool several = r.experiments > 1;
    const int t = several ? 2 : 1;  // the CSV's column of t (gnuplot counts from 1)
    const std::size_t panels = r.columns.size() + 1;
    const std::string ext = std::filesystem::path(r.output).extension().string();
    const std::string file = gnuplot_string(r.csv);
    std::ostringstream gp;
    gp << "set datafile separator ','\n";
    gp << (ext == ".png" ? "set terminal pngcairo size 1000," : "set terminal svg size 1000,") << 280 * panels
       << " noenhanced\n";
    gp << "set output " << gnuplot_string(r.output) << "\n";
    gp << "set multiplot layout " << panels << ",1 title " << gnuplot_string(r.title) << "\n";
    gp << "set grid\nset key top right\n";
    // One experiment's rows: the column where the experiment column is e, else NaN (which also breaks the line).
    const auto only = [&](std::size_t e, int column) {
        return several ? "($1 == " + std::to_string(e + 1) + " ? $" + std::to_string(column) + " : NaN)"
                       : "($" + std::to_string(column) + ")";
    };
    const auto label = [&](const PlotColumn& c, const std::string& what) {
        return gnuplot_string(c.name + what + (c.unit.empty() ? "" : " [" + c.unit + "]"));
    };
    for (std::size_t c = 0; c < r.columns.size(); ++c) {
        const int data = t + 1 + 3 * int(c), model = data + 1;
        gp << "set ylabel " << label(r.columns[c], "") << "\nplot ";
        for (std::size_t e = 0; e < r.experiments; ++e) {
            const std::string which = several ? " [" + std::to_string(e + 1) + "]" : "";
            gp << (e ? ", " : "") << file << " every ::1 using " << t << ":" << only(e, data)
               << " with points pt 7 ps 0.5 lc " << e + 1 << " title " << gnuplot_string("data" + which) << ", "
               << file << " every ::1 using " << t << ":" << only(e, model) << " with lines lw 1.5 lc rgb 'black'"
               << " title " << gnuplot_string(e ? "" : "fit");
        }
        gp << "\n";
    }
    gp << "set xlabel " << gnuplot_string(r.time_unit.empty() ? "t" : "t [" + r.time_unit + "]")
       << "\nset ylabel 'residual (model - data)'\nplot ";
    for (std::size_t c = 0; c < r.columns.size(); ++c) {
        const int residual = t + 3 + 3 * int(c);
        gp << (c ? ", " : "") << file << " every ::1 using " << t << ":" << residual << " with points pt 7 ps 0.3 title "
           << label(r.columns[c], "");
    }
    gp << "\nunset multiplot\n";
    run_gnuplot(gp.str(), r.output);
}

}  // namespace eomgen::cli
