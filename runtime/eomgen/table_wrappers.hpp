/**
 * @file table_wrappers.hpp  The model's side of a ModelTable (model_table.hpp): each function of a generated model
 * as a plain function over arrays (matrices column-major) that catches every exception and returns its kind
 * (TableStatus), with the message and time kept per thread for error_message(). model_table<M>() gathers them.
 */
#pragma once

#include "eomgen/column_units.hpp"
#include "eomgen/errors.hpp"
#include "eomgen/linearize.hpp"
#include "eomgen/model_jacobian.hpp"
#include "eomgen/model_traits.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>

namespace eomgen {

/// What a table function reports: success, or which of the runtime's errors it caught.
enum TableStatus : int {
    kTableOk = 0,
    kTableSimulationError,
    kTableSingularMassMatrix,
    kTableNonFiniteState,
    kTableSingularConstraints,
    kTableOtherError,
};

namespace table_detail {

struct LastError {
    std::string message;
    double t = 0;
};
inline LastError& last_error() {
    thread_local LastError e;
    return e;
}

/// Runs f, turning what it throws into a TableStatus (the message kept for error_message()).
template <class F>
int guarded(F&& f) noexcept {
    auto keep = [](const char* what, double t, int status) {
        try {
            last_error().message = what;
            last_error().t = t;
        } catch (...) {
        }
        return status;
    };
    try {
        f();
        return kTableOk;
    } catch (const SingularMassMatrix& e) {
        return keep(e.what(), e.t(), kTableSingularMassMatrix);
    } catch (const NonFiniteState& e) {
        return keep(e.what(), e.t(), kTableNonFiniteState);
    } catch (const SingularConstraints& e) {
        return keep(e.what(), e.t(), kTableSingularConstraints);
    } catch (const SimulationError& e) {
        return keep(e.what(), e.t(), kTableSimulationError);
    } catch (const std::exception& e) {
        return keep(e.what(), 0, kTableOtherError);
    } catch (...) {
        return keep("unknown error", 0, kTableOtherError);
    }
}

template <class V>
V read(const double* a) {
    return Eigen::Map<const V>(a);
}
template <class V>
void write(const V& v, double* a) {
    Eigen::Map<V> out(a);
    out = v;
}

/// The table's functions for generated model M (Model<double>).
template <class M>
struct Wrappers {
    using Config = typename M::Config;
    using State = typename M::State;
    using Params = typename M::Params;
    static const Params& params(const void* p) { return *static_cast<const Params*>(p); }

    static void init_params(void* p) { new (p) Params(); }
    static bool set_param(void* p, const char* name, double value) {
        return M::set_param(*static_cast<Params*>(p), name, value);
    }
    static void param_values(const void* p, double* values) {
        const auto v = M::param_values(params(p));
        for (std::size_t i = 0; i < v.size(); ++i) values[i] = v[i];
    }
    static void default_state(double* x) { write<State>(M::default_state(), x); }
    static int rhs(double t, const double* x, const void* p, double* xdot) {
        return guarded([&] {
            State out;
            M::rhs(t, read<State>(x), params(p), out);
            write<State>(out, xdot);
        });
    }
    static int energy(double t, const double* q, const double* qd, const void* p, double* h) {
        return guarded([&] { *h = M::energy(t, read<Config>(q), read<Config>(qd), params(p)); });
    }
    static int conserved(double t, const double* q, const double* qd, const void* p, double* out) {
        return guarded([&] {
            typename M::Conserved c;
            M::conserved(t, read<Config>(q), read<Config>(qd), params(p), c);
            write(c, out);
        });
    }
    static int outputs(double t, const double* q, const double* qd, const void* p, double* out) {
        return guarded([&] {
            typename M::Outputs o;
            M::outputs(t, read<Config>(q), read<Config>(qd), params(p), o);
            write(o, out);
        });
    }
    static int power(double t, const double* q, const double* qd, const void* p, double* out) {
        return guarded([&] { *out = M::power(t, read<Config>(q), read<Config>(qd), params(p)); });
    }
    static int switching(double t, const double* q, const double* qd, const void* p, double* out) {
        return guarded([&] {
            typename M::Switches s;
            M::switching(t, read<Config>(q), read<Config>(qd), params(p), s);
            write(s, out);
        });
    }
    static int mass_matrix(double t, const double* q, const void* p, double* out) {
        return guarded([&] {
            typename M::MassMatrix m;
            M::mass_matrix(t, read<Config>(q), params(p), m);
            write(m, out);
        });
    }
    static int momenta(double t, const double* q, const double* qd, const void* p, double* out) {
        return guarded([&] {
            Config m;
            M::momenta(t, read<Config>(q), read<Config>(qd), params(p), m);
            write(m, out);
        });
    }
    static int lagrangian_gradient(double t, const double* q, const double* qd, const void* p, double* out) {
        return guarded([&] {
            Config g;
            M::lagrangian_gradient(t, read<Config>(q), read<Config>(qd), params(p), g);
            write(g, out);
        });
    }
    static int constraints(double t, const double* q, const double* qd, const void* p, double* A, double* gamma) {
        return guarded([&] {
            if constexpr (is_constrained<M>::value) {
                typename M::ConstraintJacobian a;
                typename M::ConstraintVector g;
                M::constraints(t, read<Config>(q), read<Config>(qd), params(p), a, g);
                write(a, A);
                write(g, gamma);
            }
        });
    }
    static int constraint_residuals(double t, const double* q, const double* qd, const void* p, double* g,
                                    double* c) {
        return guarded([&] {
            if constexpr (is_constrained<M>::value) {
                typename M::ConstraintVector position, velocity;
                M::constraint_residuals(t, read<Config>(q), read<Config>(qd), params(p), position, velocity);
                write(position, g);
                write(velocity, c);
            }
        });
    }
    static int multipliers(double t, const double* x, const void* p, double* lambda) {
        return guarded([&] {
            if constexpr (is_constrained<M>::value) {
                typename M::ConstraintVector l;
                M::multipliers(t, read<State>(x), params(p), l);
                write(l, lambda);
            }
        });
    }
    // J and Jp: the header's analytic ones where it has them, else both from one forward differentiation
    // (linearize(), one instantiation of the model's template for the two).
    static int jacobian(double t, const double* x, const void* p, double* J) {
        return guarded([&] {
            Eigen::Matrix<double, M::nx, M::nx> j;
            if constexpr (has_analytic_jacobian<M>::value) {
                M::state_jacobian(t, read<State>(x), params(p), j);
            } else {
                Eigen::Matrix<double, M::nx, M::n_params> jp;
                linearize<detail::model_template<M>::template type>(t, read<State>(x), params(p), j, jp);
            }
            write(j, J);
        });
    }
    static int parameter_jacobian(double t, const double* x, const void* p, double* Jp) {
        return guarded([&] {
            Eigen::Matrix<double, M::nx, M::n_params> jp;
            if constexpr (has_parameter_jacobian<M>::value) {
                M::parameter_jacobian(t, read<State>(x), params(p), jp);
            } else {
                Eigen::Matrix<double, M::nx, M::nx> j;
                linearize<detail::model_template<M>::template type>(t, read<State>(x), params(p), j, jp);
            }
            write(jp, Jp);
        });
    }
    static int output_jacobian(double t, const double* x, const void* p, double* Yx, double* Yp) {
        return guarded([&] {
            Eigen::Matrix<double, M::n_outputs, M::nx> yx;
            Eigen::Matrix<double, M::n_outputs, M::n_params> yp;
            linearize_outputs<detail::model_template<M>::template type>(t, read<State>(x), params(p), yx, yp);
            write(yx, Yx);
            write(yp, Yp);
        });
    }
    static int multiplier_jacobian(double t, const double* x, const void* p, double* Lx, double* Lp) {
        return guarded([&] {
            if constexpr (is_constrained<M>::value) {
                Eigen::Matrix<double, M::n_constraints, M::nx> lx;
                Eigen::Matrix<double, M::n_constraints, M::n_params> lp;
                linearize_multipliers<detail::model_template<M>::template type>(t, read<State>(x), params(p), lx, lp);
                write(lx, Lx);
                write(lp, Lp);
            }
        });
    }
    static int constraint_residual_jacobian(double t, const double* x, const void* p, double* Rx, double* Rp) {
        return guarded([&] {
            if constexpr (is_constrained<M>::value) {
                Eigen::Matrix<double, 2 * M::n_constraints, M::nx> rx;
                Eigen::Matrix<double, 2 * M::n_constraints, M::n_params> rp;
                linearize_constraint_residuals<detail::model_template<M>::template type>(t, read<State>(x), params(p),
                                                                                        rx, rp);
                write(rx, Rx);
                write(rp, Rp);
            }
        });
    }
    static int switching_jacobian(double t, const double* x, const void* p, double* Sx, double* Sp, double* St) {
        return guarded([&] {
            if constexpr (has_switching<M>::value) {
                Eigen::Matrix<double, M::n_switches, M::nx> sx;
                Eigen::Matrix<double, M::n_switches, M::n_params> sp;
                Eigen::Matrix<double, M::n_switches, 1> st;
                linearize_switching<detail::model_template<M>::template type>(t, read<State>(x), params(p), sx, sp, st);
                write(sx, Sx);
                write(sp, Sp);
                write(st, St);
            }
        });
    }
    static int lagrangian_jacobian(double t, const double* x, const void* p, double* Px, double* Pp, double* Gx,
                                   double* Gp) {
        return guarded([&] {
            Eigen::Matrix<double, M::nq, M::nx> px, gx;
            Eigen::Matrix<double, M::nq, M::n_params> pp, gp;
            linearize_lagrangian<detail::model_template<M>::template type>(t, read<State>(x), params(p), px, pp, gx, gp);
            write(px, Px);
            write(pp, Pp);
            write(gx, Gx);
            write(gp, Gp);
        });
    }
    static const char* error_message(double* t) {
        if (t) *t = last_error().t;
        return last_error().message.c_str();
    }
};

}  // namespace table_detail

}  // namespace eomgen
