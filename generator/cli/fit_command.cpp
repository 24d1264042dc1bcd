/** @file fit_command.cpp  `eomgen fit`: model file and measured data → estimates, standard errors, correlations. */
#include "cli/fit_command.hpp"

#include "cli/compiled_model.hpp"
#include "cli/model_functions.hpp"
#include "cli/fit_data.hpp"
#include "cli/fit_plot.hpp"
#include "cli/fit_solve.hpp"
#include "cli/model_unit_values.hpp"
#include "cli/process.hpp"
#include "cli/run_command.hpp"
#include "eomgen/column_units.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"
#include "output/atomic_file.hpp"
#include "text/escape.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include <unistd.h>

namespace eomgen::cli {
namespace fs = std::filesystem;

namespace {

using output::write_atomically;
using text::csv_field;
using text::json_string;

constexpr int kExitNotConverged = 5;

/// "1.2345 m" with `digits` significant digits (10: an estimate; 3: its standard error); "-" for NaN.
std::string value(double v, const std::string& unit = "", int digits = 10) {
    if (std::isnan(v)) return "-";
    std::ostringstream os;
    os << std::setprecision(digits) << v;
    return os.str() + (unit.empty() ? "" : " " + unit);
}

std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    std::ostringstream os;
    os << std::setprecision(17) << v;
    return os.str();
}

/// The SI unit of a measurable column: state i below 2 nq, else output i − 2 nq.
std::string measured_unit(int i) {
    const std::size_t states = TableModel::state_names.size();
    return std::size_t(i) < states ? state_unit<TableModel>(std::size_t(i))
                                   : output_unit<TableModel>(std::size_t(i) - states);
}

std::string unit_of(const FreeValue& f) {
    return f.column.kind == SensitivityColumn::Kind::Parameter ? param_unit<TableModel>(std::size_t(f.column.index))
                                                               : state_unit<TableModel>(std::size_t(f.column.index));
}

/// "dm/m = +0.707, dg/g = -0.707": a direction of relative changes that the data do not see.
std::string direction(const std::vector<FreeValue>& free, const Eigen::VectorXd& v) {
    std::ostringstream os;
    os << std::showpos << std::setprecision(3);
    bool first = true;
    for (std::size_t i = 0; i < free.size(); ++i) {
        if (std::abs(v(Eigen::Index(i))) <= 1e-3) continue;
        os << (first ? "" : ", ") << "d" << free[i].name << "/" << free[i].name << " = " << v(Eigen::Index(i));
        first = false;
    }
    return os.str();
}

/// --set or --init split by experiment: `shared` for every experiment, own[e] experiment e's (K:NAME=VALUE, K the
/// data file's place from 1, the prefix removed).
struct ByExperiment {
    std::vector<std::string> shared;
    std::vector<std::vector<std::string>> own;
};

ByExperiment by_experiment(const std::vector<std::string>& specs, std::size_t experiments, const char* option) {
    ByExperiment out;
    out.own.resize(experiments);
    for (const std::string& spec : specs) {
        int k = -1;
        const std::string rest = experiment_prefix(spec, experiments, option, k);
        (k < 0 ? out.shared : out.own[std::size_t(k)]).push_back(rest);
    }
    return out;
}

/// "; its own m = 1.5 kg, phi = 0.5 rad": what one experiment sets for itself (empty when nothing).
std::string own_settings(const std::vector<std::string>& set, const std::vector<std::string>& init) {
    std::string text;
    for (const auto* list : {&set, &init})
        for (const std::string& a : *list) {
            const auto [name, v] = sim::parse_assignment(a, "--set");
            const int p = sim::index_of(TableModel::param_names, name);
            const std::string unit = list == &set ? (p >= 0 ? param_unit<TableModel>(std::size_t(p)) : "")
                                                  : state_unit<TableModel>(std::size_t(sim::index_of(TableModel::state_names, name)));
            text += (text.empty() ? "; its own " : ", ") + name + " = " + value(v, unit);
        }
    return text;
}

/// "model:   damped_pendulum (…)" and the parameters held fixed, "fixed:   m = 1 kg, g = 9.81 m/s^2".
void print_heading(const TableModel::Params& params, const std::vector<FreeValue>& free, std::ostream& os) {
    const std::string title = TableModel::title, source = TableModel::source;
    const std::string about = title + (!title.empty() && !source.empty() ? "; " : "") + source;
    os << "model:   " << TableModel::name << (about.empty() ? "" : " (" + about + ")") << "\n";
    const auto values = TableModel::param_values(params);
    std::string fixed;
    for (std::size_t i = 0; i < values.size(); ++i) {
        bool is_free = false;
        for (const FreeValue& f : free)
            is_free = is_free || (f.column.kind == SensitivityColumn::Kind::Parameter && f.column.index == int(i));
        if (is_free) continue;
        const std::string unit = param_unit<TableModel>(i);
        fixed += (fixed.empty() ? "" : ", ") + std::string(TableModel::param_names[i]) + " = " + value(values[i], unit);
    }
    os << "fixed:   " << (fixed.empty() ? "(every parameter is free)" : fixed) << "\n";
}

void print_text(const std::vector<FreeValue>& free, const std::vector<MeasuredSeries>& experiments,
                const std::vector<std::string>& own, const FitOutcome& r, const sim::Options& o,
                const std::string& jacobian, const FitLoss& loss, std::ostream& os) {
    for (std::size_t e = 0; e < experiments.size(); ++e) {
        const MeasuredSeries& data = experiments[e];
        std::string columns;
        for (const auto& n : data.names) columns += (columns.empty() ? "" : ", ") + n;
        os << "data:    " << (experiments.size() > 1 ? "[" + std::to_string(e + 1) + "] " : "") << data.path << ": "
           << data.t.size() << " times x " << data.names.size() << " column" << (data.names.size() == 1 ? "" : "s")
           << " (" << columns << ")" << own[e] << "\n";
    }
    os << "         " << r.residuals << " measurements, " << free.size() << " unknowns\n";
    os << "solver:  Levenberg-Marquardt (Ceres), " << r.iterations << " iterations (" << r.trajectories
       << " integrations, " << std::setprecision(3) << r.solve_seconds << " s), "
       << (r.converged ? "converged" : "NOT converged") << ": " << r.termination << "\n";
    os << "         the Jacobian from " << (jacobian == "differences" ? "central differences of trajectories" : "the sensitivities")
       << ", " << o.method << " at rtol " << o.rtol << ", atol " << o.atol
       << "\n";
    if (loss.name != "squared")
        os << "loss:    " << loss.name << " with scale " << value(loss.scale, "", 4) << ": " << r.beyond_scale << " of "
           << r.residuals << " residuals beyond it count less than in least squares\n";
    os << "estimates (+- standard error, from J at the solution and the residuals' "
       << (loss.name == "squared" ? "variance" : "spread under the loss (Huber's M-estimator covariance)") << "):\n";
    for (std::size_t i = 0; i < free.size(); ++i) {
        const std::string unit = unit_of(free[i]);
        os << "  " << free[i].name << " = " << value(r.estimate[i], unit);
        if (!r.caveat.empty())
            os << " +- -";
        else if (std::isnan(r.standard_error[i]))
            os << " +- (not determined by the data)";
        else
            os << " +- " << value(r.standard_error[i], unit, 3);
        os << "   (start " << value(free[i].start) << ")\n";
    }
    os << "residuals: RMS " << value(r.rms, "", 4) << ", s = " << value(r.residual_sigma, "", 4) << " with "
       << r.residuals - free.size() << " degrees of freedom"
       << (loss.name == "squared" ? "" : " (s: the scale of the robust estimate)") << "\n";
    if (!r.caveat.empty()) os << "note:    " << r.caveat << "\n";
    if (free.size() > 1) {
        os << "correlation:\n" << std::setw(14) << "";
        for (const auto& f : free) os << std::setw(12) << f.name;
        os << "\n";
        for (std::size_t a = 0; a < free.size(); ++a) {
            os << "  " << std::setw(12) << std::left << free[a].name << std::right;
            for (std::size_t b = 0; b < free.size(); ++b) {
                const double c = r.correlation(Eigen::Index(a), Eigen::Index(b));
                std::ostringstream cell;
                if (std::isnan(c))
                    cell << "-";
                else
                    cell << std::fixed << std::setprecision(4) << c;
                os << std::setw(12) << cell.str();
            }
            os << "\n";
        }
    }
    for (const Eigen::VectorXd& v : r.undetermined)
        os << "not determined: changing the values along " << direction(free, v)
           << " (relative changes) leaves every residual unchanged to first order: the data fix only a combination "
              "of them; fix one with --set, or add data that separate them\n";
}

/// {"m": 1.5, "phi": 0.5}: one experiment's own settings, as numbers in SI.
std::string json_settings(const std::vector<std::string>& assignments) {
    std::string text;
    for (const std::string& a : assignments) {
        const auto [name, v] = sim::parse_assignment(a, "--set");
        text += (text.empty() ? "" : ", ") + json_string(name) + ": " + json_number(v);
    }
    return "{" + text + "}";
}

void print_json(const std::vector<FreeValue>& free, const std::vector<MeasuredSeries>& experiments,
                const ByExperiment& set, const ByExperiment& init, const FitOutcome& r, const FitLoss& loss,
                std::ostream& os) {
    std::string paths, own;
    for (std::size_t e = 0; e < experiments.size(); ++e) {
        paths += (e ? ", " : "") + json_string(experiments[e].path);
        own += std::string(e ? "," : "") + "\n    {\"data\": " + json_string(experiments[e].path) +
               ", \"set\": " + json_settings(set.own[e]) + ", \"init\": " + json_settings(init.own[e]) + "}";
    }
    os << "{\n  \"model\": " << json_string(TableModel::name) << ",\n  \"data\": [" << paths << "]"
       << ",\n  \"experiments\": [" << own << "\n  ]"
       << ",\n  \"loss\": {\"name\": " << json_string(loss.name) << ", \"scale\": " << json_number(loss.scale)
       << ", \"beyond_scale\": " << r.beyond_scale << "}"
       << ",\n  \"measurements\": " << r.residuals << ",\n  \"converged\": " << (r.converged ? "true" : "false")
       << ",\n  \"iterations\": " << r.iterations << ",\n  \"integrations\": " << r.trajectories
       << ",\n  \"solve_seconds\": " << json_number(r.solve_seconds) << ",\n  \"termination\": " << json_string(r.termination)
       << ",\n  \"estimates\": [";
    for (std::size_t i = 0; i < free.size(); ++i)
        os << (i ? "," : "") << "\n    {\"name\": " << json_string(free[i].name)
           << ", \"value\": " << json_number(r.estimate[i]) << ", \"standard_error\": " << json_number(r.standard_error[i])
           << ", \"unit\": " << json_string(unit_of(free[i])) << ", \"start\": " << json_number(free[i].start) << "}";
    os << "\n  ],\n  \"correlation\": [";
    for (std::size_t a = 0; a < free.size(); ++a) {
        os << (a ? ", " : "") << "[";
        for (std::size_t b = 0; b < free.size(); ++b)
            os << (b ? ", " : "") << json_number(r.correlation(Eigen::Index(a), Eigen::Index(b)));
        os << "]";
    }
    os << "],\n  \"rms\": " << json_number(r.rms) << ",\n  \"residual_sigma\": " << json_number(r.residual_sigma)
       << ",\n  \"caveat\": " << (r.caveat.empty() ? "null" : json_string(r.caveat))
       << ",\n  \"undetermined\": [";
    for (std::size_t u = 0; u < r.undetermined.size(); ++u) {
        os << (u ? ", " : "") << "{";
        bool first = true;
        for (std::size_t i = 0; i < free.size(); ++i) {
            os << (first ? "" : ", ") << json_string(free[i].name) << ": " << json_number(r.undetermined[u](Eigen::Index(i)));
            first = false;
        }
        os << "}";
    }
    os << "]\n}\n";
}

/// t, then per measured column the data, the fitted model and the residual (model − data); with several
/// experiments a first column `experiment` (1, 2, ...) and the columns of every experiment (empty where it has none).
std::string fitted_csv(const std::vector<MeasuredSeries>& experiments, const FitOutcome& r) {
    std::vector<std::pair<std::string, int>> columns;  // name, state index
    for (const MeasuredSeries& d : experiments)
        for (std::size_t c = 0; c < d.names.size(); ++c)
            if (std::none_of(columns.begin(), columns.end(), [&](const auto& k) { return k.first == d.names[c]; }))
                columns.emplace_back(d.names[c], d.index[c]);
    const bool several = experiments.size() > 1;
    std::ostringstream os;
    os << std::setprecision(17) << (several ? "experiment," : "") << with_unit("t", time_unit<TableModel>());
    for (const auto& [name, state] : columns)
        for (const char* suffix : {"", "_model", "_residual"})
            os << "," << csv_field(with_unit(name + suffix, measured_unit(state)));
    os << "\n";
    for (std::size_t e = 0; e < experiments.size(); ++e) {
        const MeasuredSeries& d = experiments[e];
        for (Eigen::Index j = 0; j < d.y.rows(); ++j) {
            if (several) os << e + 1 << ",";
            os << d.t[std::size_t(j)];
            for (const auto& column : columns) {
                const auto it = std::find(d.names.begin(), d.names.end(), column.first);
                if (it == d.names.end()) {
                    os << ",,,";
                    continue;
                }
                const Eigen::Index c = Eigen::Index(it - d.names.begin());
                os << "," << d.y(j, c) << "," << r.model[e](j, c) << "," << r.model[e](j, c) - d.y(j, c);
            }
            os << "\n";
        }
    }
    return os.str();
}

}  // namespace

FitCommand::FitCommand(CLI::App& app) {
    fit_ = app.add_subcommand("fit", "Fit parameters and initial values of a model file to measured time series "
                                     "(least squares, Ceres; standard errors and correlations)");
    fit_->add_option("model", model_path_, "Model file (.toml)")->required()->check(CLI::ExistingFile);
    fit_->add_option("data", data_paths_,
                     "CSV: t, then measured states (coordinates or NAME_dot) in their SI units; several files are "
                     "several experiments (each with its own free initial values)")
        ->required()
        ->check(CLI::ExistingFile);
    fit_->add_option("--free", free_, "An unknown: NAME[=start][:lo:hi] (a parameter) or x0:STATE[=start][:lo:hi], "
                                      "in SI; K:NAME for the K-th data file's own; repeatable")
        ->required();
    fit_->add_option("--weight", weights_, "COLUMN=W: the measured column's residuals times W (default 1); repeatable");
    fit_->add_option("--format", format_, "text or json")->check(CLI::IsMember({"text", "json"}))->capture_default_str();
    fit_->add_option("--csv", csv_, "Write t, each measured column, the fitted model and the residual to this CSV");
    fit_->add_option("--plot", plot_, "Plot the data against the fit and the residuals to FILE.png or FILE.svg (gnuplot)");
    fit_->add_option("--max-iterations", max_iterations_, "Largest number of Levenberg-Marquardt iterations")
        ->capture_default_str();
    fit_->add_option("--set", options_.set,
                     "Parameter value, NAME=VALUE (the fixed values; repeatable); K:NAME=VALUE for experiment K only "
                     "(the K-th data file)");
    fit_->add_option("--init", options_.init,
                     "Initial state, NAME=VALUE (repeatable); K:NAME=VALUE for experiment K only (the K-th data file)");
    fit_->add_option("--loss", loss_,
                     "squared (least squares), or a robust loss against outliers with its scale in the residuals' "
                     "units after --weight: huber:S, soft_l1:S, cauchy:S, arctan:S, tukey:S")
        ->capture_default_str();
    fit_->add_option("--method", options_.method, "dopri5, dop853, adams or radau5")->capture_default_str();
    fit_->add_option("--rtol", options_.rtol, "Relative tolerance of the integrations")->capture_default_str();
    fit_->add_option("--atol", options_.atol, "Absolute tolerance of the integrations")->capture_default_str();
    fit_->add_option("--max-steps", options_.max_steps, "Largest number of steps of one integration")->capture_default_str();
    fit_->add_option("--jacobian", jacobian_,
                     "sensitivities (exact, integrated with the trajectory) or differences (Ceres' central differences "
                     "of whole trajectories: for comparison)")
        ->check(CLI::IsMember({"sensitivities", "differences"}))
        ->capture_default_str();
    fit_->add_flag("--no-cache", no_cache_, "Compile afresh and keep nothing in the cache");
    fit_->add_flag("--interpret", interpret_,
                   "Run the model on eomgen's interpreter instead of compiling it (as eomgen run --interpret)");
    fit_->add_flag("--quiet", quiet_, "No progress messages on stderr");
}

bool FitCommand::selected() const { return fit_->parsed(); }

int FitCommand::run() {
    try {
        return fit_model();
    } catch (const CompileError& e) {
        std::cerr << "eomgen fit: " << e.what() << "\n  command: " << e.command << "\n  log: " << e.log << "\n";
        return kExitCompiler;
    } catch (const CacheError& e) {
        std::cerr << "eomgen fit: " << e.what() << "\n";
        return 3;
    } catch (const TempDirError& e) {
        std::cerr << "eomgen fit: " << e.what() << "\n";
        return 3;
    } catch (const FitDataError& e) {
        std::cerr << "eomgen fit: " << e.what() << "\n";
        return 2;
    } catch (const sim::UsageError& e) {
        std::cerr << "eomgen fit: " << e.what() << "\n";
        return 2;
    } catch (const SimulationError& e) {
        std::cerr << "eomgen fit: simulation failed: " << e.what() << "\n";
        return 2;
    }
}

int FitCommand::fit_model() {
    const bool show_progress = !quiet_ && ::isatty(STDERR_FILENO);
    auto progress = [&](const std::string& what) {
        if (show_progress) std::fprintf(stderr, "eomgen fit: %s\n", what.c_str());
    };
    if (!csv_.empty())
        if (const std::string problem = sim::output_path_problem("--csv", csv_); !problem.empty()) {
            std::cerr << "eomgen fit: " << problem << "\n";
            return 3;
        }
    if (!plot_.empty())
        if (const std::string problem = plot_format_problem(plot_); !problem.empty()) {
            std::cerr << "eomgen fit: " << problem << "\n";
            return 2;
        }
    std::map<std::string, double> weights;
    for (const std::string& w : weights_) {
        const auto [name, v] = sim::parse_assignment(w, "--weight");
        weights[name] = v;
    }
    const std::string text = read_model_file(model_path_);
    const Model model = parse_model(text, model_path_);
    const FitLoss loss = parse_loss(loss_);
    sim::Options o = options_;
    o.model = model.name;
    // --set and --init for every experiment, and each experiment's own (K:NAME=VALUE).
    ByExperiment set = by_experiment(o.set, data_paths_.size(), "--set");
    ByExperiment init = by_experiment(o.init, data_paths_.size(), "--init");
    o.set = set.shared;
    o.init = init.shared;
    if (!options_in_si(declared_units(model), o.set, o.init, "eomgen fit")) return 2;
    for (std::size_t e = 0; e < data_paths_.size(); ++e) {
        const std::string program = "eomgen fit: experiment " + std::to_string(e + 1);
        if (!options_in_si(declared_units(model), set.own[e], init.own[e], program.c_str())) return 2;
    }
    const ModelFunctions functions = model_functions({&model, text, model_path_, true, interpret_, !no_cache_, progress});
    TableModel::bind(functions.table());

    TableModel::Params params;
    TableModel::State x0 = TableModel::default_state();
    sim::apply_settings<TableModel>(o, params, x0);
    Measurable measurable;
    measurable.states = TableModel::state_names.size();
    for (std::size_t i = 0; i < measurable.states + std::size_t(TableModel::n_outputs); ++i) {
        const bool state = i < measurable.states;
        measurable.names.push_back(state ? TableModel::state_names[i] : TableModel::output_names[i - measurable.states]);
        measurable.units.push_back(measured_unit(int(i)));
    }
    std::vector<MeasuredSeries> data;
    for (const std::string& path : data_paths_) data.push_back(read_measured(path, measurable));
    std::vector<ExperimentStart> starts;
    std::vector<std::string> own;
    for (std::size_t e = 0; e < data.size(); ++e) {
        ExperimentStart start{params, x0};
        sim::Options mine;
        mine.set = set.own[e];
        mine.init = init.own[e];
        try {
            sim::apply_settings<TableModel>(mine, start.params, start.x0);
        } catch (const sim::UsageError& err) {  // "--set mass=2: ..." said as the user wrote it, "--set 2:mass=2"
            std::string what = err.what();
            const std::size_t space = what.find(' ');
            if (what.rfind("--", 0) == 0 && space != std::string::npos) what.insert(space + 1, std::to_string(e + 1) + ":");
            throw sim::UsageError(what);
        }
        starts.push_back(start);
    }
    const std::vector<FreeValue> free = parse_free(free_, starts);
    // What each experiment sets for itself, but for what it fits as its own (--set 2:c=0.25 --free 2:c: the start).
    for (std::size_t e = 0; e < data.size(); ++e) {
        std::vector<std::string> fixed;
        for (const std::string& a : set.own[e]) {
            const std::string name = sim::parse_assignment(a, "--set").first;
            const bool fitted = std::any_of(free.begin(), free.end(), [&](const FreeValue& f) {
                return f.experiment == int(e) && f.column.kind == SensitivityColumn::Kind::Parameter &&
                       TableModel::param_names[std::size_t(f.column.index)] == name;
            });
            if (!fitted) fixed.push_back(a);
        }
        own.push_back(own_settings(fixed, init.own[e]));
    }
    // A parameter fitted is one value for every experiment: it cannot also be one experiment's own.
    for (std::size_t e = 0; e < data.size(); ++e)
        for (const std::string& a : set.own[e]) {
            const std::string name = sim::parse_assignment(a, "--set").first;
            for (const FreeValue& f : free)
                if (f.name == name)
                    throw sim::UsageError("--set " + std::to_string(e + 1) + ":" + a + ": " + name +
                                          " is free, one value fitted for every experiment; give it per experiment, "
                                          "free it per experiment (--free K:" + name + "), or free it, not both");
        }
    progress("fitting");
    const FitOutcome r = fit(o, starts, free, data, weights, max_iterations_, loss,
                             jacobian_ == "differences" ? FitJacobian::Differences : FitJacobian::Sensitivities);

    std::ostringstream report;
    if (format_ == "json") {
        print_json(free, data, set, init, r, loss, report);
    } else {
        print_heading(params, free, report);
        print_text(free, data, own, r, o, jacobian_, loss, report);
    }
    // The plot reads the fitted CSV: --csv's, or a private temporary one.
    std::optional<TempDir> plot_dir;
    std::string csv = csv_;
    if (!plot_.empty() && csv.empty()) {
        plot_dir.emplace(fs::temp_directory_path(), "eomgen-fit.");
        csv = (plot_dir->path() / "fitted.csv").string();
    }
    if (!csv.empty()) {
        try {
            write_atomically(csv, fitted_csv(data, r));
        } catch (const std::exception& e) {
            std::cerr << "eomgen fit: cannot write " << csv << ": " << e.what() << "\n";
            return 3;
        }
        if (format_ == "text" && !csv_.empty()) report << "csv:     " << csv_ << " (data, fitted model, residuals)\n";
    }
    if (!plot_.empty()) {
        FitPlotRequest p{csv, plot_, model.title.empty() ? model.name : model.title, {}, data.size(),
                         time_unit<TableModel>()};
        std::vector<std::string> seen;
        for (const MeasuredSeries& d : data)
            for (std::size_t c = 0; c < d.names.size(); ++c)
                if (std::find(seen.begin(), seen.end(), d.names[c]) == seen.end()) {
                    seen.push_back(d.names[c]);
                    p.columns.push_back({d.names[c], measured_unit(d.index[c])});
                }
        try {
            plot_fit(p);
        } catch (const std::exception& e) {
            std::cerr << "eomgen fit: " << e.what() << "\n";
            return 3;
        }
        if (format_ == "text") report << "plot:    " << plot_ << "\n";
    }
    std::cout << report.str();
    return r.converged ? 0 : kExitNotConverged;
}

}  // namespace eomgen::cli
