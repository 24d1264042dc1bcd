/**
 * @file module.cpp  The extension `eomgen._eomgen`: the generator's stages and the simulation driver as a few
 * functions over plain values (strings, dicts, NumPy arrays), which eomgen/__init__.py turns into the Python API
 * (docs/python.md). Nothing here derives or integrates on its own: a model is read by model/, derived by
 * mechanics/, compiled and cached by cli/compiled_model (the cache `eomgen run` uses), integrated by the driver of
 * eomgen_table_driver, checked by checker/.
 *
 * Threads: GiNaC is not thread-safe, so reading, deriving and checking hold the GIL; an integration releases it
 * and holds one lock instead (TableModel's table is global to the process); rhs() releases it and calls the
 * compiled table directly, which is reentrant.
 */
#include "checker/checker.hpp"
#include "checker/derivation.hpp"
#include "checker/report.hpp"
#include "cli/compiled_model.hpp"
#include "cli/latex_equations.hpp"
#include "cli/model_unit_values.hpp"
#include "cli/process.hpp"
#include "cli/show_text.hpp"
#include "codegen/cpp_emitter.hpp"
#include "codegen/math_printer.hpp"
#include "eomgen/ensemble.hpp"
#include "eomgen/errors.hpp"
#include "eomgen/model_table.hpp"
#include "eomgen/sample_csv.hpp"
#include "eomgen/simulation.hpp"
#include "mechanics/lagrangian.hpp"
#include "mechanics/small_oscillations.hpp"
#include "model/model.hpp"
#include "model/families.hpp"
#include "model/model_file.hpp"
#include "table_driver.hpp"

#include <pybind11/numpy.h>
#include <pybind11/complex.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <complex>
#include <filesystem>
#include <map>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>

namespace py = pybind11;

namespace eomgen::python {
namespace {

/// The Python exception classes, made in PYBIND11_MODULE: Error and its subclasses.
struct Exceptions {
    py::object error, model, usage, simulation, compile, cache, check;
};
Exceptions& exceptions() {
    static Exceptions* e = new Exceptions();  // never destroyed: Python owns the classes until it exits
    return *e;
}

/// A model file read (and, on first use, derived and compiled): what eomgen.Model wraps.
class LoadedModel {
  public:
    /// `name`: the model's name where the text gives none ("": the file name's stem).
    LoadedModel(std::string text, std::string path, const std::string& name)
        : text_(std::move(text)), path_(std::move(path)), model_(parse_model(text_, path_, name)) {}

    const Model& model() const { return model_; }
    const std::string& path() const { return path_; }

    const Equations& equations() {
        if (!equations_) equations_ = derive_equations(model_);
        return *equations_;
    }

    /// The compiled table (with the Jacobian where `jacobian`), compiled once per process and cached on disk.
    const ModelTable& table(bool jacobian, bool use_cache) {
        if (!jacobian && with_jacobian_) return **with_jacobian_;  // the same functions, and the Jacobian besides
        std::optional<const ModelTable*>& slot = jacobian ? with_jacobian_ : plain_;
        if (!slot) {
            const std::string file_name = std::filesystem::path(path_).filename().string();
            auto header = [this, jacobian, &file_name] {
                Model with = model_;
                with.generate.jacobians = with.generate.jacobians || (jacobian && with.constraints.empty());
                return codegen::emit_model_header(with, equations(), file_name);
            };
            cli::CompileRequest request{text_, model_.name, header, use_cache, {}};
            request.jacobian = jacobian;
            const cli::CompiledModel compiled = cli::compile_model(request);
            slot = compiled.table;
            shared_object_ = compiled.path;
        }
        return **slot;
    }

  private:
    std::string text_, path_;
    Model model_;
    std::optional<Equations> equations_;
    std::optional<const ModelTable*> plain_, with_jacobian_;
    std::string shared_object_;

  public:
    /// The shared object loaded last (compiling it where the cache has none).
    const std::string& shared_object(bool use_cache) {
        table(false, use_cache);
        return shared_object_;
    }
};

std::mutex& driver_lock() {
    static std::mutex m;
    return m;
}

py::dict describe(const LoadedModel& m) {
    const Model& model = m.model();
    py::dict d;
    d["name"] = model.name;
    d["title"] = model.title;
    d["source"] = model.source;
    d["path"] = m.path();
    py::list coordinates, parameters, outputs, constraints;
    for (const Coordinate& c : model.coordinates) {
        py::dict e;
        e["name"] = c.name;
        e["latex"] = c.latex;
        e["unit"] = c.unit;
        e["initial"] = c.initial;
        e["rate"] = c.rate;
        e["description"] = c.description;
        coordinates.append(e);
    }
    for (const Parameter& p : model.parameters) {
        py::dict e;
        e["name"] = p.name;
        e["latex"] = p.latex;
        e["unit"] = p.unit;
        e["value"] = p.value;
        e["description"] = p.description;
        parameters.append(e);
    }
    for (const DeclaredOutput& o : model.outputs) outputs.append(o.name);
    for (const auto& c : model.constraints) constraints.append(c.name);
    d["coordinates"] = coordinates;
    d["parameters"] = parameters;
    d["outputs"] = outputs;
    d["constraints"] = constraints;
    return d;
}

py::dict equations(LoadedModel& m) {
    const cli::EquationsText e = cli::equations_text(m.model(), m.equations());
    py::dict d;
    d["T"] = e.T;
    d["V"] = e.V;
    d["L"] = e.L;
    d["h"] = e.h;
    d["euler_lagrange"] = e.euler_lagrange;
    d["forces"] = e.forces;
    d["M"] = e.M;
    d["f"] = e.f;
    d["momenta"] = e.momenta;
    d["warnings"] = m.equations().warnings;
    return d;
}

std::string show(LoadedModel& m) {
    std::ostringstream os;
    cli::show_text(m.model(), m.equations(), os);
    return os.str();
}

/// The LaTeX of `show --latex` (align environments) and, for a notebook, one `$$ \begin{aligned} … $$` display per
/// block under its title.
py::tuple latex(LoadedModel& m) {
    const std::vector<cli::LatexBlock> blocks = cli::latex_equations(m.model(), m.equations());
    std::string displays;
    for (const cli::LatexBlock& b : blocks)
        displays += "$$\\textbf{" + b.title + "}$$\n" + cli::markdown_display(b) + "\n";
    return py::make_tuple(cli::latex_fragment(m.model(), blocks), displays);
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

/// A parameter block of `table` with the defaults, then `set` (NAME=VALUE in SI).
std::vector<std::max_align_t> parameter_block(const ModelTable& table, const std::vector<std::pair<std::string, double>>& set) {
    std::vector<std::max_align_t> block((table.params_size + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t) + 1);
    table.init_params(block.data());
    for (const auto& [name, value] : set) {
        if (!table.set_param(block.data(), name.c_str(), value)) {
            std::vector<std::string> names(table.param_names, table.param_names + table.n_params);
            throw sim::UsageError("no parameter '" + name + "' in the model" + sim::did_you_mean(name, names));
        }
    }
    return block;
}

/// ẋ = rhs(t, x) at each row of `x` (shape (N, 2n) or (2n,)), t a scalar or one value per row.
py::array_t<double> rhs(LoadedModel& m, py::array_t<double, py::array::c_style | py::array::forcecast> t,
                        py::array_t<double, py::array::c_style | py::array::forcecast> x,
                        const std::vector<std::pair<std::string, double>>& set, bool use_cache) {
    const ModelTable& table = m.table(false, use_cache);
    const py::ssize_t nx = 2 * py::ssize_t(table.nq);
    if ((x.ndim() != 1 && x.ndim() != 2) || x.shape(x.ndim() - 1) != nx)
        throw sim::UsageError("rhs: x must have shape (" + std::to_string(nx) + ",) or (N, " + std::to_string(nx) +
                              "): q then q' of " + m.model().name);
    const py::ssize_t rows = x.ndim() == 2 ? x.shape(0) : 1;
    if (t.size() != 1 && t.size() != rows)
        throw sim::UsageError("rhs: t must be one time or one per state (" + std::to_string(rows) + "), not " +
                              std::to_string(t.size()));
    const std::vector<std::max_align_t> params = parameter_block(table, set);
    py::array_t<double> out(x.ndim() == 2 ? std::vector<py::ssize_t>{rows, nx} : std::vector<py::ssize_t>{nx});
    const double* tp = t.data();
    const double* xp = x.data();
    double* op = out.mutable_data();
    const bool one_time = t.size() == 1;
    int status = 0;
    py::ssize_t failed = 0;
    double failed_t = 0;
    std::string message;
    {
        py::gil_scoped_release release;
        for (py::ssize_t k = 0; k < rows; ++k) {
            const double tk = one_time ? tp[0] : tp[k];
            status = table.rhs(tk, xp + k * nx, params.data(), op + k * nx);
            if (status != 0) {
                failed = k;
                double at = tk;
                message = table.error_message(&at);
                failed_t = at;
                break;
            }
        }
    }
    if (status != 0)
        throw SimulationError("rhs at row " + std::to_string(failed) + " (t = " + std::to_string(failed_t) +
                                  "): " + message,
                              failed_t);
    return out;
}

/// J = ∂ẋ/∂x (N × 2n × 2n) and Jp = ∂ẋ/∂p (N × 2n × n_params) at each row of `x` (shape (N, 2n) or (2n,), then
/// without the leading N), by the compiled table's Jacobian (the header's analytic one where the model has it,
/// else forward differentiation in the shared object).
py::tuple jacobian(LoadedModel& m, py::array_t<double, py::array::c_style | py::array::forcecast> t,
                   py::array_t<double, py::array::c_style | py::array::forcecast> x,
                   const std::vector<std::pair<std::string, double>>& set, bool use_cache) {
    const ModelTable& table = m.table(true, use_cache);
    const py::ssize_t nx = 2 * py::ssize_t(table.nq), np_ = table.n_params;
    if ((x.ndim() != 1 && x.ndim() != 2) || x.shape(x.ndim() - 1) != nx)
        throw sim::UsageError("jacobian: x must have shape (" + std::to_string(nx) + ",) or (N, " +
                              std::to_string(nx) + "): q then q' of " + m.model().name);
    const py::ssize_t rows = x.ndim() == 2 ? x.shape(0) : 1;
    if (t.size() != 1 && t.size() != rows)
        throw sim::UsageError("jacobian: t must be one time or one per state (" + std::to_string(rows) + "), not " +
                              std::to_string(t.size()));
    const std::vector<std::max_align_t> params = parameter_block(table, set);
    std::vector<py::ssize_t> jshape{nx, nx}, pshape{nx, np_};
    if (x.ndim() == 2) {
        jshape.insert(jshape.begin(), rows);
        pshape.insert(pshape.begin(), rows);
    }
    py::array_t<double> J(jshape), Jp(pshape);
    const double *tp = t.data(), *xp = x.data();
    double *jp = J.mutable_data(), *pp = Jp.mutable_data();
    std::vector<double> column_major(std::size_t(nx * std::max(nx, np_)));
    std::string message;
    {
        py::gil_scoped_release release;
        for (py::ssize_t k = 0; k < rows && message.empty(); ++k) {
            const double tk = t.size() == 1 ? tp[0] : tp[k];
            double at = tk;
            // The table's matrices are column-major; NumPy's rows are rows.
            if (table.jacobian(tk, xp + k * nx, params.data(), column_major.data()) != 0) {
                message = table.error_message(&at);
                break;
            }
            for (py::ssize_t i = 0; i < nx; ++i)
                for (py::ssize_t j = 0; j < nx; ++j) jp[k * nx * nx + i * nx + j] = column_major[std::size_t(j * nx + i)];
            if (np_ > 0 && table.parameter_jacobian(tk, xp + k * nx, params.data(), column_major.data()) != 0) {
                message = table.error_message(&at);
                break;
            }
            for (py::ssize_t i = 0; i < nx; ++i)
                for (py::ssize_t j = 0; j < np_; ++j) pp[k * nx * np_ + i * np_ + j] = column_major[std::size_t(j * nx + i)];
        }
    }
    if (!message.empty()) throw SimulationError("jacobian: " + message, 0.0);
    return py::make_tuple(J, Jp);
}

/// NAME=VALUE assignments (a number in the declared unit, or with its own) as NAME -> SI value.
std::map<std::string, double> si_map(const LoadedModel& m, const std::vector<std::string>& assignments, bool state,
                                     const char* what) {
    std::map<std::string, double> out;
    for (const std::string& a : assignments) {
        std::string si;
        try {
            si = cli::assignment_in_si(cli::declared_units(m.model()), a, state, what);
        } catch (const std::invalid_argument& e) {
            throw sim::UsageError(e.what());
        }
        out.insert(sim::parse_assignment(si, what));
    }
    return out;
}

py::array_t<double> matrix(const std::vector<std::vector<double>>& rows) {
    const std::size_t r = rows.size(), c = r ? rows[0].size() : 0;
    std::vector<double> flat;
    for (const auto& row : rows) flat.insert(flat.end(), row.begin(), row.end());
    return matrix(flat, r, c);
}

/// `eomgen modes`: the equilibria (exact where found), the linearization about each (M, K, C, G, A, B), the normal
/// modes and eigenvalues, the stability; exact values printed in the model file's language.
py::dict modes(LoadedModel& m, const std::vector<std::string>& set, const std::vector<std::vector<std::string>>& at,
               const std::vector<std::string>& momentum, const std::vector<std::string>& inputs) {
    ModesOptions options;
    options.set = si_map(m, set, false, "set");
    for (const auto& guess : at) options.at.push_back(si_map(m, guess, true, "at"));
    for (const std::string& p : momentum) options.momentum.insert(sim::parse_assignment(p, "momentum"));  // SI
    options.inputs = inputs;
    ModesResult r;
    try {
        r = small_oscillations(m.model(), m.equations(), options);
    } catch (const ModesError& e) {
        throw sim::UsageError(e.what());
    }
    codegen::SymbolTable table = codegen::symbol_table(m.model());
    int k = 0;
    for (const auto& [symbol, latex] : r.momentum_symbols) {
        table.info.push_back({codegen::SymbolKind::Constant, ++k, symbol.get_name(), symbol.get_name(), latex, ""});
        table.exprs.push_back(symbol);
    }
    codegen::MathPrinter printer(table);
    auto text = [&printer](const std::optional<GiNaC::ex>& e) -> py::object {
        if (!e) return py::none();
        return py::str(printer.print(*e, codegen::MathStyle::Text));
    };
    py::list equilibria;
    for (const Equilibrium& e : r.equilibria) {
        py::dict d;
        d["q"] = e.q;
        py::list exact;
        for (const auto& x : e.exact) exact.append(text(x));
        d["exact"] = exact;
        d["M"] = matrix(e.M);
        d["K"] = matrix(e.K);
        d["C"] = matrix(e.C);
        d["G"] = matrix(e.G);
        d["A"] = matrix(e.A);
        d["B"] = matrix(e.B);
        d["multipliers"] = e.multipliers;
        d["tangent"] = matrix(e.tangent);
        py::list normal_modes;
        for (const NormalMode& mode : e.modes) normal_modes.append(py::make_tuple(mode.omega2, text(mode.omega2_exact), mode.shape));
        d["modes"] = normal_modes;
        d["eigenvalues"] = e.eigenvalues;
        d["stability"] = std::string(stability_name(e.stability));
        d["growth_rate"] = e.growth_rate;
        d["gyroscopic"] = e.gyroscopic;
        d["damped"] = e.damped;
        equilibria.append(d);
    }
    py::dict d;
    d["coordinates"] = r.coordinates;
    d["reduced"] = r.reduced;
    d["constraints"] = r.constraints;
    d["V_eff"] = printer.print(r.V_eff, codegen::MathStyle::Text);
    d["equilibria"] = equilibria;
    d["notes"] = r.notes;
    return d;
}

py::dict check(LoadedModel& m, const std::string& text, const std::string& path,
               const std::vector<std::string>& sections, const std::vector<std::pair<std::string, double>>& set) {
    const checker::Derivation derivation = checker::parse_derivation(text, path);
    checker::CheckOptions options;
    options.sections = sections;
    options.set = set;
    checker::CheckReport report = checker::check_derivation(m.model(), m.equations(), derivation, options);
    report.model_path = m.path();
    report.model_title = m.model().title;
    report.derivation_path = path;
    py::list rows;
    for (const checker::EquationCheck& c : report.equations) {
        py::dict r;
        r["verdict"] = std::string(checker::verdict_name(c.verdict));
        r["line"] = c.where.line;
        r["column"] = c.where.column;
        r["section"] = c.section;
        r["equation"] = c.equation;
        r["compared_with"] = c.compared_with;
        r["reason"] = c.reason;
        r["difference"] = c.difference;
        r["wrong_terms"] = c.wrong_terms;
        r["corrected"] = c.corrected;
        r["notes"] = c.notes;
        rows.append(r);
    }
    py::list problems;
    for (const auto& p : report.problems)
        problems.append(py::make_tuple(p.where.line, p.where.column, p.message));
    py::dict d;
    d["equations"] = rows;
    d["problems"] = problems;
    d["text"] = checker::format_text(report);
    d["markdown"] = checker::format_markdown(report);
    d["json"] = checker::format_json(report);
    return d;
}

void raise(const py::object& type, const char* what) { PyErr_SetString(type.ptr(), what); }

}  // namespace
}  // namespace eomgen::python

PYBIND11_MODULE(_eomgen, m) {
    using namespace eomgen::python;
    m.doc() = "eomgen's generator and simulation driver; use the package `eomgen`, not this module";

    Exceptions& e = exceptions();
    e.error = py::reinterpret_steal<py::object>(
        PyErr_NewExceptionWithDoc("eomgen.Error", "Any error of eomgen.", PyExc_Exception, nullptr));
    auto sub = [&e](const char* name, const char* doc, PyObject* also) {
        py::tuple bases = also ? py::make_tuple(e.error, py::handle(also)) : py::make_tuple(e.error);
        return py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(name, doc, bases.ptr(), nullptr));
    };
    e.model = sub("eomgen.ModelError", "A model file is wrong; the message starts with file:line:col.", PyExc_ValueError);
    e.usage = sub("eomgen.UsageError", "A bad option or value (an unknown parameter, a method without dt, ...).",
                  PyExc_ValueError);
    e.simulation = sub("eomgen.SimulationError", "An integration failed (a singular mass matrix, a blown-up state, "
                                                 "the step limit).", nullptr);
    e.compile = sub("eomgen.CompileError", "The C++ compiler is missing or failed; the message names its log.", nullptr);
    e.cache = sub("eomgen.CacheError", "The cache of compiled models cannot be used safely.", PyExc_OSError);
    e.check = sub("eomgen.CheckError", "A --section or map entry of a check cannot be used.", PyExc_ValueError);
    m.attr("Error") = e.error;
    m.attr("ModelError") = e.model;
    m.attr("UsageError") = e.usage;
    m.attr("SimulationError") = e.simulation;
    m.attr("CompileError") = e.compile;
    m.attr("CacheError") = e.cache;
    m.attr("CheckError") = e.check;
    py::register_exception_translator([](std::exception_ptr p) {
        if (!p) return;
        Exceptions& x = exceptions();
        try {
            std::rethrow_exception(p);
        } catch (const eomgen::ModelError& err) {
            raise(x.model, err.what());
        } catch (const eomgen::sim::UsageError& err) {
            raise(x.usage, err.what());
        } catch (const eomgen::InconsistentInitialConditions& err) {
            const std::string what = std::string(err.what()) +
                                     " (give a state on the constraints with init=, or project_initial=True)";
            raise(x.simulation, what.c_str());
        } catch (const eomgen::SimulationError& err) {
            raise(x.simulation, err.what());
        } catch (const eomgen::cli::CompileError& err) {
            const std::string what = std::string(err.what()) + "\n  command: " + err.command + "\n  log: " + err.log;
            raise(x.compile, what.c_str());
        } catch (const eomgen::cli::CacheError& err) {
            raise(x.cache, err.what());
        } catch (const eomgen::cli::TempDirError& err) {
            raise(x.cache, err.what());
        } catch (const eomgen::checker::CheckError& err) {
            raise(x.check, err.what());
        }
    });

    py::class_<LoadedModel>(m, "LoadedModel")
        .def(py::init<std::string, std::string, std::string>(), py::arg("text"), py::arg("path"), py::arg("name"))
        .def("describe", &describe)
        .def("equations", &equations)
        .def("show", &show)
        .def("latex", &latex)
        .def("simulate", &simulate, py::arg("t_end"), py::arg("method"), py::arg("rtol"), py::arg("atol"),
             py::arg("dt"), py::arg("samples"), py::arg("max_steps"), py::arg("set"), py::arg("init"),
             py::arg("until"), py::arg("project_initial"), py::arg("switch_events"), py::arg("use_cache"))
        .def("sweep", &sweep, py::arg("names"), py::arg("values"), py::arg("t_end"), py::arg("method"), py::arg("rtol"),
             py::arg("atol"), py::arg("dt"), py::arg("max_steps"), py::arg("set"), py::arg("init"), py::arg("until"),
             py::arg("project_initial"), py::arg("switch_events"), py::arg("threads"), py::arg("use_cache"))
        .def("rhs", &rhs, py::arg("t"), py::arg("x"), py::arg("set"), py::arg("use_cache"))
        .def("modes", &modes, py::arg("set"), py::arg("at"), py::arg("momentum"), py::arg("inputs"))
        .def("jacobian", &jacobian, py::arg("t"), py::arg("x"), py::arg("set"), py::arg("use_cache"))
        .def("shared_object", &LoadedModel::shared_object, py::arg("use_cache"))
        .def("check", &check, py::arg("text"), py::arg("path"), py::arg("sections"), py::arg("set"));
    m.def("read_file", [](const std::string& path) { return py::bytes(eomgen::read_model_file(path)); },
          "The bytes of a model file (ModelError when unreadable).");
    m.def("family_text", [](const std::string& spec) {
        try {
            return eomgen::family_model_text(eomgen::parse_family_spec(spec));
        } catch (const std::invalid_argument& e) {
            throw eomgen::sim::UsageError(std::string("family: ") + e.what());
        }
    }, "The model file of an n-link family, e.g. \"pendulum:n=8\" (eomgen generate --family).");
    m.def("cache_directory", [] { return eomgen::cli::cache_directory().string(); });
}
