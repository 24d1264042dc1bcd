/**
 * @file variational_sensitivities.hpp  S = ∂x/∂(p, x₀) beside the variational integrator's motion (symplectic.hpp):
 * the exact derivative of its discrete map, so that S is the sensitivity of the numbers the run gives, whatever dt.
 *
 * A step of the midpoint rule solves R(v) = P(t_m, q_m, v) − (h/2) G(t_m, q_m, v) − p_k = 0 for the midpoint
 * velocity v (q_m = q_k + (h/2) v, P = ∂L/∂q̇, G = ∂L/∂q), then q_{k+1} = q_k + h v and p_{k+1} = P + (h/2) G. With
 * Px = [P_q P_v], Pp and Gx = [G_q G_v], Gp at (t_m, q_m, v), the implicit function theorem gives, column by column
 * (δθ the column's unit parameter, 0 for an initial value),
 *
 *     (h/2 B + P_v − h/2 G_v) δv = δp_k − B δq_k − (P_p − h/2 G_p) δθ,     B = P_q − h/2 G_q,
 *     δq_{k+1} = δq_k + h δv,   δp_{k+1} = (P_q + h/2 G_q)(δq_k + h/2 δv) + (P_v + h/2 G_v) δv + (P_p + h/2 G_p) δθ,
 *
 * one evaluation of the Lagrangian's derivatives and one LU of an n × n matrix per step, whatever the columns. The
 * velocity at a node is the inverse Legendre map of (q_k, p_k), so there δq̇ = P_v⁻¹(δp − P_q δq − P_p δθ). The
 * derivatives are the model's own (a compiled table's `lagrangian_jacobian`) or forward differentiation of its
 * template (linearize_lagrangian), never differences.
 */
#pragma once

#include "eomgen/errors.hpp"
#include "eomgen/linearize.hpp"
#include "eomgen/model_jacobian.hpp"
#include "eomgen/model_traits.hpp"
#include "eomgen/sensitivities.hpp"
#include "eomgen/symplectic.hpp"

#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace eomgen {

namespace detail {

template <class M, class = void>
struct has_lagrangian_jacobian : std::false_type {};
template <class M>
struct has_lagrangian_jacobian<M, std::void_t<decltype(M::lagrangian_jacobian(
                                      0.0, std::declval<const typename M::State&>(),
                                      std::declval<const typename M::Params&>(), std::declval<Eigen::MatrixXd&>(),
                                      std::declval<Eigen::MatrixXd&>(), std::declval<Eigen::MatrixXd&>(),
                                      std::declval<Eigen::MatrixXd&>()))>> : std::true_type {};

}  // namespace detail

/// Px = ∂P/∂x, Pp = ∂P/∂p of the momenta P = ∂L/∂q̇ and Gx, Gp of G = ∂L/∂q at (t, x = (q, q̇); p): Model M's own
/// where it has them (a compiled table), else forward differentiation of M's template.
template <class M>
void lagrangian_jacobians(double t, const typename M::State& x, const typename M::Params& p, Eigen::MatrixXd& Px,
                          Eigen::MatrixXd& Pp, Eigen::MatrixXd& Gx, Eigen::MatrixXd& Gp) {
    if constexpr (detail::has_lagrangian_jacobian<M>::value)
        M::lagrangian_jacobian(t, x, p, Px, Pp, Gx, Gp);
    else
        linearize_lagrangian<detail::model_template<M>::template type>(t, x, p, Px, Pp, Gx, Gp);
}

namespace detail {

/// The parameters' columns of D (n × n_params) in the order of `columns`, zero for an initial value's.
inline Eigen::MatrixXd selected_parameters(const Eigen::MatrixXd& D, const std::vector<SensitivityColumn>& columns) {
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(D.rows(), Eigen::Index(columns.size()));
    for (std::size_t c = 0; c < columns.size(); ++c)
        if (columns[c].kind == SensitivityColumn::Kind::Parameter) out.col(Eigen::Index(c)) = D.col(columns[c].index);
    return out;
}

/// The state (q, q̇) of a node (t, q, p) of the variational integrator and S = ∂(q, q̇)/∂(columns) from Sq, Sp.
template <class M>
SensitivitySample variational_node(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                                   const Eigen::MatrixXd& Sq, const Eigen::MatrixXd& Sp, const typename M::Params& params,
                                   const std::vector<SensitivityColumn>& columns) {
    const Eigen::Index n = q.size();
    SensitivitySample s;
    s.t = t;
    s.x.resize(2 * n);
    s.x << q, qd;
    Eigen::MatrixXd Px, Pp, Gx, Gp;
    lagrangian_jacobians<M>(t, model_state<M>(s.x), params, Px, Pp, Gx, Gp);
    const Eigen::PartialPivLU<Eigen::MatrixXd> mass(Px.rightCols(n));
    s.S.resize(2 * n, Sq.cols());
    s.S.topRows(n) = Sq;
    s.S.bottomRows(n) = mass.solve(Sp - Px.leftCols(n) * Sq - selected_parameters(Pp, columns));
    if (!s.S.allFinite())
        throw NonFiniteState(describe_state("the sensitivities are not finite (a singular mass matrix?)", t, s.x), t);
    return s;
}

}  // namespace detail

/**
 * The variational integrator's motion of Model M (VariationalIntegrator: fixed steps dt from t0, round((t_end −
 * t0)/dt) of them, as `eomgen run --method symplectic` takes) with S beside it, the exact derivative of its discrete
 * map (the file's comment). Samples at the nodes nearest `sample_times`. Unconstrained models without generalized
 * forces or switching surfaces only, as the integrator itself (std::invalid_argument otherwise); SimulationError
 * where a step's Newton iteration fails, NonFiniteState where S stops being finite.
 */
template <class M>
SensitivityResult integrate_sensitivities_symplectic(const typename M::Params& params, double t0,
                                                     const typename M::State& x0, double t_end, double dt,
                                                     const std::vector<SensitivityColumn>& columns,
                                                     const std::vector<double>& sample_times = {},
                                                     const VariationalOptions<double>& options = {}) {
    bool refused = constraint_count<M>() > 0 || M::has_generalized_forces;
    if constexpr (has_switching<M>::value) refused = refused || M::n_switches > 0;
    if (refused)
        throw std::invalid_argument(std::string(M::name) +
                                    ": the variational integrator takes unconstrained models without forces or switching "
                                    "surfaces; use dopri5, dop853 or adams");
    if (!(dt > 0) || !std::isfinite(dt) || !(t_end >= t0))
        throw std::invalid_argument("the variational integrator needs a positive step and t_end ≥ t0");
    check_sensitivity_columns<M>(t0, x0, params, columns);
    using Config = typename M::Config;
    const Eigen::Index nx = x0.size(), n = nx / 2, k = Eigen::Index(columns.size());
    const auto steps = static_cast<long long>(std::llround((t_end - t0) / dt));
    std::set<long long> sampled;
    for (double s : sample_times) sampled.insert(std::clamp<long long>(std::llround((s - t0) / dt), 0, steps));

    // S at the start: unit columns for initial values, then the momenta's p = P(t0, q0, q̇0; θ).
    Eigen::MatrixXd S0 = Eigen::MatrixXd::Zero(nx, k);
    for (Eigen::Index c = 0; c < k; ++c)
        if (columns[std::size_t(c)].kind == SensitivityColumn::Kind::InitialValue) S0(columns[std::size_t(c)].index, c) = 1;
    Eigen::MatrixXd Px, Pp, Gx, Gp;
    lagrangian_jacobians<M>(t0, x0, params, Px, Pp, Gx, Gp);
    std::size_t derivative_evaluations = 1;
    Eigen::MatrixXd Sq = S0.topRows(n);
    Eigen::MatrixXd Sp = Px * S0 + detail::selected_parameters(Pp, columns);

    VariationalIntegrator<M> vi(params, dt, options);
    vi.set_state(t0, Config(x0.head(n)), Config(x0.tail(n)));
    SensitivityResult out;
    const auto node = [&](const Eigen::VectorXd& qd) {
        ++derivative_evaluations;
        return detail::variational_node<M>(vi.t(), Eigen::VectorXd(vi.q()), qd, Sq, Sp, params, columns);
    };
    if (sampled.count(0)) out.samples.push_back(node(Eigen::VectorXd(x0.tail(n))));
    const double h = dt;
    Eigen::VectorXd x(nx);
    for (long long step = 1; step <= steps; ++step) {
        const double t = vi.t();
        const Eigen::VectorXd q = vi.q();
        vi.step();
        const Eigen::VectorXd v = vi.midpoint_velocity();
        x << q + (h / 2) * v, v;
        lagrangian_jacobians<M>(t + h / 2, detail::model_state<M>(x), params, Px, Pp, Gx, Gp);
        ++derivative_evaluations;
        const Eigen::MatrixXd B = Px.leftCols(n) - (h / 2) * Gx.leftCols(n);
        const Eigen::MatrixXd A = (h / 2) * B + Px.rightCols(n) - (h / 2) * Gx.rightCols(n);
        const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
        const Eigen::MatrixXd dv = lu.solve(Sp - B * Sq - detail::selected_parameters(Pp - (h / 2) * Gp, columns));
        const Eigen::MatrixXd dqm = Sq + (h / 2) * dv;
        Sq += h * dv;
        Sp = (Px.leftCols(n) + (h / 2) * Gx.leftCols(n)) * dqm + (Px.rightCols(n) + (h / 2) * Gx.rightCols(n)) * dv +
             detail::selected_parameters(Pp + (h / 2) * Gp, columns);
        if (!Sq.allFinite() || !Sp.allFinite())
            throw NonFiniteState(describe_state("the sensitivities are not finite (a singular step matrix?) after the "
                                                "step from",
                                                t, detail::model_state<M>(x)),
                                 t);
        if (sampled.count(step) || step == steps) {
            SensitivitySample s = node(Eigen::VectorXd(vi.velocity()));
            if (step == steps) out.end = s;
            if (sampled.count(step)) out.samples.push_back(std::move(s));
        }
    }
    if (steps == 0) out.end = node(Eigen::VectorXd(x0.tail(n)));
    const SensitivitySystem<M> system(params, nx, columns);
    for (SensitivitySample& s : out.samples) system.outputs(s);
    system.outputs(out.end);
    out.t = out.end.t;
    out.x = out.end.x;
    out.S = out.end.S;
    out.stop_reason = StopReason::ReachedEnd;
    out.accepted_steps = std::size_t(steps);
    out.rhs_evaluations = vi.newton_iterations();
    out.jacobian_evaluations = derivative_evaluations;
    return out;
}

}  // namespace eomgen
