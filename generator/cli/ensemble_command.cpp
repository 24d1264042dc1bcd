/** @file ensemble_command.cpp  `eomgen run --sweep/--sample`: members → rows of a CSV table, and its plot. */
#include "cli/ensemble_command.hpp"
#include "table_driver.hpp"  // the driver for TableModel, compiled once

#include "cli/plot.hpp"
#include "cli/process.hpp"
#include "eomgen/ensemble.hpp"
#include "eomgen/model_table.hpp"
#include "eomgen/output.hpp"
#include "output/atomic_file.hpp"

#ifdef EOMGEN_HAVE_MPI
#include "cli/ensemble_mpi.hpp"
#endif
#ifdef EOMGEN_HAVE_HDF5
#include "cli/ensemble_hdf5.hpp"
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

namespace eomgen::cli {
namespace fs = std::filesystem;
using eomgen::TableModel;
using eomgen::sim::UsageError;

namespace {

using eomgen::csv_number;

/// The row of one member: its varied values, then what it gave (ensemble_columns' order). Only t may be
/// unknown (a failure without a time: empty); any other NaN, e.g. an output's, is written as nan.
std::vector<std::string> row(const eomgen::MemberResult<TableModel>& r, const std::vector<double>& varied,
                             std::size_t n_state, std::size_t n_outputs, std::size_t n_sensitivities,
                             bool with_event_time) {
    std::vector<std::string> f{std::to_string(r.index)};
    for (const double v : varied) f.push_back(csv_number(v));
    f.push_back(r.ok ? "ok" : "failed");
    f.push_back(r.ok ? (r.stopped_by.empty() ? "t_end" : r.stopped_by) : "");
    f.push_back(std::isnan(r.t) ? "" : csv_number(r.t));
    for (std::size_t i = 0; i < n_state; ++i) f.push_back(r.ok ? csv_number(r.x(Eigen::Index(i))) : "");
    f.push_back(r.ok ? csv_number(r.energy) : "");
    for (std::size_t i = 0; i < n_outputs; ++i) f.push_back(r.ok ? csv_number(r.outputs(Eigen::Index(i))) : "");
    // The sensitivities' columns (ensemble_columns): per column, the state's, the outputs', and the event time's.
    for (std::size_t c = 0; c < n_sensitivities; ++c) {
        const Eigen::Index k = Eigen::Index(c);
        for (std::size_t i = 0; i < n_state; ++i) f.push_back(r.ok ? csv_number(r.S(Eigen::Index(i), k)) : "");
        for (std::size_t i = 0; i < n_outputs; ++i)
            f.push_back(r.ok && r.Y.size() > 0 ? csv_number(r.Y(Eigen::Index(i), k)) : "");
        if (with_event_time) f.push_back(r.ok && r.dt.size() > 0 ? csv_number(r.dt(k)) : "");
    }
    f.push_back(r.error);
    return f;
}

/// The unit of a column for the plot's axes: a parameter's or an output's from the model file, s for t.
std::string unit_of(const Model& model, const std::string& column) {
    if (column == "t") return "s";
    for (const Parameter& p : model.parameters)
        if (p.name == column) return p.unit;
    for (const DeclaredOutput& o : model.outputs)
        if (o.name == column) return o.unit;
    return "";
}

bool is_hdf5(const std::string& path) { return fs::path(path).extension() == ".h5"; }

/// Where an ensemble's rows go: a CSV file written atomically, stdout, or both (a plot's copy and stdout),
/// and an HDF5 file (--out FILE.h5) beside them.
class TableSink {
  public:
    TableSink(const std::string& csv, bool to_stdout, const std::vector<std::string>& columns) : to_stdout_(to_stdout) {
        if (!csv.empty()) file_.emplace(csv);
        write(columns);  // the CSV's header; an HDF5 table, added after, names its datasets instead
    }
#ifdef EOMGEN_HAVE_HDF5
    void also_hdf5(Hdf5Table table) { hdf5_.emplace(std::move(table)); }
#endif
    void write(const std::vector<std::string>& fields) {
        const std::string line = eomgen::csv_row(fields);
        if (file_) file_->write(line);
        if (to_stdout_) std::cout << line;
#ifdef EOMGEN_HAVE_HDF5
        if (hdf5_) hdf5_->add(fields);
#endif
    }
    void commit() {
        if (file_) file_->commit();
#ifdef EOMGEN_HAVE_HDF5
        if (hdf5_) hdf5_->commit();
#endif
        std::cout.flush();
    }

  private:
    std::optional<eomgen::output::AtomicFile> file_;
    bool to_stdout_;
#ifdef EOMGEN_HAVE_HDF5
    std::optional<Hdf5Table> hdf5_;
#endif
};

}  // namespace

bool first_rank() {
    for (const char* v : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
        if (const char* rank = std::getenv(v)) return std::atoi(rank) == 0;
    return true;
}

std::vector<std::string> ensemble_columns(const EnsembleDesign& design, const std::vector<std::string>& states,
                                          const std::vector<std::string>& outputs,
                                          const std::vector<std::string>& sensitivities, bool with_event_time) {
    std::vector<std::string> c{"member"};
    for (const EnsembleVariable& v : design.variables()) c.push_back(v.is_state ? v.name + "(0)" : v.name);
    c.insert(c.end(), {"status", "stopped", "t"});
    c.insert(c.end(), states.begin(), states.end());
    c.push_back("energy");
    c.insert(c.end(), outputs.begin(), outputs.end());
    for (const std::string& by : sensitivities) {
        for (const std::string& s : states) c.push_back("d" + s + "/d" + by);
        for (const std::string& y : outputs) c.push_back("d" + y + "/d" + by);
        if (with_event_time) c.push_back("dt/d" + by);
    }
    c.push_back("message");
    return c;
}

/// The SI unit of each of ensemble_columns' columns (TableModel bound): the varied values', t's, the state's, h's
/// and the outputs'; "" for the member, status, stopped and message, and where the model declares none.
static std::vector<std::string> ensemble_units(const EnsembleDesign& design,
                                               const std::vector<eomgen::sim::SensitivityLabel>& labels,
                                               bool with_event_time, std::size_t n_columns) {
    std::vector<std::string> u{""};
    for (const EnsembleVariable& v : design.variables()) {
        const auto& names = v.is_state ? TableModel::state_names : TableModel::param_names;
        const auto& units = v.is_state ? TableModel::state_units : TableModel::param_units;
        std::string unit;
        for (std::size_t i = 0; i < names.size(); ++i)
            if (v.name == names[i]) unit = units[i];
        u.push_back(unit);
    }
    u.insert(u.end(), {"", "", eomgen::time_unit<TableModel>()});
    u.insert(u.end(), TableModel::state_units.begin(), TableModel::state_units.end());
    u.push_back(TableModel::energy_unit);
    u.insert(u.end(), TableModel::output_units.begin(), TableModel::output_units.end());
    using eomgen::sim::unit_ratio;
    for (const auto& label : labels) {
        for (std::size_t i = 0; i < TableModel::state_names.size(); ++i)
            u.push_back(unit_ratio(eomgen::state_unit<TableModel>(i), label.unit));
        for (std::size_t i = 0; i < TableModel::output_names.size(); ++i)
            u.push_back(unit_ratio(eomgen::output_unit<TableModel>(i), label.unit));
        if (with_event_time) u.push_back(unit_ratio(eomgen::time_unit<TableModel>(), label.unit));
    }
    u.push_back("");
    u.resize(n_columns);
    return u;
}

int run_ensemble(const EnsembleRequest& req) {
    int rank = 0;
#ifdef EOMGEN_HAVE_MPI
    // Every rank reads the same command line and so refuses the same mistakes; rank 0 alone says so.
    MpiSession mpi;
    rank = mpi.rank();
#else
    if (const char* size = std::getenv("OMPI_COMM_WORLD_SIZE"); size && std::atoi(size) > 1)
        std::cerr << "eomgen run: warning: this eomgen was built without MPI, so each of the " << size
                  << " processes runs the whole ensemble\n";
#endif
    auto fail = [rank](int code, const std::string& message) {
        if (rank == 0) std::cerr << "eomgen run: " << message << "\n";
        return code;
    };
    const eomgen::sim::Options& o = req.options;
    std::vector<std::string> states(TableModel::state_names.begin(), TableModel::state_names.end());
    std::vector<std::string> outputs(TableModel::output_names.begin(), TableModel::output_names.end());
    std::optional<EnsembleDesign> design;
    TableModel::Params base;
    TableModel::State x0 = TableModel::default_state();
    std::vector<std::string> columns;
    std::vector<eomgen::sim::SensitivityLabel> labels;  // --sensitivities' columns
    std::vector<std::string> by;                        // their names in the headers: "theta", "psi(0)"
    const bool with_event_time = !o.until.empty();
    std::pair<PlotColumn, PlotColumn> xy;
    try {
        const EnsembleNames names{{TableModel::param_names.begin(), TableModel::param_names.end()}, states};
        design.emplace(req.design, names);
        if (!o.csv.empty())
            throw UsageError("--csv writes the samples of one run; an ensemble writes one row per member to --out");
        eomgen::sim::check_options(o);
        eomgen::sim::apply_settings<TableModel>(o, base, x0);
        for (const EnsembleVariable& v : design->variables())
            for (const std::string& s : v.is_state ? o.init : o.set)
                if (s.rfind(v.name + "=", 0) == 0)
                    throw UsageError((v.is_state ? "--init " : "--set ") + s + ": " + v.name +
                                     " is varied by the ensemble; leave it out of " +
                                     (v.is_state ? "--init" : "--set"));
        labels = eomgen::sim::sensitivity_labels<TableModel>(o);
        if (!labels.empty()) eomgen::sim::check_sensitivity_method<TableModel>(o);
        for (const auto& label : labels) by.push_back(label.name);
        columns = ensemble_columns(*design, states, outputs, by, with_event_time);
#ifndef EOMGEN_HAVE_HDF5
        if (is_hdf5(req.out))
            throw UsageError("--out " + req.out + ": this eomgen was built without HDF5 (libhdf5-dev); write a .csv");
#endif
        if (!req.plot.empty()) {
            if (const std::string problem = plot_format_problem(req.plot); !problem.empty()) throw UsageError(problem);
            if (req.plot_xy.size() > 1) throw UsageError("--plot-xy: an ensemble's plot takes one X,Y");
            std::string x = columns[1], y = o.until.empty() ? (outputs.empty() ? states[0] : outputs[0]) : "t";
            if (!req.plot_xy.empty()) {
                const std::string& spec = req.plot_xy[0];
                const auto comma = spec.find(',');
                if (comma == std::string::npos) throw UsageError("--plot-xy " + spec + ": expected X,Y, e.g. theta,t");
                x = spec.substr(0, comma);
                y = spec.substr(comma + 1);
                for (const std::string& name : {x, y})
                    if (std::find(columns.begin() + 1, columns.end() - 1, name) == columns.end() - 1 ||
                        name == "status" || name == "stopped")
                        throw UsageError("--plot-xy " + spec + ": no numeric column '" + name + "'" +
                                         eomgen::sim::did_you_mean(name, columns) + " (columns: " +
                                         eomgen::sim::list(columns) + ")");
            }
            xy = {{x, unit_of(*req.model, x)}, {y, unit_of(*req.model, y)}};
        } else if (!req.plot_xy.empty()) {
            throw UsageError("--plot-xy needs --plot");
        }
        (void)eomgen::sim::until_events<TableModel>(o);  // a bad --until is refused before any member runs
    } catch (const UsageError& e) {
        return fail(2, e.what());
    }
    for (const auto& [option, path] : {std::pair<std::string, std::string>{"--out", req.out}, {"--plot", req.plot}})
        if (!path.empty())
            if (const std::string problem = eomgen::sim::output_path_problem(option, path); !problem.empty())
                return fail(3, problem);

    eomgen::EnsembleOptions options;
    options.simulation = o;
    options.simulation.set.clear();
    options.simulation.init.clear();
    options.threads = req.threads;
    auto member = [&](std::size_t i) {
        eomgen::Member<TableModel> m{base, x0};
        const std::vector<double> v = design->values(i);
        for (std::size_t k = 0; k < v.size(); ++k) {
            const EnsembleVariable& var = design->variables()[k];
            if (var.is_state)
                m.x0(var.index) = v[k];
            else
                TableModel::set_param(m.params, var.name, v[k]);
        }
        return m;
    };

    // A plot without --out draws from a private temporary copy of the table.
    std::optional<TempDir> tmp;
    std::string table_path = is_hdf5(req.out) ? "" : req.out;  // the CSV
    if (!req.plot.empty() && table_path.empty() && rank == 0) {
        tmp.emplace(fs::temp_directory_path(), "eomgen-ensemble.");
        table_path = (tmp->path() / "ensemble.csv").string();
    }
    const auto start = std::chrono::steady_clock::now();
    std::size_t failed = 0;
    try {
        std::optional<TableSink> table;
        // The CSV's header names each column with its unit ("psi [rad]"); HDF5 gives units as attributes.
        std::vector<std::string> units = ensemble_units(*design, labels, with_event_time, columns.size()), header;
        for (std::size_t k = 0; k < columns.size(); ++k) header.push_back(eomgen::with_unit(columns[k], units[k]));
        if (rank == 0) table.emplace(table_path, req.out.empty(), header);
#ifdef EOMGEN_HAVE_HDF5
        if (table && is_hdf5(req.out)) {
            std::vector<bool> numeric;
            for (const std::string& c : columns) numeric.push_back(c != "status" && c != "stopped" && c != "message");
            std::string sets, inits, varied;
            for (const std::string& v : o.set) sets += (sets.empty() ? "" : " ") + v;
            for (const std::string& v : o.init) inits += (inits.empty() ? "" : " ") + v;
            for (const std::string& v : req.design.sweeps) varied += (varied.empty() ? "--sweep " : " --sweep ") + v;
            if (req.design.sample >= 0) varied = "--sample " + std::to_string(req.design.sample);
            for (const std::string& v : req.design.dists) varied += " --dist " + v;
            if (req.design.sample >= 0) varied += " --seed " + std::to_string(req.design.seed);
            table->also_hdf5(Hdf5Table(req.out, columns, numeric, units,
                                       {{"eomgen_version", EOMGEN_VERSION},
                                        {"model", req.model->name},
                                        {"model_file", req.model_path},
                                        {"model_hash", req.model_hash},
                                        {"design", design->describe()},
                                        {"varied", varied},
                                        {"members", std::to_string(design->size())},
                                        {"method", o.method},
                                        {"rtol", csv_number(o.rtol)},
                                        {"atol", csv_number(o.atol)},
                                        {"dt", csv_number(o.dt)},
                                        {"t_end", csv_number(o.t_end)},
                                        {"until", o.until},
                                        {"max_steps", std::to_string(o.max_steps)},
                                        {"set", sets},
                                        {"init", inits}}));
        }
#endif
        auto sink = [&](const eomgen::MemberResult<TableModel>& r) {
            failed += r.ok ? 0 : 1;
            table->write(row(r, design->values(r.index), states.size(), outputs.size(), labels.size(), with_event_time));
        };
#ifdef EOMGEN_HAVE_MPI
        if (mpi.size() > 1)
            mpi_ensemble(mpi, design->size(), member, options, sink);
        else
#endif
            eomgen::ensemble<TableModel>(design->size(), member, options, sink);
        if (table) table->commit();
    } catch (const UsageError& e) {
        return fail(2, e.what());
    } catch (const eomgen::output::WriteError& e) {
        return fail(3, e.what());
    }
    if (rank != 0) return 0;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // With the table on stdout, the summary goes to stderr.
    std::ostream& say = req.out.empty() ? std::cerr : std::cout;
    auto threads = [](unsigned n) { return std::to_string(n) + (n == 1 ? " thread" : " threads"); };
    std::string where = threads(eomgen::thread_count(req.threads));
#ifdef EOMGEN_HAVE_MPI
    if (mpi.size() > 1) where = threads(mpi.threads(req.threads)) + " in each of " + std::to_string(mpi.size()) + " MPI ranks";
#endif
    std::ostringstream took;
    took.precision(3);
    took << seconds;
    say << "ensemble: " << design->size() << " members (" << design->describe() << "), " << failed << " failed, on "
        << where << ", " << took.str() << " s\n";
    if (!req.out.empty()) say << "table:   " << req.out << "\n";
    if (!req.plot.empty()) {
        if (failed == design->size()) return fail(2, "--plot " + req.plot + ": every member failed, nothing to draw");
        TablePlotRequest p;
        p.csv = table_path;
        p.output = req.plot;
        p.title = req.model->title.empty() ? req.model->name : req.model->title;
        p.key = xy.second.name + " against " + xy.first.name + " (" + design->describe() + ")";
        p.x = xy.first;
        p.y = xy.second;
        p.status = "status";
        p.lines = design->variables().size() == 1 && req.design.sweeps.size() == 1;
        try {
            plot_table(p);
        } catch (const std::runtime_error& e) {
            return fail(3, e.what());
        }
        say << "plot:    " << req.plot << "\n";
    }
    return 0;
}

}  // namespace eomgen::cli
