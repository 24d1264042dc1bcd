/**
 * @file sensitivities.hpp  Forward sensitivities of a model's trajectory, S(t) = ∂x(t)/∂(p_k, x0_i), integrated
 * with the state: the variational equations
 *
 *     Ṡ = J(t, x) S + Jp(t, x),    J = ∂ẋ/∂x,  Jp = ∂ẋ/∂p (the selected parameters' columns; 0 for x0's),
 *     S(t0) = [0 … 0 | e_i …]      (a parameter's column starts at 0, an initial value's at its unit vector),
 *
 * as one augmented system z = [x, vec(S)] under one error control (state and sensitivities, as CVODES's
 * errconS = true), by any adaptive method of integrate_with (Dopri5, Dop853, Adams) or by Radau5 (its Newton
 * matrix block-diagonal, I − hγ diag(J, …, J): the coupling ∂(J S)/∂x is left out of the iteration matrix only,
 * which slows Newton's convergence a little and changes nothing of the result's accuracy).
 *
 *     std::vector<eomgen::SensitivityColumn> cols{eomgen::parameter_column(M::param_names, "theta"),
 *                                                 eomgen::initial_column(M::state_names, "psi")};
 *     auto r = eomgen::integrate_sensitivities<M>(params, 0.0, x0, 3.0, cols, opts, events, sample_times);
 *     r.S            // nx × 2: ∂x(3)/∂θ and ∂x(3)/∂ψ0
 *     r.events[0].dt // ∂t⁎/∂θ, ∂t⁎/∂ψ0 of a terminal event, −(g_x S + g_p)/(g_t + g_x ẋ) at t*
 *
 * Each sample also carries the declared outputs y ([outputs] of the model file) and their sensitivities
 * Yx S + Yp, and a constrained model's multipliers λ and theirs, Lx S + Lp, each by forward differentiation.
 *
 * J and Jp are exact: a generated unconstrained model with analytic Jacobians ([generate] jacobians = true)
 * gives them (state_jacobian, parameter_jacobian); a compiled table (eomgen run) gives its own; any other generated
 * model is differentiated forward through its rhs() (linearize.hpp), constrained solve included.
 *
 * A constrained model integrates its index-1 equations without projection; S starts on the tangent of the
 * constraint manifold (consistent_sensitivities.hpp: a changed initial value or a parameter the constraints contain
 * moves the start as --project-initial would move it), and the linearized constraints then hold along the motion.
 * Its x0 must be consistent (InconsistentInitialConditions otherwise). Where a motion crosses a switching surface
 * (abs, sign, … in the model file) S jumps by the saltation matrix (saltation.hpp); a motion that slides along one
 * (sticks) is followed with its own variational equations by the adaptive methods (sliding_sensitivities.hpp), a
 * constrained model's too (its one-sided fields and Jacobians are those of the constrained solve).
 */
#pragma once

#include "eomgen/consistent_sensitivities.hpp"
#include "eomgen/constraints.hpp"
#include "eomgen/errors.hpp"
#include "eomgen/grazing.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/linearize.hpp"
#include "eomgen/model_jacobian.hpp"
#include "eomgen/model_traits.hpp"
#include "eomgen/radau5.hpp"
#include "eomgen/saltation.hpp"
#include "eomgen/sensitivity_types.hpp"
#include "eomgen/sliding_sensitivities.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace eomgen {

namespace detail {

template <class M, class = void>
struct has_multiplier_jacobian : std::false_type {};
template <class M>
struct has_multiplier_jacobian<M, std::void_t<decltype(M::multiplier_jacobian(
                                      0.0, std::declval<const typename M::State&>(),
                                      std::declval<const typename M::Params&>(), std::declval<Eigen::MatrixXd&>(),
                                      std::declval<Eigen::MatrixXd&>()))>> : std::true_type {};

template <class M, class = void>
struct has_output_jacobian : std::false_type {};
template <class M>
struct has_output_jacobian<M, std::void_t<decltype(M::output_jacobian(
                                  0.0, std::declval<const typename M::State&>(), std::declval<const typename M::Params&>(),
                                  std::declval<Eigen::MatrixXd&>(), std::declval<Eigen::MatrixXd&>()))>>
    : std::true_type {};

/// The model's state type from a dynamic vector (a generated model's State has a fixed size).
template <class M>
typename M::State model_state(const Eigen::VectorXd& x) {
    return typename M::State(x);
}

}  // namespace detail

/**
 * J = ∂ẋ/∂x and Jp = ∂ẋ/∂p (all parameters, param_names order) of Model M at (t, x; p): M's own
 * parameter_jacobian with model_jacobian where M has one (a compiled table, an unconstrained generated model
 * with analytic Jacobians), else both by one forward differentiation of M's template (linearize()).
 */
template <class M>
void sensitivity_jacobians(double t, const typename M::State& x, const typename M::Params& p, Eigen::MatrixXd& J,
                           Eigen::MatrixXd& Jp) {
    if constexpr (has_parameter_jacobian<M>::value) {
        model_jacobian<M>(t, x, p, J);
        M::parameter_jacobian(t, x, p, Jp);
    } else {
        linearize<detail::model_template<M>::template type>(t, x, p, J, Jp);
    }
}

/// Yx = ∂y/∂x and Yp = ∂y/∂p of Model M's declared outputs at (t, x; p): M's own where it has them (a compiled
/// table), else by forward differentiation of M's template (linearize_outputs()).
template <class M>
void output_jacobians(double t, const typename M::State& x, const typename M::Params& p, Eigen::MatrixXd& Yx,
                      Eigen::MatrixXd& Yp) {
    if constexpr (detail::has_output_jacobian<M>::value)
        M::output_jacobian(t, x, p, Yx, Yp);
    else
        linearize_outputs<detail::model_template<M>::template type>(t, x, p, Yx, Yp);
}

/**
 * The augmented right-hand side z' = [ẋ, vec(J S + Jp_sel)] of Model M with parameters p and the given columns;
 * also the Newton matrix's approximation diag(J, …, J) for Radau5.
 */
template <class M>
class SensitivitySystem {
  public:
    SensitivitySystem(const typename M::Params& p, Eigen::Index nx, std::vector<SensitivityColumn> columns)
        : p_(p), nx_(nx), columns_(std::move(columns)) {}

    Eigen::Index nx() const { return nx_; }
    Eigen::Index size() const { return nx_ * (1 + Eigen::Index(columns_.size())); }
    std::size_t jacobian_evaluations() const { return jacobian_evaluations_; }

    void operator()(const double& t, const Eigen::VectorXd& z, Eigen::VectorXd& zdot) {
        const Eigen::Index k = Eigen::Index(columns_.size());
        const typename M::State x = detail::model_state<M>(z.head(nx_));
        typename M::State xdot = x;
        M::rhs(t, x, p_, xdot);
        sensitivity_jacobians<M>(t, x, p_, J_, Jp_);
        ++jacobian_evaluations_;
        zdot.resize(z.size());
        zdot.head(nx_) = xdot;
        const Eigen::Map<const Eigen::MatrixXd> S(z.data() + nx_, nx_, k);
        Eigen::Map<Eigen::MatrixXd> Sdot(zdot.data() + nx_, nx_, k);
        Sdot.noalias() = J_ * S;
        for (Eigen::Index c = 0; c < k; ++c)
            if (columns_[std::size_t(c)].kind == SensitivityColumn::Kind::Parameter)
                Sdot.col(c) += Jp_.col(columns_[std::size_t(c)].index);
        if (!zdot.allFinite())
            throw NonFiniteState(describe_state("the sensitivities are not finite", t, x), t);
    }

    /// diag(J, …, J) at (t, x(z)): Radau5's Newton matrix.
    void newton_jacobian(const double& t, const Eigen::VectorXd& z, Eigen::MatrixXd& Jz) {
        const typename M::State x = detail::model_state<M>(z.head(nx_));
        Eigen::MatrixXd J;
        model_jacobian<M>(t, x, p_, J);
        Jz.setZero(z.size(), z.size());
        for (Eigen::Index b = 0; b <= Eigen::Index(columns_.size()); ++b) Jz.block(b * nx_, b * nx_, nx_, nx_) = J;
    }

    /// A constrained model's multipliers λ at a sample and their sensitivities Lx S + Lp.
    void multipliers(SensitivitySample& s) const {
        if constexpr (is_constrained<M>::value) {
            if (M::n_constraints == 0) return;
            const typename M::State x = detail::model_state<M>(s.x);
            typename M::ConstraintVector lambda;
            M::multipliers(s.t, x, p_, lambda);
            s.lambda = lambda;
            Eigen::MatrixXd Lx, Lp;
            if constexpr (detail::has_multiplier_jacobian<M>::value)
                M::multiplier_jacobian(s.t, x, p_, Lx, Lp);
            else
                linearize_multipliers<detail::model_template<M>::template type>(s.t, x, p_, Lx, Lp);
            s.L = with_parameters(Lx * s.S, Lp);
        }
    }

    /// The declared outputs y at a sample and their sensitivities Yx S + Yp (the parameters' columns of Yp).
    void outputs(SensitivitySample& s) const {
        if (M::n_outputs == 0) return;
        const typename M::State x = detail::model_state<M>(s.x);
        typename M::Outputs y;
        M::outputs(s.t, positions<M::nq>(x), velocities<M::nq>(x), p_, y);
        s.y = y;
        Eigen::MatrixXd Yx, Yp;
        output_jacobians<M>(s.t, x, p_, Yx, Yp);
        s.Y = with_parameters(Yx * s.S, Yp);
    }

    /// ẋ at (t, x).
    Eigen::VectorXd state_rate(double t, const Eigen::VectorXd& x) const {
        const typename M::State xs = detail::model_state<M>(x);
        typename M::State xdot = xs;
        M::rhs(t, xs, p_, xdot);
        return Eigen::VectorXd(xdot);
    }

  private:
    /// D plus, in each parameter's column, that parameter's column of the explicit derivative E.
    Eigen::MatrixXd with_parameters(Eigen::MatrixXd D, const Eigen::MatrixXd& E) const {
        for (std::size_t c = 0; c < columns_.size(); ++c)
            if (columns_[c].kind == SensitivityColumn::Kind::Parameter)
                D.col(Eigen::Index(c)) += E.col(columns_[c].index);
        return D;
    }

    typename M::Params p_;
    Eigen::Index nx_;
    std::vector<SensitivityColumn> columns_;
    Eigen::MatrixXd J_, Jp_;
    std::size_t jacobian_evaluations_ = 0;
};

/// g_t and g_x of event e at (t, x): its gradient where given, else central differences.
inline void event_gradient(const SensitivityEvent& e, double t, const Eigen::VectorXd& x, double& g_t,
                           Eigen::RowVectorXd& g_x) {
    if (e.gradient) {
        e.gradient(t, x, g_t, g_x);
        return;
    }
    const auto step = [](double v) { return 1e-5 * std::max(1.0, std::abs(v)); };
    const double ht = step(t);
    g_t = (e.event.g(t + ht, x) - e.event.g(t - ht, x)) / (2 * ht);
    g_x.resize(x.size());
    Eigen::VectorXd xp = x, xm = x;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
        const double h = step(x(i));
        xp(i) = x(i) + h;
        xm(i) = x(i) - h;
        g_x(i) = (e.event.g(t, xp) - e.event.g(t, xm)) / (2 * h);
        xp(i) = xm(i) = x(i);
    }
}

/// Checks that each column names a parameter or a state of M (std::invalid_argument otherwise).
template <class M>
void check_sensitivity_columns([[maybe_unused]] double t0, const typename M::State& x0,
                               [[maybe_unused]] const typename M::Params& p,
                               const std::vector<SensitivityColumn>& columns) {
    const Eigen::Index nx = x0.size();
    for (const SensitivityColumn& c : columns) {
        const bool parameter = c.kind == SensitivityColumn::Kind::Parameter;
        if (c.index < 0 || c.index >= (parameter ? Eigen::Index(M::param_names.size()) : nx))
            throw std::invalid_argument("integrate_sensitivities: a column's index is out of range");
    }
}

/**
 * Integrates Model M from (t0, x0) to t_end with the sensitivities of the given columns, by the adaptive
 * method Method (Dopri5, Dop853, Adams) with `options`, stopping at a terminal event. Samples (state and S) at
 * `sample_times`; every located event with ∂t⁎/∂(columns). Throws std::invalid_argument for what is refused (see
 * the file's comment) and the runtime's SimulationError when the integration fails.
 */
template <class M, template <class> class Method = Dop853>
SensitivityResult integrate_sensitivities(const typename M::Params& p, double t0, const typename M::State& x0,
                                          double t_end, const std::vector<SensitivityColumn>& columns,
                                          const typename Method<Eigen::VectorXd>::Options& options = {},
                                          const std::vector<SensitivityEvent>& events = {},
                                          const std::vector<double>& sample_times = {});

/// The same by Radau5 (implicit), with the block-diagonal Newton matrix diag(J, …, J).
template <class M>
SensitivityResult integrate_sensitivities_radau5(const typename M::Params& p, double t0, const typename M::State& x0,
                                                 double t_end, const std::vector<SensitivityColumn>& columns,
                                                 const Radau5Options<double>& options = {},
                                                 const std::vector<SensitivityEvent>& events = {},
                                                 const std::vector<double>& sample_times = {});

/**
 * The same by classic RK4 on the fixed grid t0 + k·dt (integrate_rk4). RK4 applied to the augmented system is the
 * exact derivative of RK4's own discrete motion (the variational equations of a Runge–Kutta step are that step of the
 * variational equations), so S is the sensitivity of the numbers the run gives, whatever dt; the jumps at switching
 * surfaces need steps that end there, which RK4's do not (std::invalid_argument for a model with switches).
 */
template <class M>
SensitivityResult integrate_sensitivities_rk4(const typename M::Params& p, double t0, const typename M::State& x0,
                                              double t_end, double dt, const std::vector<SensitivityColumn>& columns,
                                              const std::vector<SensitivityEvent>& events = {},
                                              const std::vector<double>& sample_times = {});

namespace detail {

/// The augmented right-hand side and Radau5's Newton matrix behind function types that do not name the model: each
/// method's integration of an Eigen::VectorXd is then compiled once per file, whatever the models whose
/// sensitivities the file integrates (a call through std::function costs nothing beside J S).
using AugmentedRhs = std::function<void(const double&, const Eigen::VectorXd&, Eigen::VectorXd&)>;
using AugmentedJacobian = std::function<void(const double&, const Eigen::VectorXd&, Eigen::MatrixXd&)>;

/// The augmented system's start, its events, and the result from the augmented run's.
template <class M>
struct SensitivityRun {
    SensitivitySystem<M> system;
    std::vector<SensitivityEvent> events;
    Eigen::VectorXd z0;
    std::vector<Event<Eigen::VectorXd>> augmented_events;
    std::vector<SensitivitySample> samples;
    /// For a model with switching surfaces: the sliding along each (sliding_sensitivities.hpp), whose
    /// Switch events are the last of augmented_events; and the touches that cross nothing (grazing.hpp), within the
    /// resolution of the run's tolerances (set by the caller that has them).
    std::vector<std::shared_ptr<const SlidingVariations>> sliding;
    GrazeWatch<M> grazing;
    double rtol = 0, atol = 0;

    SensitivityRun(const typename M::Params& p, double t0, const typename M::State& x0,
                   const std::vector<SensitivityColumn>& columns, const std::vector<SensitivityEvent>& given)
        : system(p, x0.size(), columns), events(given), grazing(p, x0.size()) {
        check_sensitivity_columns<M>(t0, x0, p, columns);
        if constexpr (is_constrained<M>::value)
            if (M::n_constraints > 0) check_consistent<M>(t0, x0, p);
        const Eigen::Index nx = x0.size(), k = Eigen::Index(columns.size());
        z0 = Eigen::VectorXd::Zero(system.size());
        z0.head(nx) = x0;
        Eigen::MatrixXd S0 = Eigen::MatrixXd::Zero(nx, k);
        std::vector<int> parameter_of;
        for (Eigen::Index c = 0; c < k; ++c) {
            const SensitivityColumn& column = columns[std::size_t(c)];
            const bool initial = column.kind == SensitivityColumn::Kind::InitialValue;
            if (initial) S0(column.index, c) = 1;
            parameter_of.push_back(initial ? -1 : column.index);
        }
        consistent_sensitivity_start<M>(t0, x0, p, parameter_of, S0);
        z0.tail(nx * k) = Eigen::Map<const Eigen::VectorXd>(S0.data(), nx * k);
        for (const SensitivityEvent& e : events)
            augmented_events.push_back({e.event.name,
                                        [g = e.event.g, nx](const double& t, const Eigen::VectorXd& z) {
                                            return g(t, Eigen::VectorXd(z.head(nx)));
                                        },
                                        e.event.direction, e.event.action});
        // Each switching surface ends the steps where the motion crosses it, and S jumps there (saltation.hpp).
        if constexpr (has_switching<M>::value) {
            for (Event<Eigen::VectorXd>& e : grazing.events()) augmented_events.push_back(std::move(e));
            const bool follows = true;  // as a plain run: the one-sided fields and Jacobians are the constrained ones
            const auto given_values = M::param_values(p);
            Eigen::VectorXd values(Eigen::Index(M::param_names.size()));
            for (std::size_t l = 0; l < M::param_names.size(); ++l) values(Eigen::Index(l)) = given_values[l];
            for (int s = 0; s < M::n_switches && follows; ++s)
                sliding.push_back(std::make_shared<const SlidingVariations>(
                    [p](double t, const Eigen::VectorXd& x, Eigen::VectorXd& f, Eigen::MatrixXd* J,
                        Eigen::MatrixXd* Jp) {
                        const typename M::State xs = detail::model_state<M>(x);
                        typename M::State xdot = xs;
                        M::rhs(t, xs, p, xdot);
                        f = xdot;
                        if (J) sensitivity_jacobians<M>(t, xs, p, *J, *Jp);
                    },
                    [p, s](double t, const Eigen::VectorXd& x, const Eigen::VectorXd& pv) {
                        typename M::Params q = p;
                        for (std::size_t l = 0; l < M::param_names.size(); ++l)
                            M::set_param(q, M::param_names[l], pv(Eigen::Index(l)));
                        Eigen::MatrixXd Sx, Sp;
                        Eigen::VectorXd St;
                        switching_jacobians<M>(t, detail::model_state<M>(x), q, Sx, Sp, St);
                        return SurfaceDerivatives{Sx.row(s), Sp.row(s), St(s)};
                    },
                    values, parameter_of, nx));
            for (int s = 0; s < M::n_switches; ++s) {
                Event<Eigen::VectorXd> e{M::switch_names[std::size_t(s)],
                                         [p, s, nx](const double& t, const Eigen::VectorXd& z) {
                                             const typename M::State x = detail::model_state<M>(z.head(nx));
                                             typename M::Switches values;
                                             M::switching(t, positions<M::nq>(x), velocities<M::nq>(x), p, values);
                                             return double(values(s));
                                         },
                                         EventDirection::Both, EventAction::Switch};
                // A surface that holds the motion (sticking) ends the run: finish() refuses it there.
                const auto surface = std::make_shared<SlidingSurface<Eigen::VectorXd>>(
                    [p](const double& t, const Eigen::VectorXd& x, Eigen::VectorXd& xdot) {
                        const typename M::State xs = detail::model_state<M>(x);
                        typename M::State f = xs;
                        M::rhs(t, xs, p, f);
                        xdot = f;
                    },
                    [g = e.g](const double& t, const Eigen::VectorXd& x) { return g(t, x); });  // g reads x only
                e.stop_at_switch = [surface, nx](const double& t, const Eigen::VectorXd& z) {
                    return surface->attracting(t, Eigen::VectorXd(z.head(nx)));
                };
                e.jump = [saltation = Saltation<M>(p, s, parameter_of, follows), nx](const double& t,
                                                                                     Eigen::VectorXd& z) {
                    Eigen::Map<Eigen::MatrixXd> S(z.data() + nx, nx, (z.size() - nx) / nx);
                    Eigen::MatrixXd jumped = S;
                    saltation.apply(t, Eigen::VectorXd(z.head(nx)), jumped);
                    S = jumped;
                };
                augmented_events.push_back(std::move(e));
            }
        }
    }

    /// The system's right-hand side as an AugmentedRhs (the run must outlive it).
    AugmentedRhs rhs() {
        return [this](const double& t, const Eigen::VectorXd& z, Eigen::VectorXd& zdot) { system(t, z, zdot); };
    }

    Observer<Eigen::VectorXd> observer() {
        return [this](const double& t, const Eigen::VectorXd& z) { samples.push_back(split(t, z)); };
    }

    SensitivitySample split(double t, const Eigen::VectorXd& z) const {
        const Eigen::Index nx = system.nx();
        return {t, z.head(nx), Eigen::Map<const Eigen::MatrixXd>(z.data() + nx, nx, (z.size() - nx) / nx), {}, {}};
    }

    SensitivityResult finish(const IntegrationResult<Eigen::VectorXd>& r) {
        SensitivityResult out;
        const SensitivitySample end = split(r.t, r.x);
        out.t = r.t;
        out.x = end.x;
        out.S = end.S;
        out.samples = std::move(samples);
        for (SensitivitySample& s : out.samples) {
            system.outputs(s);
            system.multipliers(s);
        }
        out.end = end;
        system.outputs(out.end);
        system.multipliers(out.end);
        for (const auto& hit : r.switches) out.switches.emplace_back(hit.name, hit.t);
        const auto given = [&](const std::string& name) {
            return std::any_of(events.begin(), events.end(), [&](const SensitivityEvent& e) { return e.event.name == name; });
        };
        if (r.stop_reason == StopReason::TerminalEvent && !given(r.stopped_by)) {
            std::ostringstream os;
            os.precision(15);
            os << "the motion sticks on the switching surface " << r.stopped_by << " = 0 at t = " << r.t
               << " (both sides of its jump push into it, as static friction holds a door): this method does not "
                  "follow the sensitivities of a motion that slides along a surface; dopri5, dop853 and adams do";
            throw SimulationError(os.str(), r.t);
        }
        out.stop_reason = r.stop_reason;
        out.stopped_by = r.stopped_by;
        out.accepted_steps = r.accepted_steps;
        out.rejected_steps = r.rejected_steps;
        out.rhs_evaluations = r.rhs_evaluations;
        out.jacobian_evaluations = system.jacobian_evaluations();
        if constexpr (has_switching<M>::value)
            for (auto& graze : grazing.grazes(r.events, rtol, atol)) out.switches.push_back(std::move(graze));
        for (const auto& hit : r.events) {
            if (!given(hit.name)) {  // where sliding began or ended ("…: slides", "…: leaves to s > 0")
                if (!is_touch_event(hit.name)) out.switches.emplace_back(hit.name, hit.t);
                continue;
            }
            const SensitivitySample s = split(hit.t, hit.x);
            const auto it = std::find_if(events.begin(), events.end(),
                                         [&](const SensitivityEvent& e) { return e.event.name == hit.name; });
            SensitivityEventHit h{hit.name, hit.t, s.x, s.S, {}, {}};
            double g_t = 0;
            Eigen::RowVectorXd g_x;
            event_gradient(*it, hit.t, s.x, g_t, g_x);
            const Eigen::VectorXd xdot = system.state_rate(hit.t, s.x);
            const double rate = g_t + g_x.dot(xdot);
            // A grazing crossing (ġ = 0) has no derivative of its time: NaN says so rather than a huge number.
            h.dt = rate != 0 ? Eigen::RowVectorXd(-(g_x * s.S) / rate)
                             : Eigen::RowVectorXd::Constant(s.S.cols(), std::numeric_limits<double>::quiet_NaN());
            h.dx = s.S + xdot * h.dt;
            out.events.push_back(std::move(h));
        }
        std::stable_sort(out.switches.begin(), out.switches.end(),
                         [](const auto& a, const auto& b) { return a.second < b.second; });
        return out;
    }
};

}  // namespace detail

template <class M, template <class> class Method>
SensitivityResult integrate_sensitivities(const typename M::Params& p, double t0, const typename M::State& x0,
                                          double t_end, const std::vector<SensitivityColumn>& columns,
                                          const typename Method<Eigen::VectorXd>::Options& options,
                                          const std::vector<SensitivityEvent>& events,
                                          const std::vector<double>& sample_times) {
    detail::SensitivityRun<M> run(p, t0, x0, columns, events);
    run.rtol = options.rtol;
    run.atol = options.atol;
    detail::AugmentedRhs f = run.rhs();
    if (run.sliding.empty())
        return run.finish(integrate_with<Method>(f, t0, run.z0, t_end, options, run.augmented_events, sample_times,
                                                 run.observer()));
    std::vector<std::string> names;
    for (const Event<Eigen::VectorXd>& e : run.augmented_events) names.push_back(e.name);
    SlidingRules<Eigen::VectorXd> rules =
        sliding_sensitivity_rules(run.sliding, run.augmented_events.size() - run.sliding.size(),
                                  run.augmented_events.size(), names, x0.size());
    for (const std::string& name : names) rules.idle_while_sliding.push_back(is_touch_event(name));
    return run.finish(integrate_sliding_with<Method>(f, t0, run.z0, t_end, options, run.augmented_events, rules,
                                                     sample_times, run.observer()));
}

template <class M>
SensitivityResult integrate_sensitivities_rk4(const typename M::Params& p, double t0, const typename M::State& x0,
                                              double t_end, double dt, const std::vector<SensitivityColumn>& columns,
                                              const std::vector<SensitivityEvent>& events,
                                              const std::vector<double>& sample_times) {
    if constexpr (has_switching<M>::value)
        if (M::n_switches > 0)
            throw std::invalid_argument(std::string(M::name) +
                                        " has switching surfaces, where the sensitivities jump: rk4's fixed steps do "
                                        "not end there; use dopri5, dop853 or adams");
    detail::SensitivityRun<M> run(p, t0, x0, columns, events);
    detail::AugmentedRhs f = run.rhs();
    const auto r = integrate_rk4(f, t0, run.z0, t_end, dt, run.augmented_events, sample_times, run.observer());
    return run.finish(r);
}

template <class M>
SensitivityResult integrate_sensitivities_radau5(const typename M::Params& p, double t0, const typename M::State& x0,
                                                 double t_end, const std::vector<SensitivityColumn>& columns,
                                                 const Radau5Options<double>& options,
                                                 const std::vector<SensitivityEvent>& events,
                                                 const std::vector<double>& sample_times) {
    if constexpr (has_switching<M>::value)
        if (M::n_switches > 0)
            throw std::invalid_argument(std::string(M::name) +
                                        " has switching surfaces, where the sensitivities jump: radau5 does not end its "
                                        "steps there; use dopri5, dop853 or adams");
    detail::SensitivityRun<M> run(p, t0, x0, columns, events);
    detail::AugmentedRhs f = run.rhs();
    detail::AugmentedJacobian jac = [&run](const double& t, const Eigen::VectorXd& z, Eigen::MatrixXd& J) {
        run.system.newton_jacobian(t, z, J);
    };
    const auto r = integrate_radau5(f, jac, t0, run.z0, t_end, options, run.augmented_events, sample_times,
                                    run.observer());
    return run.finish(r);
}

}  // namespace eomgen
