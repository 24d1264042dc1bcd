/**
 * @file binding.hpp  What the extension's files share (python/): a model file read, derived on first use and
 * compiled into the cache on first use (LoadedModel), the Python exception classes, and the functions each file
 * binds: bind_model.cpp (the model and its mechanics: description, equations, LaTeX, modes, check),
 * bind_simulation.cpp (simulate, sweep), bind_arrays.cpp (rhs and the Jacobians over NumPy arrays); module.cpp
 * makes the module. Nothing here derives or integrates on its own: a model is read by model/, derived by
 * mechanics/, compiled and cached by cli/compiled_model (the cache `eomgen run` uses), integrated by the driver of
 * eomgen_table_driver, checked by checker/.
 *
 * Threads: GiNaC is not thread-safe, so reading, deriving and checking hold the GIL; an integration releases it
 * and holds one lock instead (TableModel's table is global to the process); rhs() releases it and calls the
 * compiled table directly, which is reentrant.
 */
#pragma once

#include "cli/compiled_model.hpp"
#include "interpreter/interpreted_table.hpp"
#include "codegen/cpp_emitter.hpp"
#include "eomgen/model_table.hpp"
#include "eomgen/simulation_options.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"
#include "model/model_file.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace eomgen::python {

namespace py = pybind11;

/// The Python exception classes, made in PYBIND11_MODULE: Error and its subclasses.
struct Exceptions {
    py::object error, model, usage, simulation, compile, cache, check;
};
Exceptions& exceptions();

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

    /// The compiled table (with the Jacobian where `jacobian`), compiled once per process and cached on disk; with
    /// `interpret`, the interpreter's table instead (interpreter/interpreted_table.hpp: no compiler).
    const ModelTable& table(bool jacobian, bool use_cache, bool interpret = false) {
        if (interpret) {  // its Jacobians by forward differentiation of the tapes: `jacobian` asks for nothing more
            if (!interpreted_)
                interpreted_ = std::make_unique<interpreter::InterpretedTable>(interpreter::interpret(model_, equations()));
            return interpreted_->table();
        }
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

    /// The shared object loaded last (compiling it where the cache has none).
    const std::string& shared_object(bool use_cache) {
        table(false, use_cache);
        return shared_object_;
    }

  private:
    std::string text_, path_;
    Model model_;
    std::optional<Equations> equations_;
    std::optional<const ModelTable*> plain_, with_jacobian_;
    std::unique_ptr<interpreter::InterpretedTable> interpreted_;
    std::string shared_object_;
};

/// The lock an integration holds: TableModel's table is one per process.
std::mutex& driver_lock();

/// NumPy array of shape (rows, columns) from row-major values.
py::array_t<double> matrix(const std::vector<double>& values, std::size_t rows, std::size_t columns);
py::array_t<double> matrix(const std::vector<std::vector<double>>& rows);

/// The options of `eomgen run` from keyword values; set and init as NAME=VALUE strings (units as on the command
/// line: a bare number in the declared unit, or one of its own).
sim::Options run_options(const LoadedModel& m, double t_end, const std::string& method, double rtol, double atol,
                         double dt, int samples, std::size_t max_steps, const std::vector<std::string>& set,
                         const std::vector<std::string>& init, const std::string& until, bool project_initial,
                         bool switch_events);

/// `value` of NAME (a parameter, else a state) in SI: a number in the unit the model file declares for NAME.
double value_in_si(const LoadedModel& m, const std::string& name, double value, bool state);

/// NAME=VALUE assignments (a number in the declared unit, or with its own) as NAME -> SI value.
std::map<std::string, double> si_map(const LoadedModel& m, const std::vector<std::string>& assignments, bool state,
                                     const char* what);

/// A parameter block of `table` with the defaults, then `set` (NAME=VALUE in SI).
std::vector<std::max_align_t> parameter_block(const ModelTable& table, const std::vector<std::pair<std::string, double>>& set);

// bind_model.cpp
py::dict describe(const LoadedModel& m);
py::dict equations(LoadedModel& m);
std::string show(LoadedModel& m);
/// The LaTeX of `show --latex` (align environments) and, for a notebook, one `$$ \begin{aligned} … $$` display per
/// block under its title.
py::tuple latex(LoadedModel& m);
/// `eomgen modes`: the equilibria (exact where found), the linearization about each (M, K, C, G, A, B), the normal
/// modes and eigenvalues, the stability; exact values printed in the model file's language.
py::dict modes(LoadedModel& m, const std::vector<std::string>& set, const std::vector<std::vector<std::string>>& at,
               const std::vector<std::string>& momentum, const std::vector<std::string>& inputs);
py::dict check(LoadedModel& m, const std::string& text, const std::string& path,
               const std::vector<std::string>& sections, const std::vector<std::pair<std::string, double>>& set);

// bind_simulation.cpp
/// One integration as `eomgen run` makes it, the samples returned as arrays: t, x (the state: q then q'), the
/// derived columns (sample_csv.hpp: energy, work, conserved quantities, residuals, multipliers, outputs); with
/// `sensitivities` (as --sensitivities) S = dx/d(columns) beside the state, the outputs', multipliers', events'.
py::dict simulate(LoadedModel& m, double t_end, const std::string& method, double rtol, double atol, double dt,
                  int samples, std::size_t max_steps, const std::vector<std::string>& set,
                  const std::vector<std::string>& init, const std::string& until, bool project_initial,
                  bool switch_events, const std::vector<std::string>& sensitivities, bool state_error_only,
                  bool use_cache, bool interpret);
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
               bool project_initial, bool switch_events, unsigned threads, bool use_cache, bool interpret);

// bind_arrays.cpp
/// ẋ = rhs(t, x) at each row of `x` (shape (N, 2n) or (2n,)), t a scalar or one value per row.
py::array_t<double> rhs(LoadedModel& m, py::array_t<double, py::array::c_style | py::array::forcecast> t,
                        py::array_t<double, py::array::c_style | py::array::forcecast> x,
                        const std::vector<std::pair<std::string, double>>& set, bool use_cache, bool interpret);
/// J = ∂ẋ/∂x (N × 2n × 2n) and Jp = ∂ẋ/∂p (N × 2n × n_params) at each row of `x` (shape (N, 2n) or (2n,), then
/// without the leading N), by the compiled table's Jacobian (the header's analytic one where the model has it,
/// else forward differentiation in the shared object).
py::tuple jacobian(LoadedModel& m, py::array_t<double, py::array::c_style | py::array::forcecast> t,
                   py::array_t<double, py::array::c_style | py::array::forcecast> x,
                   const std::vector<std::pair<std::string, double>>& set, bool use_cache, bool interpret);

}  // namespace eomgen::python
