/**
 * @file model_table.hpp  A generated model behind a table of plain functions, so that a model compiled on
 * its own (a shared object `eomgen run` builds and loads with dlopen) is integrated by a driver compiled
 * once, in the program that loads it.
 *
 * Why: the simulation driver (simulation.hpp) instantiated for one generated model costs about 9 s of
 * compilation, the model's own functions about 1 s. With the table, the shared object holds only the
 * model's functions and the driver is compiled once into eomgen, instantiated for TableModel.
 *
 * The model's side (the shared object): model_table<Model<double>>() is the table of one generated model;
 * its functions (table_wrappers.hpp) take and fill arrays (matrices column-major), catch every exception and
 * return its kind (TableStatus), with the message and time kept per thread for error_message().
 *
 * The program's side: TableModel is a Model (docs/generated_code.md) whose sizes are known at run time
 * (nq = Eigen::Dynamic; Config, State, ... are Eigen's dynamic vectors), calling through the table bound
 * with TableModel::bind(); errors come back as the runtime's own exception classes.
 */
#pragma once

#include "eomgen/errors.hpp"
#include "eomgen/model_jacobian.hpp"
#include "eomgen/column_units.hpp"
#include "eomgen/model_traits.hpp"
#include "eomgen/table_wrappers.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen {

/// Raised when ModelTable's layout changes: a table of another layout is refused.
constexpr std::uint32_t kModelTableAbi = 8;

/// One model as data and plain functions. Parameters live in an opaque block of params_size bytes that
/// init_params fills with the model's defaults. Functions without constraints are null when n_constraints = 0.
struct ModelTable {
    std::uint32_t abi;
    const char *name, *title, *source;
    int nq, n_params, n_conserved, n_outputs, n_constraints;
    bool explicit_time, has_generalized_forces;
    const char* const* state_names;       ///< 2 nq: q, then q'
    const char* const* param_names;       ///< n_params
    const char* const* conserved_names;   ///< n_conserved
    const char* const* output_names;      ///< n_outputs
    const char* const* constraint_names;  ///< n_constraints
    const bool* constraint_is_holonomic;  ///< n_constraints
    std::size_t params_size, params_align;
    void (*init_params)(void* p);
    bool (*set_param)(void* p, const char* name, double value);
    void (*param_values)(const void* p, double* values);
    void (*default_state)(double* x);
    int (*rhs)(double t, const double* x, const void* p, double* xdot);
    int (*energy)(double t, const double* q, const double* qd, const void* p, double* h);
    int (*conserved)(double t, const double* q, const double* qd, const void* p, double* out);
    int (*outputs)(double t, const double* q, const double* qd, const void* p, double* out);
    int (*mass_matrix)(double t, const double* q, const void* p, double* M);
    int (*momenta)(double t, const double* q, const double* qd, const void* p, double* out);
    int (*lagrangian_gradient)(double t, const double* q, const double* qd, const void* p, double* out);
    int (*constraints)(double t, const double* q, const double* qd, const void* p, double* A, double* gamma);
    int (*constraint_residuals)(double t, const double* q, const double* qd, const void* p, double* g, double* c);
    int (*multipliers)(double t, const double* x, const void* p, double* lambda);
    /// J = ∂ẋ/∂x (2 nq × 2 nq, column-major), by forward differentiation in the shared object (model_jacobian.hpp);
    /// null unless the table was made by model_table<M, true>.
    int (*jacobian)(double t, const double* x, const void* p, double* J);
    /// Jp = ∂ẋ/∂p (2 nq × n_params, column-major), for sensitivities (sensitivities.hpp): the header's analytic one
    /// where it has one, else by forward differentiation in the shared object; null as `jacobian` is.
    int (*parameter_jacobian)(double t, const double* x, const void* p, double* Jp);
    /// Yx = ∂y/∂x (n_outputs × 2 nq) and Yp = ∂y/∂p (n_outputs × n_params) of the declared outputs, column-major, by
    /// forward differentiation in the shared object (linearize_outputs); null as `jacobian` is.
    int (*output_jacobian)(double t, const double* x, const void* p, double* Yx, double* Yp);
    /// Lx = ∂λ/∂x (n_constraints × 2 nq) and Lp = ∂λ/∂p of the multipliers, column-major, by forward differentiation
    /// through the constrained solve (linearize_multipliers); null without constraints and as `jacobian` is.
    int (*multiplier_jacobian)(double t, const double* x, const void* p, double* Lx, double* Lp);
    /// The message of the last error on this thread, and its time in *t.
    const char* (*error_message)(double* t);
    /// The switching surfaces of rhs() (abs, sign, heaviside, max, min): n_switches values s_k, 0 and null when none.
    int n_switches;
    const char* const* switch_names;
    int (*switching)(double t, const double* q, const double* qd, const void* p, double* out);
    /// dh/dt = Σ Q_i q'_i − ∂L/∂t (M::power), null where the model has none.
    int (*power)(double t, const double* q, const double* qd, const void* p, double* out);
    /// The units (column_units.hpp), null where the header declares none: SI for the values written, the model
    /// file's own for the numbers of --set and --init.
    const char* energy_unit;
    const char* const* state_units;                ///< 2 nq
    const char* const* param_units;                ///< n_params
    const char* const* conserved_units;            ///< n_conserved
    const char* const* output_units;               ///< n_outputs
    const char* const* multiplier_units;           ///< n_constraints
    const char* const* param_declared_units;       ///< n_params
    const char* const* coordinate_declared_units;  ///< nq
    /// Rx = ∂(g, c)/∂x (2 n_constraints × 2 nq) and Rp = ∂(g, c)/∂p of the constraint residuals (position rows, then
    /// velocity rows), column-major, by forward differentiation (linearize_constraint_residuals): a consistent start
    /// of the sensitivities; null without constraints and as `jacobian` is.
    int (*constraint_residual_jacobian)(double t, const double* x, const void* p, double* Rx, double* Rp);
    /// Sx = ∂s/∂x (n_switches × 2 nq), Sp = ∂s/∂p and St = ∂s/∂t of the switching functions, column-major, by
    /// forward differentiation (linearize_switching): the saltation of the sensitivities; null without switches and
    /// as `jacobian` is.
    int (*switching_jacobian)(double t, const double* x, const void* p, double* Sx, double* Sp, double* St);
    /// Px = ∂P/∂x, Pp = ∂P/∂p of the momenta P = ∂L/∂q̇ and Gx, Gp of G = ∂L/∂q (nq × 2 nq and nq × n_params each,
    /// column-major), by forward differentiation: the sensitivities of the variational integrator
    /// (variational_sensitivities.hpp); null as `jacobian` is.
    int (*lagrangian_jacobian)(double t, const double* x, const void* p, double* Px, double* Pp, double* Gx,
                               double* Gp);
};

/// The table of generated model M (a Model<double> of a generated header). With `WithJacobian` the table's
/// `jacobian` and `parameter_jacobian` are filled (one forward differentiation through rhs() for both where the
/// header has no analytic ones: it doubles the shared object's compile time), else null.
template <class M, bool WithJacobian = false>
const ModelTable& model_table() {
    using W = table_detail::Wrappers<M>;
    constexpr bool constrained = is_constrained<M>::value;
    static const ModelTable table = [] {
        ModelTable t{};
        t.abi = kModelTableAbi;
        t.name = M::name;
        t.title = M::title;
        t.source = M::source;
        t.nq = M::nq;
        t.n_params = M::n_params;
        t.n_conserved = M::n_conserved;
        t.n_outputs = M::n_outputs;
        t.n_constraints = constraint_count<M>();
        t.explicit_time = M::explicit_time;
        t.has_generalized_forces = M::has_generalized_forces;
        t.state_names = M::state_names.data();
        t.param_names = M::param_names.data();
        t.conserved_names = M::conserved_names.data();
        t.output_names = M::output_names.data();
        if constexpr (constrained) {
            t.constraint_names = M::constraint_names.data();
            t.constraint_is_holonomic = M::constraint_is_holonomic.data();
            t.constraints = &W::constraints;
            t.constraint_residuals = &W::constraint_residuals;
            t.multipliers = &W::multipliers;
        }
        t.params_size = sizeof(typename M::Params);
        t.params_align = alignof(typename M::Params);
        t.init_params = &W::init_params;
        t.set_param = &W::set_param;
        t.param_values = &W::param_values;
        t.default_state = &W::default_state;
        t.rhs = &W::rhs;
        t.energy = &W::energy;
        t.conserved = &W::conserved;
        t.outputs = &W::outputs;
        t.mass_matrix = &W::mass_matrix;
        t.momenta = &W::momenta;
        t.lagrangian_gradient = &W::lagrangian_gradient;
        if constexpr (WithJacobian) {
            t.jacobian = &W::jacobian;
            t.parameter_jacobian = &W::parameter_jacobian;
            t.output_jacobian = &W::output_jacobian;
            if constexpr (constrained) {
                t.multiplier_jacobian = &W::multiplier_jacobian;
                t.constraint_residual_jacobian = &W::constraint_residual_jacobian;
            }
            if constexpr (has_switching<M>::value) t.switching_jacobian = &W::switching_jacobian;
            t.lagrangian_jacobian = &W::lagrangian_jacobian;
        }
        t.error_message = &W::error_message;
        if constexpr (declares_power<M>::value) t.power = &W::power;
        if constexpr (has_switching<M>::value) {
            t.n_switches = M::n_switches;
            t.switch_names = M::switch_names.data();
            t.switching = &W::switching;
        }
        if constexpr (declares_units<M>::value) {
            t.energy_unit = M::energy_unit;
            t.state_units = M::state_units.data();
            t.param_units = M::param_units.data();
            t.conserved_units = M::conserved_units.data();
            t.output_units = M::output_units.data();
            if constexpr (constrained) t.multiplier_units = M::multiplier_units.data();
            t.param_declared_units = M::param_declared_units.data();
            t.coordinate_declared_units = M::coordinate_declared_units.data();
        }
        return t;
    }();
    return table;
}

/**
 * A Model whose functions are a ModelTable's: sizes at run time, the interface of a generated model
 * (docs/generated_code.md) otherwise, so that simulation.hpp's driver runs it unchanged. One table is bound
 * at a time (bind() before any other use); the table and the shared object holding it must outlive its use.
 */
class TableModel {
  public:
    using Scalar = double;
    static constexpr int nq = Eigen::Dynamic;
    static constexpr int nx = Eigen::Dynamic;
    using Config = Eigen::VectorXd;
    using State = Eigen::VectorXd;
    using MassMatrix = Eigen::MatrixXd;
    using Conserved = Eigen::VectorXd;
    using Outputs = Eigen::VectorXd;
    using ConstraintVector = Eigen::VectorXd;
    using ConstraintJacobian = Eigen::MatrixXd;

    /// The model's parameter block, holding its defaults when made.
    class Params {
      public:
        Params() : storage_((table().params_size + sizeof(Slot) - 1) / sizeof(Slot) + 1) {
            table().init_params(data());
        }
        const void* data() const { return storage_.data(); }
        void* data() { return storage_.data(); }

      private:
        using Slot = std::max_align_t;
        std::vector<Slot> storage_;
    };

    static inline const char* name = "";
    static inline const char* title = "";
    static inline const char* source = "";
    static inline int n_params = 0, n_conserved = 0, n_outputs = 0, n_constraints = 0;
    static inline bool explicit_time = false, has_generalized_forces = false;
    static inline std::vector<const char*> state_names, coordinate_names, param_names, conserved_names, output_names,
        constraint_names;
    static inline std::vector<bool> constraint_is_holonomic;
    /// The switching surfaces (none when the model has no abs, sign, heaviside, max or min).
    using Switches = Eigen::VectorXd;
    static inline int n_switches = 0;
    static inline std::vector<const char*> switch_names;
    /// Whether the model has power() (dh/dt where h is not conserved).
    static inline bool has_power = false;
    /// The units (column_units.hpp): "" entries where the table has none.
    static inline const char* energy_unit = "";
    static inline std::vector<const char*> state_units, param_units, conserved_units, output_units, multiplier_units,
        param_declared_units, coordinate_declared_units;

    /// Makes `t` the model of every TableModel call; throws std::invalid_argument for a table of another
    /// layout or one this program cannot use.
    static void bind(const ModelTable& t) {
        if (t.abi != kModelTableAbi)
            throw std::invalid_argument("the compiled model's table has layout " + std::to_string(t.abi) +
                                        ", this eomgen reads " + std::to_string(kModelTableAbi));
        if (t.params_align > alignof(std::max_align_t))
            throw std::invalid_argument("the compiled model's parameters need an alignment this eomgen cannot give");
        table_ = &t;
        name = t.name;
        title = t.title;
        source = t.source;
        n_params = t.n_params;
        n_conserved = t.n_conserved;
        n_outputs = t.n_outputs;
        n_constraints = t.n_constraints;
        explicit_time = t.explicit_time;
        has_generalized_forces = t.has_generalized_forces;
        state_names.assign(t.state_names, t.state_names + 2 * t.nq);
        coordinate_names.assign(t.state_names, t.state_names + t.nq);
        param_names.assign(t.param_names, t.param_names + t.n_params);
        conserved_names.assign(t.conserved_names, t.conserved_names + t.n_conserved);
        output_names.assign(t.output_names, t.output_names + t.n_outputs);
        constraint_names.assign(t.constraint_names, t.constraint_names + t.n_constraints);
        constraint_is_holonomic.assign(t.constraint_is_holonomic, t.constraint_is_holonomic + t.n_constraints);
        n_switches = t.switching ? t.n_switches : 0;
        has_power = t.power != nullptr;
        switch_names.assign(t.switch_names, t.switch_names + n_switches);
        auto units = [](std::vector<const char*>& v, const char* const* from, int n) {
            if (from) v.assign(from, from + n);
            else v.assign(std::size_t(n), "");
        };
        energy_unit = t.energy_unit ? t.energy_unit : "";
        units(state_units, t.state_units, 2 * t.nq);
        units(param_units, t.param_units, t.n_params);
        units(conserved_units, t.conserved_units, t.n_conserved);
        units(output_units, t.output_units, t.n_outputs);
        units(multiplier_units, t.multiplier_units, t.n_constraints);
        units(param_declared_units, t.param_declared_units, t.n_params);
        units(coordinate_declared_units, t.coordinate_declared_units, t.nq);
    }

    static const ModelTable& table() {
        if (!table_) throw std::logic_error("TableModel used before bind()");
        return *table_;
    }
    static int dof() { return table().nq; }

    static bool set_param(Params& p, const std::string& name, double value) {
        return table().set_param(p.data(), name.c_str(), value);
    }
    static std::vector<double> param_values(const Params& p) {
        std::vector<double> v(std::size_t(table().n_params));
        table().param_values(p.data(), v.data());
        return v;
    }
    static State default_state() {
        State x(2 * dof());
        table().default_state(x.data());
        return x;
    }

    static void rhs(double t, const State& x, const Params& p, State& xdot) {
        xdot.resize(x.size());
        check(table().rhs(t, x.data(), p.data(), xdot.data()));
    }
    static double energy(double t, const Config& q, const Config& qd, const Params& p) {
        double h = 0;
        check(table().energy(t, q.data(), qd.data(), p.data(), &h));
        return h;
    }
    static void conserved(double t, const Config& q, const Config& qd, const Params& p, Conserved& out) {
        out.resize(n_conserved);
        check(table().conserved(t, q.data(), qd.data(), p.data(), out.data()));
    }
    static void outputs(double t, const Config& q, const Config& qd, const Params& p, Outputs& out) {
        out.resize(n_outputs);
        check(table().outputs(t, q.data(), qd.data(), p.data(), out.data()));
    }
    static double power(double t, const Config& q, const Config& qd, const Params& p) {
        double out = 0;
        if (!table().power) throw std::logic_error("the compiled model has no power()");
        check(table().power(t, q.data(), qd.data(), p.data(), &out));
        return out;
    }
    static void switching(double t, const Config& q, const Config& qd, const Params& p, Switches& out) {
        out.resize(n_switches);
        if (n_switches > 0) check(table().switching(t, q.data(), qd.data(), p.data(), out.data()));
    }
    static void mass_matrix(double t, const Config& q, const Params& p, MassMatrix& M) {
        M.resize(dof(), dof());
        check(table().mass_matrix(t, q.data(), p.data(), M.data()));
    }
    static void momenta(double t, const Config& q, const Config& qd, const Params& p, Config& out) {
        out.resize(dof());
        check(table().momenta(t, q.data(), qd.data(), p.data(), out.data()));
    }
    static void lagrangian_gradient(double t, const Config& q, const Config& qd, const Params& p, Config& out) {
        out.resize(dof());
        check(table().lagrangian_gradient(t, q.data(), qd.data(), p.data(), out.data()));
    }
    static void constraints(double t, const Config& q, const Config& qd, const Params& p, ConstraintJacobian& A,
                            ConstraintVector& gamma) {
        A.resize(n_constraints, dof());
        gamma.resize(n_constraints);
        if (n_constraints > 0) check(table().constraints(t, q.data(), qd.data(), p.data(), A.data(), gamma.data()));
    }
    static void constraint_residuals(double t, const Config& q, const Config& qd, const Params& p,
                                     ConstraintVector& g, ConstraintVector& c) {
        g.resize(n_constraints);
        c.resize(n_constraints);
        if (n_constraints > 0)
            check(table().constraint_residuals(t, q.data(), qd.data(), p.data(), g.data(), c.data()));
    }
    static void multipliers(double t, const State& x, const Params& p, ConstraintVector& lambda) {
        lambda.resize(n_constraints);
        if (n_constraints > 0) check(table().multipliers(t, x.data(), p.data(), lambda.data()));
    }

    /// J = ∂ẋ/∂x, computed in the shared object (model_jacobian.hpp asks for it by this name).
    static void jacobian(double t, const State& x, const Params& p, Eigen::MatrixXd& J) {
        if (!table().jacobian)
            throw std::logic_error("the compiled model has no Jacobian (model_table<M, true> compiles one)");
        J.resize(x.size(), x.size());
        check(table().jacobian(t, x.data(), p.data(), J.data()));
    }

    /// Yx = ∂y/∂x and Yp = ∂y/∂p of the declared outputs, computed in the shared object (sensitivities.hpp).
    static void output_jacobian(double t, const State& x, const Params& p, Eigen::MatrixXd& Yx, Eigen::MatrixXd& Yp) {
        if (!table().output_jacobian)
            throw std::logic_error("the compiled model has no Jacobians (model_table<M, true> compiles them)");
        Yx.resize(n_outputs, x.size());
        Yp.resize(n_outputs, n_params);
        if (n_outputs > 0) check(table().output_jacobian(t, x.data(), p.data(), Yx.data(), Yp.data()));
    }

    /// Lx = ∂λ/∂x and Lp = ∂λ/∂p of the multipliers, computed in the shared object (sensitivities.hpp).
    static void multiplier_jacobian(double t, const State& x, const Params& p, Eigen::MatrixXd& Lx,
                                    Eigen::MatrixXd& Lp) {
        Lx.resize(n_constraints, x.size());
        Lp.resize(n_constraints, n_params);
        if (n_constraints == 0) return;
        if (!table().multiplier_jacobian)
            throw std::logic_error("the compiled model has no Jacobians (model_table<M, true> compiles them)");
        check(table().multiplier_jacobian(t, x.data(), p.data(), Lx.data(), Lp.data()));
    }

    /// Rx = ∂(g, c)/∂x and Rp = ∂(g, c)/∂p of the constraint residuals, computed in the shared object
    /// (consistent_sensitivities.hpp).
    static void constraint_residual_jacobian(double t, const State& x, const Params& p, Eigen::MatrixXd& Rx,
                                             Eigen::MatrixXd& Rp) {
        Rx.resize(2 * n_constraints, x.size());
        Rp.resize(2 * n_constraints, n_params);
        if (n_constraints == 0) return;
        if (!table().constraint_residual_jacobian)
            throw std::logic_error("the compiled model has no Jacobians (model_table<M, true> compiles them)");
        check(table().constraint_residual_jacobian(t, x.data(), p.data(), Rx.data(), Rp.data()));
    }

    /// Sx = ∂s/∂x, Sp = ∂s/∂p and St = ∂s/∂t of the switching functions, computed in the shared object (saltation.hpp).
    static void switching_jacobian(double t, const State& x, const Params& p, Eigen::MatrixXd& Sx, Eigen::MatrixXd& Sp,
                                   Eigen::VectorXd& St) {
        Sx.resize(n_switches, x.size());
        Sp.resize(n_switches, n_params);
        St.resize(n_switches);
        if (n_switches == 0) return;
        if (!table().switching_jacobian)
            throw std::logic_error("the compiled model has no Jacobians (model_table<M, true> compiles them)");
        check(table().switching_jacobian(t, x.data(), p.data(), Sx.data(), Sp.data(), St.data()));
    }

    /// Px, Pp, Gx, Gp: the derivatives of the momenta and of ∂L/∂q by (q, q̇) and p, computed in the shared object
    /// (variational_sensitivities.hpp).
    static void lagrangian_jacobian(double t, const State& x, const Params& p, Eigen::MatrixXd& Px, Eigen::MatrixXd& Pp,
                                    Eigen::MatrixXd& Gx, Eigen::MatrixXd& Gp) {
        if (!table().lagrangian_jacobian)
            throw std::logic_error("the compiled model has no Jacobians (model_table<M, true> compiles them)");
        Px.resize(dof(), x.size());
        Gx.resize(dof(), x.size());
        Pp.resize(dof(), n_params);
        Gp.resize(dof(), n_params);
        check(table().lagrangian_jacobian(t, x.data(), p.data(), Px.data(), Pp.data(), Gx.data(), Gp.data()));
    }

    /// Jp = ∂ẋ/∂p (columns in param_names order), computed in the shared object (sensitivities.hpp asks for it).
    static void parameter_jacobian(double t, const State& x, const Params& p, Eigen::MatrixXd& Jp) {
        if (!table().parameter_jacobian)
            throw std::logic_error("the compiled model has no Jacobians (model_table<M, true> compiles them)");
        Jp.resize(x.size(), n_params);
        check(table().parameter_jacobian(t, x.data(), p.data(), Jp.data()));
    }

  private:
    static inline const ModelTable* table_ = nullptr;

    /// Rethrows what a table function caught, as the class it was.
    static void check(int status) {
        if (status == kTableOk) return;
        double t = 0;
        const std::string what = table().error_message(&t);
        switch (status) {
        case kTableSingularMassMatrix: throw SingularMassMatrix(what, t);
        case kTableNonFiniteState: throw NonFiniteState(what, t);
        case kTableSingularConstraints: throw SingularConstraints(what, t);
        case kTableSimulationError: throw SimulationError(what, t);
        default: throw std::runtime_error(what);
        }
    }
};

}  // namespace eomgen
