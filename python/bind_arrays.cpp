/** @file bind_arrays.cpp  The compiled functions over NumPy arrays for Python (binding.hpp): rhs and the Jacobians
 * at many states, looping in C++ without the GIL. */
#include "binding.hpp"

#include "eomgen/errors.hpp"

#include <algorithm>

namespace eomgen::python {

/// How many states `x` holds (shape (N, 2n) or one state (2n,)), with `t` one time or one per state; UsageError
/// naming `what` otherwise.
static py::ssize_t state_rows(const LoadedModel& m, const py::array_t<double, py::array::c_style | py::array::forcecast>& t,
                              const py::array_t<double, py::array::c_style | py::array::forcecast>& x, const char* what) {
    const py::ssize_t nx = 2 * py::ssize_t(m.model().dof());
    if ((x.ndim() != 1 && x.ndim() != 2) || x.shape(x.ndim() - 1) != nx)
        throw sim::UsageError(std::string(what) + ": x must have shape (" + std::to_string(nx) + ",) or (N, " +
                              std::to_string(nx) + "): q then q' of " + m.model().name);
    const py::ssize_t rows = x.ndim() == 2 ? x.shape(0) : 1;
    if (t.size() != 1 && t.size() != rows)
        throw sim::UsageError(std::string(what) + ": t must be one time or one per state (" + std::to_string(rows) +
                              "), not " + std::to_string(t.size()));
    return rows;
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
                        const std::vector<std::pair<std::string, double>>& set, bool use_cache, bool interpret) {
    const ModelTable& table = m.table(false, use_cache, interpret);
    const py::ssize_t nx = 2 * py::ssize_t(table.nq);
    const py::ssize_t rows = state_rows(m, t, x, "rhs");
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
                   const std::vector<std::pair<std::string, double>>& set, bool use_cache, bool interpret) {
    const ModelTable& table = m.table(true, use_cache, interpret);
    const py::ssize_t nx = 2 * py::ssize_t(table.nq), np_ = table.n_params;
    const py::ssize_t rows = state_rows(m, t, x, "jacobian");
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

}  // namespace eomgen::python
