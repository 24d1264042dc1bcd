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

/// One integration as `eomgen run` makes it, the samples returned as arrays: t, x (the state: q then q'), the
/// derived columns (sample_csv.hpp: energy, work, conserved quantities, residuals, multipliers, outputs).
py::dict simulate(LoadedModel& m, double t_end, const std::string& method, double rtol, double atol, double dt,
                  int samples, std::size_t max_steps, const std::vector<std::string>& set,
                  const std::vector<std::string>& init, const std::string& until, bool project_initial,
                  bool switch_events, bool use_cache) {
    sim::Options o = run_options(m, t_end, method, rtol, atol, dt, samples, max_steps, set, init, until,
                                 project_initial, switch_events);
    const ModelTable& table = m.table(method == "radau5", use_cache);  // derives and compiles, holding the GIL
    sim::Trajectory<TableModel> r;
    std::vector<std::string> state_names, state_units;
    std::string time_unit;
    std::vector<std::pair<std::string, std::string>> columns;
    std::vector<double> x, derived;
    std::vector<double> parameter_values;
    std::vector<std::string> parameter_names;
    {
        py::gil_scoped_release release;
        std::lock_guard<std::mutex> lock(driver_lock());
        TableModel::bind(table);
        sim::check_method_for<TableModel>(o);
        TableModel::Params params;
        TableModel::State x0 = TableModel::default_state();
        sim::apply_settings<TableModel>(o, params, x0);
        const auto events = sim::until_events<TableModel>(o);
        r = sim::simulate<TableModel>(o, params, x0, events, true, nullptr);
        const bool with_work = !r.work.empty() && r.work.size() == r.samples.size();
        columns = sim::derived_columns<TableModel>(with_work);
        for (std::size_t k = 0; k < r.samples.size(); ++k) {
            const auto& s = r.samples[k];
            x.insert(x.end(), s.x.data(), s.x.data() + s.x.size());
            const std::vector<double> row =
                sim::derived_values<TableModel>(params, s.t, s.x, with_work, with_work ? r.work[k] : 0.0);
            derived.insert(derived.end(), row.begin(), row.end());
        }
        for (std::size_t i = 0; i < TableModel::state_names.size(); ++i) {
            state_names.push_back(TableModel::state_names[i]);
            state_units.push_back(eomgen::state_unit<TableModel>(i));
        }
        time_unit = eomgen::time_unit<TableModel>();
        parameter_values = TableModel::param_values(params);
        parameter_names.assign(TableModel::param_names.begin(), TableModel::param_names.end());
    }
    const std::size_t n = r.samples.size();
    std::vector<double> t(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = r.samples[k].t;
    py::dict d;
    d["t"] = py::array_t<double>(py::ssize_t(n), t.data());
    d["x"] = matrix(x, n, state_names.size());
    d["state_names"] = state_names;
    d["state_units"] = state_units;
    d["time_unit"] = time_unit;
    d["derived"] = matrix(derived, n, columns.size());
    py::list names, units;
    for (const auto& [name, unit] : columns) {
        names.append(name);
        units.append(unit);
    }
    d["derived_names"] = names;
    d["derived_units"] = units;
    d["t_final"] = r.t;
    d["stopped_by"] = r.stopped_by;
    d["h0"] = r.h0;
    d["max_drift"] = r.max_drift;
    d["max_imbalance"] = r.max_imbalance;
    py::dict params;
    for (std::size_t k = 0; k < parameter_names.size(); ++k) params[py::str(parameter_names[k])] = parameter_values[k];
    d["parameters"] = params;
    return d;
}

/// `value` of NAME (a parameter, else a state) in SI: a number in the unit the model file declares for NAME.
double value_in_si(const LoadedModel& m, const std::string& name, double value, bool state) {
    std::ostringstream text;
    text.precision(17);
    text << name << "=" << value;
    try {
        const std::string si = cli::assignment_in_si(cli::declared_units(m.model()), text.str(), state, "sweep");
        return std::stod(si.substr(si.find('=') + 1));
    } catch (const std::invalid_argument& e) {
        throw sim::UsageError(e.what());
    }
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
               bool project_initial, bool switch_events, unsigned threads, bool use_cache) {
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
    const ModelTable& table = m.table(method == "radau5", use_cache);
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
