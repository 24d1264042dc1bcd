/** @file bind_simulation.cpp  Simulations for Python (binding.hpp): one run as `eomgen run` makes it, the samples as
 * arrays, and ensembles on threads (sweep), both through the driver compiled into eomgen_table_driver. */
#include "binding.hpp"

#include "cli/model_unit_values.hpp"
#include "eomgen/ensemble.hpp"
#include "eomgen/sample_csv.hpp"
#include "eomgen/simulation.hpp"
#include "table_driver.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

namespace eomgen::python {

std::mutex& driver_lock() {
    static std::mutex m;
    return m;
}

/// The options of `eomgen run` from keyword values; set and init as NAME=VALUE strings (units as on the command
/// line: a bare number in the declared unit, or one of its own).
sim::Options run_options(const LoadedModel& m, double t_end, const std::string& method, double rtol, double atol,
                         double dt, int samples, std::size_t max_steps, const std::vector<std::string>& set,
                         const std::vector<std::string>& init, const std::string& until, bool project_initial,
                         bool switch_events) {
    sim::Options o;
    o.model = m.model().name;
    o.t_end = t_end;
    o.method = method;
    o.rtol = rtol;
    o.atol = atol;
    o.dt = dt;
    o.samples = samples;
    o.max_steps = max_steps;
    o.set = set;
    o.init = init;
    o.until = until;
    o.project_initial = project_initial;
    o.switch_events = switch_events;
    o.report_csv = false;
    try {
        const cli::DeclaredUnits units = cli::declared_units(m.model());
        cli::assignments_in_si(units, o.set, false, "set");
        cli::assignments_in_si(units, o.init, true, "init");
    } catch (const std::invalid_argument& e) {
        throw sim::UsageError(e.what());
    }
    sim::check_options(o);
    return o;
}

/// NumPy array of shape (rows, columns) from row-major values.
py::array_t<double> matrix(const std::vector<double>& values, std::size_t rows, std::size_t columns) {
    py::array_t<double> a({rows, columns});
    std::copy(values.begin(), values.end(), a.mutable_data());
    return a;
}

namespace {

/// A run's samples as the module returns them, gathered while the driver's lock is held.
struct Samples {
    std::vector<double> t, x, derived;
    std::vector<std::pair<std::string, std::string>> columns;  ///< the derived columns: name, unit
    /// With sensitivities: per sample the columns' S (nx × k), Y (outputs × k), L (multipliers × k), row-major.
    std::vector<double> S, Y, L;
    std::size_t nx = 0, k = 0, n_outputs = 0, n_multipliers = 0;
};

/// Appends one sample: t, x and the derived columns at (t, x).
void add_sample(Samples& out, const TableModel::Params& params, double t, const Eigen::VectorXd& x, bool with_work,
                double work) {
    out.t.push_back(t);
    out.x.insert(out.x.end(), x.data(), x.data() + x.size());
    const std::vector<double> row = sim::derived_values<TableModel>(params, t, x, with_work, work);
    out.derived.insert(out.derived.end(), row.begin(), row.end());
}

/// Appends a column-major matrix row by row.
void add_rows(std::vector<double>& out, const Eigen::MatrixXd& m) {
    for (Eigen::Index i = 0; i < m.rows(); ++i)
        for (Eigen::Index j = 0; j < m.cols(); ++j) out.push_back(m(i, j));
}

}  // namespace

/// One integration as `eomgen run` makes it, the samples returned as arrays: t, x (the state: q then q'), the
/// derived columns (sample_csv.hpp: energy, work, conserved quantities, residuals, multipliers, outputs); with
/// `sensitivities` (as --sensitivities: parameters, x0:STATE) S = dx/d(columns) beside the state
/// (sensitivity_run.hpp), with the outputs' and multipliers' and an event time's.
py::dict simulate(LoadedModel& m, double t_end, const std::string& method, double rtol, double atol, double dt,
                  int samples, std::size_t max_steps, const std::vector<std::string>& set,
                  const std::vector<std::string>& init, const std::string& until, bool project_initial,
                  bool switch_events, const std::vector<std::string>& sensitivities, bool state_error_only,
                  bool use_cache, bool interpret) {
    sim::Options o = run_options(m, t_end, method, rtol, atol, dt, samples, max_steps, set, init, until,
                                 project_initial, switch_events);
    o.sensitivities = sensitivities;
    o.state_error_only = state_error_only;
    // Derives and compiles, holding the GIL; the Jacobians for radau5 and for the sensitivities.
    const ModelTable& table = m.table(method == "radau5" || !sensitivities.empty(), use_cache, interpret);
    Samples out;
    double t_final = 0, h0 = 0, max_drift = 0, max_imbalance = 0;
    std::string stopped_by, time_unit;
    std::vector<std::string> state_names, state_units, labels;
    std::vector<std::pair<std::string, std::vector<double>>> event_dt;  // an event's name, dt/d(columns)
    std::vector<double> parameter_values;
    std::vector<std::string> parameter_names;
    {
        py::gil_scoped_release release;
        std::lock_guard<std::mutex> lock(driver_lock());
        TableModel::bind(table);
        if (sensitivities.empty()) {
            sim::check_method_for<TableModel>(o);
            TableModel::Params params;
            TableModel::State x0 = TableModel::default_state();
            sim::apply_settings<TableModel>(o, params, x0);
            const sim::Trajectory<TableModel> r =
                sim::simulate<TableModel>(o, params, x0, sim::until_events<TableModel>(o), true, nullptr);
            const bool with_work = !r.work.empty() && r.work.size() == r.samples.size();
            out.columns = sim::derived_columns<TableModel>(with_work);
            for (std::size_t k = 0; k < r.samples.size(); ++k)
                add_sample(out, params, r.samples[k].t, r.samples[k].x, with_work, with_work ? r.work[k] : 0.0);
            t_final = r.t;
            stopped_by = r.stopped_by;
            h0 = r.h0;
            max_drift = r.max_drift;
            max_imbalance = r.max_imbalance;
            parameter_values = TableModel::param_values(params);
        } else {
            const sim::SensitivityRun<TableModel> run = sim::sensitivity_run<TableModel>(o);
            const SensitivityResult& r = run.result;
            out.columns = sim::derived_columns<TableModel>(false);
            out.k = run.labels.size();
            for (const auto& l : run.labels) labels.push_back(l.name);
            for (const SensitivitySample& sample : r.samples) {
                add_sample(out, run.params, sample.t, sample.x, false, 0.0);
                add_rows(out.S, sample.S);
                add_rows(out.Y, sample.Y);
                add_rows(out.L, sample.L);
                out.n_outputs = std::size_t(sample.Y.rows());
                out.n_multipliers = std::size_t(sample.L.rows());
            }
            for (const SensitivityEventHit& e : r.events)
                event_dt.push_back({e.name, std::vector<double>(e.dt.data(), e.dt.data() + e.dt.size())});
            t_final = r.t;
            stopped_by = r.stopped_by;
            // The energy's drift at the samples, as a plain run measures it (relative unless h starts at 0).
            const std::size_t n_derived = out.columns.size();
            if (!out.t.empty()) h0 = out.derived[0];  // the first derived column is the energy
            for (std::size_t k = 0; k < out.t.size(); ++k)
                max_drift = std::max(max_drift, std::abs(out.derived[k * n_derived] - h0));
            if (std::abs(h0) >= 1e-12) max_drift /= std::abs(h0);
            parameter_values = TableModel::param_values(run.params);
        }
        for (std::size_t i = 0; i < TableModel::state_names.size(); ++i) {
            state_names.push_back(TableModel::state_names[i]);
            state_units.push_back(eomgen::state_unit<TableModel>(i));
        }
        out.nx = state_names.size();
        time_unit = eomgen::time_unit<TableModel>();
        parameter_names.assign(TableModel::param_names.begin(), TableModel::param_names.end());
    }
    const std::size_t n = out.t.size();
    py::dict d;
    d["t"] = py::array_t<double>(py::ssize_t(n), out.t.data());
    d["x"] = matrix(out.x, n, out.nx);
    d["state_names"] = state_names;
    d["state_units"] = state_units;
    d["time_unit"] = time_unit;
    d["derived"] = matrix(out.derived, n, out.columns.size());
    py::list names, units;
    for (const auto& [name, unit] : out.columns) {
        names.append(name);
        units.append(unit);
    }
    d["derived_names"] = names;
    d["derived_units"] = units;
    d["t_final"] = t_final;
    d["stopped_by"] = stopped_by;
    d["h0"] = h0;
    d["max_drift"] = max_drift;
    d["max_imbalance"] = max_imbalance;
    py::dict params;
    for (std::size_t k = 0; k < parameter_names.size(); ++k) params[py::str(parameter_names[k])] = parameter_values[k];
    d["parameters"] = params;
    if (!sensitivities.empty()) {
        auto cube = [n, &out](const std::vector<double>& v, std::size_t rows) {
            py::array_t<double> a(std::vector<py::ssize_t>{py::ssize_t(n), py::ssize_t(rows), py::ssize_t(out.k)});
            std::copy(v.begin(), v.end(), a.mutable_data());
            return a;
        };
        d["sensitivity_names"] = labels;
        d["S"] = cube(out.S, out.nx);
        d["S_outputs"] = cube(out.Y, out.n_outputs);
        d["S_multipliers"] = cube(out.L, out.n_multipliers);
        py::dict events;
        for (const auto& [name, values] : event_dt) events[py::str(name)] = py::array_t<double>(py::ssize_t(values.size()), values.data());
        d["event_dt"] = events;
    }
    return d;
}

/// `value` of NAME (a parameter, else a state) in SI: a number in the unit the model file declares for NAME.
double value_in_si(const LoadedModel& m, const std::string& name, double value, bool state) {
    std::ostringstream text;
    text.precision(17);
    text << name << "=" << value;
    return si_map(m, {text.str()}, state, "sweep").at(name);
}

/**
 * An ensemble of members on `threads` threads (0: every core), member k with values(k, j) for names[j] (a parameter
 * or a state's initial value, in its declared unit) on top of the model's defaults and `set`, `init`; each member
 * integrated as simulate() integrates one. Returns per member: ok, where it ended (t), the state there, the
 * terminal event, h and the outputs there, or the failure's message; in member order whatever the threads.
 */
py::dict sweep(LoadedModel& m, const std::vector<std::string>& names,
               py::array_t<double, py::array::c_style | py::array::forcecast> values, double t_end,
               const std::string& method, double rtol, double atol, double dt, std::size_t max_steps,
               const std::vector<std::string>& set, const std::vector<std::string>& init, const std::string& until,
               bool project_initial, bool switch_events, unsigned threads, bool use_cache, bool interpret) {
    if (values.ndim() != 2 || values.shape(1) != py::ssize_t(names.size()))
        throw sim::UsageError("sweep: one column of values per name");
    sim::Options o = run_options(m, t_end, method, rtol, atol, dt, 1, max_steps, set, init, until, project_initial,
                                 switch_events);
    const std::size_t count = std::size_t(values.shape(0)), k = names.size();
    // Which parameter or state each name is, and its declared unit as an affine map to SI (a + b v).
    std::vector<std::string> parameter_names, state_names;
    for (const Parameter& p : m.model().parameters) parameter_names.push_back(p.name);
    for (const Coordinate& c : m.model().coordinates) state_names.push_back(c.name);
    for (const Coordinate& c : m.model().coordinates) state_names.push_back(c.name + "_dot");
    std::vector<int> state_index(k, -1);
    std::vector<double> offset(k), scale(k);
    for (std::size_t j = 0; j < k; ++j) {
        const auto in = [&](const std::vector<std::string>& v) { return std::find(v.begin(), v.end(), names[j]) != v.end(); };
        if (!in(parameter_names)) {
            if (!in(state_names)) {
                std::vector<std::string> all = parameter_names;
                all.insert(all.end(), state_names.begin(), state_names.end());
                throw sim::UsageError("sweep: no parameter or state '" + names[j] + "'" + sim::did_you_mean(names[j], all));
            }
            state_index[j] = int(std::find(state_names.begin(), state_names.end(), names[j]) - state_names.begin());
        }
        offset[j] = value_in_si(m, names[j], 0.0, state_index[j] >= 0);
        scale[j] = value_in_si(m, names[j], 1.0, state_index[j] >= 0) - offset[j];
    }
    const ModelTable& table = m.table(method == "radau5", use_cache, interpret);
    const double* v = values.data();
    std::vector<unsigned char> ok(count);
    std::vector<double> t(count), energy(count), x, outputs;
    std::vector<std::string> stopped_by(count), error(count);
    std::size_t nx = 0, n_outputs = 0;
    {
        py::gil_scoped_release release;
        std::lock_guard<std::mutex> lock(driver_lock());
        TableModel::bind(table);
        sim::check_method_for<TableModel>(o);
        Member<TableModel> base;
        sim::apply_settings<TableModel>(o, base.params, base.x0);
        nx = std::size_t(base.x0.size());
        n_outputs = std::size_t(TableModel::n_outputs);
        x.assign(count * nx, std::numeric_limits<double>::quiet_NaN());
        outputs.assign(count * n_outputs, std::numeric_limits<double>::quiet_NaN());
        EnsembleOptions options;
        options.simulation = o;
        options.threads = threads;
        ensemble<TableModel>(
            count,
            [&](std::size_t i) {
                Member<TableModel> member = base;
                for (std::size_t j = 0; j < k; ++j) {
                    const double si = offset[j] + scale[j] * v[i * k + j];
                    if (state_index[j] >= 0) member.x0(state_index[j]) = si;
                    else TableModel::set_param(member.params, names[j], si);
                }
                return member;
            },
            options,
            [&](const MemberResult<TableModel>& r) {
                ok[r.index] = r.ok;
                t[r.index] = r.t;
                if (r.ok) {
                    std::copy(r.x.data(), r.x.data() + nx, x.begin() + std::ptrdiff_t(r.index * nx));
                    std::copy(r.outputs.data(), r.outputs.data() + n_outputs,
                              outputs.begin() + std::ptrdiff_t(r.index * n_outputs));
                }
                energy[r.index] = r.energy;
                stopped_by[r.index] = r.stopped_by;
                error[r.index] = r.error;
            });
    }
    std::vector<double> si_values(count * k);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t j = 0; j < k; ++j) si_values[i * k + j] = offset[j] + scale[j] * v[i * k + j];
    py::dict d;
    d["ok"] = py::array_t<bool>(py::ssize_t(count), reinterpret_cast<const bool*>(ok.data()));
    d["t"] = py::array_t<double>(py::ssize_t(count), t.data());
    d["x"] = matrix(x, count, nx);
    d["energy"] = py::array_t<double>(py::ssize_t(count), energy.data());
    d["outputs"] = matrix(outputs, count, n_outputs);
    d["values_si"] = matrix(si_values, count, k);
    d["stopped_by"] = stopped_by;
    d["error"] = error;
    return d;
}

}  // namespace eomgen::python
