/** @file interpreted_table.cpp  The table functions over an InterpretedModel's tapes (interpreted_table.hpp). */
#include "interpreter/interpreted_table.hpp"

#include "eomgen/constraints.hpp"
#include "eomgen/linear_solve.hpp"
#include "eomgen/table_wrappers.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace eomgen::interpreter {
namespace {

using table_detail::guarded;

/// The models of the slots in use (null: free).
std::array<std::atomic<const InterpretedModel*>, InterpretedTable::kSlots> g_slots{};
std::mutex g_slots_lock;

// The parameter block: the model, then one double per parameter.
const InterpretedModel& model_of(const void* p) { return **static_cast<const InterpretedModel* const*>(p); }
const double* values_of(const void* p) {
    return reinterpret_cast<const double*>(static_cast<const char*>(p) + sizeof(const InterpretedModel*));
}
double* values_of(void* p) { return reinterpret_cast<double*>(static_cast<char*>(p) + sizeof(const InterpretedModel*)); }

/// Per thread: the registers, a tape's values, and the matrices of a solve (no allocation once sized).
struct Workspace {
    std::vector<double> registers, values;
    Eigen::MatrixXd M, A;
    Eigen::VectorXd f, gamma, qdd, lambda;
    MassFactor<double, Eigen::Dynamic> factor;  ///< kept, so that factoring M allocates nothing once sized
};
Workspace& workspace() {
    thread_local Workspace w;
    return w;
}

/// The tapes' inputs (interpreted_model.hpp: the parameters, q, q̇, q̈ of each coordinate, t, π) at (t, q, q̇).
void set_inputs(double* r, const InterpretedModel& m, double t, const double* q, const double* qd, const void* p) {
    const std::size_t np = m.param_names.size();
    std::copy(values_of(p), values_of(p) + np, r);
    for (int i = 0; i < m.nq; ++i) {
        r[np + 3 * i] = q[i];
        r[np + 3 * i + 1] = qd ? qd[i] : 0.0;
        r[np + 3 * i + 2] = 0.0;  // q̈ appears in none of the functions run here
    }
    r[np + 3 * m.nq] = t;
    r[np + 3 * m.nq + 1] = 3.141592653589793238462643383279502884;
}

/// Runs `tape` at (t, q, q̇) with the block's parameters (q̇ null: zero); returns its values.
const std::vector<double>& run(const Tape& tape, double t, const double* q, const double* qd, const void* p) {
    Workspace& w = workspace();
    if (w.registers.size() < static_cast<std::size_t>(tape.registers())) w.registers.resize(tape.registers());
    w.values.resize(tape.outputs.size());
    set_inputs(w.registers.data(), model_of(p), t, q, qd, p);
    tape.run(w.registers.data(), w.values.data());
    return w.values;
}

/// A run with derivatives: values, and dvalues[i K + d] = ∂value_i/∂z_d for z = (q, q̇, p, t), K = 2n + n_p + 1.
struct Derivatives {
    std::vector<double> registers, tangents, values, dvalues;
    int K = 0;
    double d(std::size_t value, int direction) const { return dvalues[value * static_cast<std::size_t>(K) + static_cast<std::size_t>(direction)]; }
};

/// Runs `tape` at (t, x) with the derivatives by every state, parameter and t.
void run_derivatives(const Tape& tape, double t, const double* x, const void* p, Derivatives& w) {
    const InterpretedModel& m = model_of(p);
    const int n = m.nq, np = static_cast<int>(m.param_names.size());
    w.K = 2 * n + np + 1;
    const std::size_t K = static_cast<std::size_t>(w.K);
    w.registers.resize(static_cast<std::size_t>(tape.registers()));
    w.tangents.assign(static_cast<std::size_t>(tape.registers()) * K, 0.0);
    w.values.resize(tape.outputs.size());
    w.dvalues.resize(tape.outputs.size() * K);
    set_inputs(w.registers.data(), m, t, x, x + n, p);
    auto seed = [&](int reg, int direction) { w.tangents[static_cast<std::size_t>(reg) * K + static_cast<std::size_t>(direction)] = 1; };
    for (int i = 0; i < np; ++i) seed(i, 2 * n + i);
    for (int i = 0; i < n; ++i) {
        seed(np + 3 * i, i);
        seed(np + 3 * i + 1, n + i);
    }
    seed(np + 3 * n, 2 * n + np);
    tape.run_tangent(w.registers.data(), w.tangents.data(), w.K, w.values.data(), w.dvalues.data());
}

/// out (rows × cols, column-major) = ∂value_{first + r}/∂z_{from + c}.
void derivative_block(const Derivatives& w, std::size_t first, int rows, int from, int cols, double* out) {
    for (int c = 0; c < cols; ++c)
        for (int r = 0; r < rows; ++r)
            out[static_cast<std::size_t>(c) * static_cast<std::size_t>(rows) + static_cast<std::size_t>(r)] =
                w.d(first + static_cast<std::size_t>(r), from + c);
}

/// The values into out[0 .. count), from `first`.
void copy(const std::vector<double>& v, std::size_t first, std::size_t count, double* out) {
    std::copy(v.begin() + static_cast<std::ptrdiff_t>(first), v.begin() + static_cast<std::ptrdiff_t>(first + count), out);
}

/// M (row by row in the tape; symmetric) and f from the tape's first n² + n values into the workspace.
void mass_and_forcing(const std::vector<double>& v, int n, Workspace& w) {
    w.M.resize(n, n);
    w.f.resize(n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) w.M(i, j) = v[static_cast<std::size_t>(i * n + j)];
    for (int i = 0; i < n; ++i) w.f(i) = v[static_cast<std::size_t>(n * n + i)];
}

/// q̈ and λ of a constrained model with its Baumgarte terms, as a header's accelerations() computes them.
void constrained_accelerations(double t, const double* x, const void* p) {
    const InterpretedModel& m = model_of(p);
    const int n = m.nq, nc = static_cast<int>(m.constraint_names.size());
    const std::vector<double>& v = run(m.constrained, t, x, x + n, p);
    Workspace& w = workspace();
    mass_and_forcing(v, n, w);
    std::size_t at = static_cast<std::size_t>(n * n + n);
    w.A.resize(nc, n);
    for (int k = 0; k < nc; ++k)
        for (int i = 0; i < n; ++i) w.A(k, i) = v[at++];
    w.gamma.resize(nc);
    for (int k = 0; k < nc; ++k) {
        const double gamma = v[at + static_cast<std::size_t>(k)], position = v[at + static_cast<std::size_t>(nc + k)],
                     velocity = v[at + static_cast<std::size_t>(2 * nc + k)];
        w.gamma(k) = gamma - (2 * m.baumgarte_alpha * velocity + m.baumgarte_beta * m.baumgarte_beta * position);
    }
    w.qdd.resize(n);
    w.lambda.resize(nc);
    const Eigen::Map<const Eigen::VectorXd> state(x, 2 * n);
    solve_constrained(w.M, w.f, w.A, w.gamma, w.qdd, w.lambda, t, state);
}

Derivatives& derivatives() {
    thread_local Derivatives d;
    return d;
}

void differentiate_accelerations(double t, const double* x, const void* p, Eigen::MatrixXd& dqdd, Eigen::MatrixXd& dlambda);

/// ∂q̈/∂z (n × K) and, with constraints, ∂λ/∂z (n_c × K), z = (q, q̇, p, t), by differentiating the solve of
/// rhs(): M dq̈ = df − dM q̈ (+ dAᵀ λ + Aᵀ dλ), A dq̈ = dγ̃ − dA q̈ with γ̃ = γ − 2α c − β² g, each column by the same
/// factorization (solve_constrained: one solve a column). The last result is kept per thread: the sensitivities ask
/// for ∂ẋ/∂x and ∂ẋ/∂p (and ∂λ) at the same point one after the other, and get them from one pass.
void acceleration_derivatives(double t, const double* x, const void* p, Eigen::MatrixXd& dqdd, Eigen::MatrixXd& dlambda) {
    struct Last {
        std::uint64_t model = 0;  ///< InterpretedModel::identity (an address could be a later model's)
        double t = 0;
        std::vector<double> x, params;
        Eigen::MatrixXd dqdd, dlambda;
    };
    thread_local Last last;
    const InterpretedModel& m = model_of(p);
    const std::size_t nx = static_cast<std::size_t>(2 * m.nq), np = m.param_names.size();
    const bool same = last.model == m.identity && last.t == t && last.x.size() == nx &&
                      std::equal(x, x + nx, last.x.begin()) && last.params.size() == np &&
                      std::equal(values_of(p), values_of(p) + np, last.params.begin());
    if (!same) {
        last.model = 0;  // until the new result is complete (a throw leaves nothing kept)
        differentiate_accelerations(t, x, p, last.dqdd, last.dlambda);
        last.model = m.identity;
        last.t = t;
        last.x.assign(x, x + nx);
        last.params.assign(values_of(p), values_of(p) + np);
    }
    dqdd = last.dqdd;
    dlambda = last.dlambda;
}

void differentiate_accelerations(double t, const double* x, const void* p, Eigen::MatrixXd& dqdd, Eigen::MatrixXd& dlambda) {
    const InterpretedModel& m = model_of(p);
    const int n = m.nq, nc = static_cast<int>(m.constraint_names.size());
    Derivatives& d = derivatives();
    const Eigen::Map<const Eigen::VectorXd> state(x, 2 * n);
    Workspace& w = workspace();
    run_derivatives(nc == 0 ? m.dynamics : m.constrained, t, x, p, d);
    const int K = d.K;
    mass_and_forcing(d.values, n, w);
    auto dM = [&](int i, int j, int z) { return d.d(static_cast<std::size_t>(i * n + j), z); };
    auto df = [&](int i, int z) { return d.d(static_cast<std::size_t>(n * n + i), z); };
    dqdd.resize(n, K);
    if (nc == 0) {
        if (!w.factor.compute(w.M)) throw_solve_failure(w.M, w.f, true, t, state);
        w.qdd = w.f;
        w.factor.solve_in_place(w.qdd);
        if (!w.qdd.allFinite()) throw_solve_failure(w.M, w.f, false, t, state);
        for (int z = 0; z < K; ++z)
            for (int i = 0; i < n; ++i) {
                double v = df(i, z);
                for (int j = 0; j < n; ++j) v -= dM(i, j, z) * w.qdd(j);
                dqdd(i, z) = v;
            }
        w.factor.solve_in_place(dqdd);
        dlambda.resize(0, K);
        return;
    }
    const std::size_t at = static_cast<std::size_t>(n * n + n);  // A, then γ, g, c
    w.A.resize(nc, n);
    for (int k = 0; k < nc; ++k)
        for (int i = 0; i < n; ++i) w.A(k, i) = d.values[at + static_cast<std::size_t>(k * n + i)];
    const double alpha = m.baumgarte_alpha, beta2 = m.baumgarte_beta * m.baumgarte_beta;
    auto gamma_row = [&](int k) { return at + static_cast<std::size_t>(nc * n + k); };
    auto g_row = [&](int k) { return at + static_cast<std::size_t>(nc * n + nc + k); };
    auto c_row = [&](int k) { return at + static_cast<std::size_t>(nc * n + 2 * nc + k); };
    w.gamma.resize(nc);
    for (int k = 0; k < nc; ++k)
        w.gamma(k) = d.values[gamma_row(k)] - (2 * alpha * d.values[c_row(k)] + beta2 * d.values[g_row(k)]);
    w.qdd.resize(n);
    w.lambda.resize(nc);
    solve_constrained(w.M, w.f, w.A, w.gamma, w.qdd, w.lambda, t, state);
    dlambda.resize(nc, K);
    Eigen::VectorXd fz(n), gz(nc), qz(n), lz(nc);
    for (int z = 0; z < K; ++z) {
        for (int i = 0; i < n; ++i) {
            double v = df(i, z);
            for (int j = 0; j < n; ++j) v -= dM(i, j, z) * w.qdd(j);
            for (int k = 0; k < nc; ++k) v += d.d(at + static_cast<std::size_t>(k * n + i), z) * w.lambda(k);
            fz(i) = v;
        }
        for (int k = 0; k < nc; ++k) {
            double v = d.d(gamma_row(k), z) - 2 * alpha * d.d(c_row(k), z) - beta2 * d.d(g_row(k), z);
            for (int i = 0; i < n; ++i) v -= d.d(at + static_cast<std::size_t>(k * n + i), z) * w.qdd(i);
            gz(k) = v;
        }
        solve_constrained(w.M, fz, w.A, gz, qz, lz, t, state);
        dqdd.col(z) = qz;
        dlambda.col(z) = lz;
    }
}

struct Functions {
    static bool set_param(void* p, const char* name, double value) {
        const InterpretedModel& m = model_of(p);
        for (std::size_t i = 0; i < m.param_names.size(); ++i)
            if (m.param_names[i] == name) {
                values_of(p)[i] = value;
                return true;
            }
        return false;
    }
    static void param_values(const void* p, double* values) {
        std::copy(values_of(p), values_of(p) + model_of(p).param_names.size(), values);
    }
    static int rhs(double t, const double* x, const void* p, double* xdot) {
        return guarded([&] {
            const InterpretedModel& m = model_of(p);
            const int n = m.nq;
            Workspace& w = workspace();
            if (m.constraint_names.empty()) {
                mass_and_forcing(run(m.dynamics, t, x, x + n, p), n, w);
                // solve_mass_matrix's steps, on the workspace's factor.
                const Eigen::Map<const Eigen::VectorXd> state(x, 2 * n);
                if (!w.factor.compute(w.M)) throw_solve_failure(w.M, w.f, true, t, state);
                w.qdd = w.f;
                w.factor.solve_in_place(w.qdd);
                if (!w.qdd.allFinite()) throw_solve_failure(w.M, w.f, false, t, state);
            } else {
                constrained_accelerations(t, x, p);
            }
            std::copy(x + n, x + 2 * n, xdot);
            std::copy(w.qdd.data(), w.qdd.data() + n, xdot + n);
        });
    }
    static int energy(double t, const double* q, const double* qd, const void* p, double* h) {
        return guarded([&] { *h = run(model_of(p).energy, t, q, qd, p)[0]; });
    }
    static int conserved(double t, const double* q, const double* qd, const void* p, double* out) {
        return guarded([&] {
            const Tape& tape = model_of(p).conserved;
            copy(run(tape, t, q, qd, p), 0, tape.outputs.size(), out);
        });
    }
    static int outputs(double t, const double* q, const double* qd, const void* p, double* out) {
        return guarded([&] {
            const Tape& tape = model_of(p).outputs;
            copy(run(tape, t, q, qd, p), 0, tape.outputs.size(), out);
        });
    }
    static int mass_matrix(double t, const double* q, const void* p, double* M) {
        return guarded([&] {
            const int n = model_of(p).nq;
            const std::vector<double>& v = run(model_of(p).dynamics, t, q, nullptr, p);
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) M[j * n + i] = v[static_cast<std::size_t>(i * n + j)];  // column-major
        });
    }
    static int momenta(double t, const double* q, const double* qd, const void* p, double* out) {
        return guarded([&] { copy(run(model_of(p).momenta, t, q, qd, p), 0, static_cast<std::size_t>(model_of(p).nq), out); });
    }
    static int lagrangian_gradient(double t, const double* q, const double* qd, const void* p, double* out) {
        return guarded([&] {
            copy(run(model_of(p).lagrangian_gradient, t, q, qd, p), 0, static_cast<std::size_t>(model_of(p).nq), out);
        });
    }
    static int constraints(double t, const double* q, const double* qd, const void* p, double* A, double* gamma) {
        return guarded([&] {
            const InterpretedModel& m = model_of(p);
            const int n = m.nq, nc = static_cast<int>(m.constraint_names.size());
            const std::vector<double>& v = run(m.constrained, t, q, qd, p);
            const std::size_t at = static_cast<std::size_t>(n * n + n);
            for (int k = 0; k < nc; ++k)
                for (int i = 0; i < n; ++i) A[i * nc + k] = v[at + static_cast<std::size_t>(k * n + i)];  // column-major
            copy(v, at + static_cast<std::size_t>(nc * n), static_cast<std::size_t>(nc), gamma);
        });
    }
    static int constraint_residuals(double t, const double* q, const double* qd, const void* p, double* g, double* c) {
        return guarded([&] {
            const InterpretedModel& m = model_of(p);
            const std::size_t n = static_cast<std::size_t>(m.nq), nc = m.constraint_names.size();
            const std::vector<double>& v = run(m.constrained, t, q, qd, p);
            const std::size_t at = n * n + n + nc * n + nc;
            copy(v, at, nc, g);
            copy(v, at + nc, nc, c);
        });
    }
    static int multipliers(double t, const double* x, const void* p, double* lambda) {
        return guarded([&] {
            constrained_accelerations(t, x, p);
            const Workspace& w = workspace();
            std::copy(w.lambda.data(), w.lambda.data() + w.lambda.size(), lambda);
        });
    }
    static int switching(double t, const double* q, const double* qd, const void* p, double* out) {
        return guarded([&] {
            const Tape& tape = model_of(p).switching;
            copy(run(tape, t, q, qd, p), 0, tape.outputs.size(), out);
        });
    }
    static int power(double t, const double* q, const double* qd, const void* p, double* out) {
        return guarded([&] { *out = run(model_of(p).power, t, q, qd, p)[0]; });
    }
    // The Jacobians: forward differentiation through the tapes (Tape::run_tangent) and the solve.
    static int jacobian(double t, const double* x, const void* p, double* J) {
        return guarded([&] {
            const int n = model_of(p).nq;
            Eigen::MatrixXd dqdd, dlambda;
            acceleration_derivatives(t, x, p, dqdd, dlambda);
            Eigen::Map<Eigen::MatrixXd> out(J, 2 * n, 2 * n);
            out.setZero();
            out.topRightCorner(n, n).setIdentity();
            out.bottomRows(n) = dqdd.leftCols(2 * n);
        });
    }
    static int parameter_jacobian(double t, const double* x, const void* p, double* Jp) {
        return guarded([&] {
            const int n = model_of(p).nq, np = static_cast<int>(model_of(p).param_names.size());
            Eigen::MatrixXd dqdd, dlambda;
            acceleration_derivatives(t, x, p, dqdd, dlambda);
            Eigen::Map<Eigen::MatrixXd> out(Jp, 2 * n, np);
            out.setZero();
            out.bottomRows(n) = dqdd.middleCols(2 * n, np);
        });
    }
    static int multiplier_jacobian(double t, const double* x, const void* p, double* Lx, double* Lp) {
        return guarded([&] {
            const int n = model_of(p).nq, np = static_cast<int>(model_of(p).param_names.size());
            Eigen::MatrixXd dqdd, dlambda;
            acceleration_derivatives(t, x, p, dqdd, dlambda);
            Eigen::Map<Eigen::MatrixXd>(Lx, dlambda.rows(), 2 * n) = dlambda.leftCols(2 * n);
            Eigen::Map<Eigen::MatrixXd>(Lp, dlambda.rows(), np) = dlambda.middleCols(2 * n, np);
        });
    }
    static int output_jacobian(double t, const double* x, const void* p, double* Yx, double* Yp) {
        return guarded([&] {
            const InterpretedModel& m = model_of(p);
            const int n = m.nq, np = static_cast<int>(m.param_names.size()), no = static_cast<int>(m.output_names.size());
            Derivatives& d = derivatives();
            run_derivatives(m.outputs, t, x, p, d);
            derivative_block(d, 0, no, 0, 2 * n, Yx);
            derivative_block(d, 0, no, 2 * n, np, Yp);
        });
    }
    static int constraint_residual_jacobian(double t, const double* x, const void* p, double* Rx, double* Rp) {
        return guarded([&] {
            const InterpretedModel& m = model_of(p);
            const int n = m.nq, np = static_cast<int>(m.param_names.size()), nc = static_cast<int>(m.constraint_names.size());
            Derivatives& d = derivatives();
            run_derivatives(m.constrained, t, x, p, d);
            // Position rows (g), then velocity rows (c): the values after M, f, A and γ, as they are recorded.
            const std::size_t g = static_cast<std::size_t>(n * n + n + nc * n + nc);
            Eigen::MatrixXd rx(2 * nc, 2 * n), rp(2 * nc, np);
            derivative_block(d, g, 2 * nc, 0, 2 * n, rx.data());
            derivative_block(d, g, 2 * nc, 2 * n, np, rp.data());
            Eigen::Map<Eigen::MatrixXd>(Rx, 2 * nc, 2 * n) = rx;
            Eigen::Map<Eigen::MatrixXd>(Rp, 2 * nc, np) = rp;
        });
    }
    static int switching_jacobian(double t, const double* x, const void* p, double* Sx, double* Sp, double* St) {
        return guarded([&] {
            const InterpretedModel& m = model_of(p);
            const int n = m.nq, np = static_cast<int>(m.param_names.size()), ns = static_cast<int>(m.switch_names.size());
            Derivatives& d = derivatives();
            run_derivatives(m.switching, t, x, p, d);
            derivative_block(d, 0, ns, 0, 2 * n, Sx);
            derivative_block(d, 0, ns, 2 * n, np, Sp);
            derivative_block(d, 0, ns, 2 * n + np, 1, St);
        });
    }
    static int lagrangian_jacobian(double t, const double* x, const void* p, double* Px, double* Pp, double* Gx,
                                   double* Gp) {
        return guarded([&] {
            const InterpretedModel& m = model_of(p);
            const int n = m.nq, np = static_cast<int>(m.param_names.size());
            Derivatives& d = derivatives();
            run_derivatives(m.momenta, t, x, p, d);
            derivative_block(d, 0, n, 0, 2 * n, Px);
            derivative_block(d, 0, n, 2 * n, np, Pp);
            run_derivatives(m.lagrangian_gradient, t, x, p, d);
            derivative_block(d, 0, n, 0, 2 * n, Gx);
            derivative_block(d, 0, n, 2 * n, np, Gp);
        });
    }
    static const char* error_message(double* t) {
        if (t) *t = table_detail::last_error().t;
        return table_detail::last_error().message.c_str();
    }
};

/// The two functions that have no parameter block to read the model from: one instance per slot.
template <int K>
struct Slot {
    static void init_params(void* p) {
        const InterpretedModel* m = g_slots[K].load();
        std::memcpy(p, &m, sizeof m);
        std::copy(m->param_defaults.begin(), m->param_defaults.end(), values_of(p));
    }
    static void default_state(double* x) {
        const InterpretedModel* m = g_slots[K].load();
        std::copy(m->default_state.begin(), m->default_state.end(), x);
    }
};

using InitParams = void (*)(void*);
using DefaultState = void (*)(double*);
template <std::size_t... K>
constexpr std::array<std::pair<InitParams, DefaultState>, sizeof...(K)> slot_functions(std::index_sequence<K...>) {
    return {{{&Slot<static_cast<int>(K)>::init_params, &Slot<static_cast<int>(K)>::default_state}...}};
}
constexpr auto kSlotFunctions = slot_functions(std::make_index_sequence<InterpretedTable::kSlots>());

}  // namespace

InterpretedTable::InterpretedTable(InterpretedModel model) : model_(std::make_unique<InterpretedModel>(std::move(model))) {
    static std::atomic<std::uint64_t> tables{0};
    model_->identity = ++tables;
    {
        std::lock_guard<std::mutex> lock(g_slots_lock);
        for (int k = 0; k < kSlots && slot_ < 0; ++k)
            if (!g_slots[static_cast<std::size_t>(k)].load()) {
                g_slots[static_cast<std::size_t>(k)].store(model_.get());
                slot_ = k;
            }
    }
    if (slot_ < 0)
        throw std::runtime_error("more than " + std::to_string(kSlots) + " interpreted models at once in one process");
    const InterpretedModel& m = *model_;
    // set_inputs() writes the symbol table's layout: a tape recorded over another would read the wrong registers.
    for (const Tape* tape : {&m.dynamics, &m.energy, &m.conserved, &m.outputs, &m.momenta, &m.lagrangian_gradient,
                             &m.power, &m.switching, &m.constrained})
        if (tape->n_inputs != 0 && tape->n_inputs != m.n_inputs()) {  // 0: not recorded (no power, no constraints)
            g_slots[static_cast<std::size_t>(slot_)].store(nullptr);
            throw std::logic_error("an interpreted model's tape has " + std::to_string(tape->n_inputs) +
                                   " inputs where its model has " + std::to_string(m.n_inputs()));
        }
    auto names = [this](const std::vector<std::string>& v) {
        std::vector<const char*> c;
        for (const std::string& s : v) c.push_back(s.c_str());
        names_.push_back(std::move(c));
        return names_.back().data();
    };
    names_.reserve(16);  // the arrays' data() must stay where they are: no reallocation of names_ below
    ModelTable& t = table_;
    t.abi = kModelTableAbi;
    t.name = m.name.c_str();
    t.title = m.title.c_str();
    t.source = m.source.c_str();
    t.nq = m.nq;
    t.n_params = static_cast<int>(m.param_names.size());
    t.n_conserved = static_cast<int>(m.conserved_names.size());
    t.n_outputs = static_cast<int>(m.output_names.size());
    t.n_constraints = static_cast<int>(m.constraint_names.size());
    t.explicit_time = m.explicit_time;
    t.has_generalized_forces = m.has_generalized_forces;
    t.state_names = names(m.state_names);
    t.param_names = names(m.param_names);
    t.conserved_names = names(m.conserved_names);
    t.output_names = names(m.output_names);
    t.params_size = sizeof(const InterpretedModel*) + sizeof(double) * m.param_names.size();
    t.params_align = alignof(double);
    t.init_params = kSlotFunctions[static_cast<std::size_t>(slot_)].first;
    t.default_state = kSlotFunctions[static_cast<std::size_t>(slot_)].second;
    t.set_param = &Functions::set_param;
    t.param_values = &Functions::param_values;
    t.rhs = &Functions::rhs;
    t.energy = &Functions::energy;
    t.conserved = &Functions::conserved;
    t.outputs = &Functions::outputs;
    t.mass_matrix = &Functions::mass_matrix;
    t.momenta = &Functions::momenta;
    t.lagrangian_gradient = &Functions::lagrangian_gradient;
    if (t.n_constraints > 0) {
        t.constraint_names = names(m.constraint_names);
        holonomic_ = std::make_unique<bool[]>(m.constraint_is_holonomic.size());
        for (std::size_t k = 0; k < m.constraint_is_holonomic.size(); ++k) holonomic_[k] = m.constraint_is_holonomic[k] != 0;
        t.constraint_is_holonomic = holonomic_.get();
        t.constraints = &Functions::constraints;
        t.constraint_residuals = &Functions::constraint_residuals;
        t.multipliers = &Functions::multipliers;
    }
    t.error_message = &Functions::error_message;
    t.jacobian = &Functions::jacobian;
    t.parameter_jacobian = &Functions::parameter_jacobian;
    t.output_jacobian = &Functions::output_jacobian;
    t.lagrangian_jacobian = &Functions::lagrangian_jacobian;
    if (t.n_constraints > 0) {
        t.multiplier_jacobian = &Functions::multiplier_jacobian;
        t.constraint_residual_jacobian = &Functions::constraint_residual_jacobian;
    }
    if (!m.switch_names.empty()) {
        t.n_switches = static_cast<int>(m.switch_names.size());
        t.switch_names = names(m.switch_names);
        t.switching = &Functions::switching;
        t.switching_jacobian = &Functions::switching_jacobian;
    }
    if (m.has_power) t.power = &Functions::power;
    t.energy_unit = m.energy_unit.c_str();
    t.state_units = names(m.state_units);
    t.param_units = names(m.param_units);
    t.conserved_units = names(m.conserved_units);
    t.output_units = names(m.output_units);
    if (t.n_constraints > 0) t.multiplier_units = names(m.multiplier_units);
    t.param_declared_units = names(m.param_declared_units);
    t.coordinate_declared_units = names(m.coordinate_declared_units);
}

InterpretedTable::~InterpretedTable() {
    std::lock_guard<std::mutex> lock(g_slots_lock);
    if (slot_ >= 0) g_slots[static_cast<std::size_t>(slot_)].store(nullptr);
}

}  // namespace eomgen::interpreter
