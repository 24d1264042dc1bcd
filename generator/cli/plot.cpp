/** @file plot.cpp  gnuplot script for a run's CSV: coordinates, invariant drift, residuals, phase portrait. */
#include "cli/plot.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace eomgen::cli {
namespace fs = std::filesystem;
namespace {

std::vector<std::string> csv_header(const std::string& csv) {
    std::ifstream in(csv);
    std::string line;
    if (!std::getline(in, line)) throw std::runtime_error("cannot read " + csv);
    std::vector<std::string> names;
    std::istringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) names.push_back(f);
    return names;
}

int column(const std::vector<std::string>& header, const std::string& name) {
    for (std::size_t i = 0; i < header.size(); ++i)
        if (header[i] == name) return static_cast<int>(i) + 1;  // gnuplot counts from 1
    throw std::runtime_error("the CSV has no column '" + name + "'");
}

std::string read_all(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

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
    const std::string ext = fs::path(r.output).extension().string();
    if (ext != ".png" && ext != ".svg")
        throw std::invalid_argument("--plot " + r.output + ": the file name must end in .png or .svg");
    const int rows = 2 + (r.residuals.empty() ? 0 : 1) + (r.phase.empty() ? 0 : 1);
    std::ostringstream gp;
    gp << "set datafile separator ','\n";
    gp << (ext == ".png" ? "set terminal pngcairo size 1000," : "set terminal svg size 1000,") << 300 * rows
       << " noenhanced\n";
    gp << "set output " << gnuplot_string(r.output) << "\n";
    gp << "set multiplot layout " << rows << ",1 title " << gnuplot_string(r.title) << "\n";
    gp << "set key outside right\nset grid\nset xlabel 't [s]'\n";
    // Coordinates against t.
    std::string units;
    for (const std::string& u : r.units)
        if (!u.empty() && units.find(u) == std::string::npos) units += (units.empty() ? "" : ", ") + u;
    gp << "set ylabel " << gnuplot_string(units.empty() ? "q" : "q [" + units + "]") << "\n";
    gp << "plot ";
    for (std::size_t i = 0; i < r.coordinates.size(); ++i)
        gp << (i ? ", " : "") << gnuplot_string(r.csv) << " every ::1 using 1:" << column(header, r.coordinates[i])
           << " with lines title " << gnuplot_string(r.coordinates[i]);
    gp << "\n";
    // Relative drift of each invariant, from its first sample, on a log scale (floored at 1e-17 so that an
    // exactly kept quantity still draws).
    for (std::size_t k = 0; k < r.invariants.size(); ++k)
        gp << "stats " << gnuplot_string(r.csv) << " every ::1::1 using " << column(header, r.invariants[k])
           << " name 'I" << k << "' nooutput\n";
    gp << "set logscale y\nset format y '%.0e'\nset ylabel 'relative drift (floor 1e-17)'\nplot ";
    for (std::size_t k = 0; k < r.invariants.size(); ++k) {
        const std::string first = "I" + std::to_string(k) + "_min";
        gp << (k ? ", " : "") << gnuplot_string(r.csv) << " every ::1 using 1:(abs($" << column(header, r.invariants[k])
           << " - " << first << ")/(abs(" << first << ") > 1e-300 ? abs(" << first << ") : 1) + 1e-17) with lines title "
           << gnuplot_string(r.invariants[k]);
    }
    gp << "\n";
    if (!r.residuals.empty()) {
        gp << "set ylabel 'constraint residual'\nplot ";
        for (std::size_t k = 0; k < r.residuals.size(); ++k)
            gp << (k ? ", " : "") << gnuplot_string(r.csv) << " every ::1 using 1:(abs($"
               << column(header, r.residuals[k]) << ") + 1e-17) with lines title " << gnuplot_string(r.residuals[k]);
        gp << "\n";
    }
    gp << "unset logscale y\nset format y '% h'\n";
    if (!r.phase.empty()) {
        gp << "set xlabel " << gnuplot_string(r.phase) << "\nset ylabel " << gnuplot_string(r.phase + "_dot") << "\n";
        gp << "plot " << gnuplot_string(r.csv) << " every ::1 using " << column(header, r.phase) << ":"
           << column(header, r.phase + "_dot") << " with lines title 'phase portrait'\n";
    }
    gp << "unset multiplot\n";

    // The script goes to a private temporary file; gnuplot gets it as an argument (no shell).
    std::string dir_pattern = (fs::temp_directory_path() / "eomgen-plot.XXXXXX").string();
    if (!::mkdtemp(dir_pattern.data())) throw std::runtime_error("cannot create a temporary directory");
    const fs::path dir = dir_pattern, script = dir / "plot.gp", log = dir / "gnuplot.log";
    std::ofstream(script) << gp.str();
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    std::string program = "gnuplot", script_arg = script.string();
    char* argv[] = {program.data(), script_arg.data(), nullptr};
    pid_t pid = 0;
    const int err = ::posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    int status = 1;
    if (err == 0)
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
    const std::string messages = err == 0 ? read_all(log) : std::string(std::strerror(err));
    std::error_code ec;
    fs::remove_all(dir, ec);
    if (err != 0) throw std::runtime_error("cannot start gnuplot: " + messages + " (install gnuplot-nox)");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !fs::exists(r.output))
        throw std::runtime_error("gnuplot failed to draw " + r.output + ": " + messages);
}

}  // namespace eomgen::cli
