/**
 * @file consistent_sensitivities.hpp  Where the sensitivities of a constrained model start: S(t0) on the tangent of
 * the constraint manifold, so that a change of one initial value, or of a parameter the constraints contain, moves
 * the start the way a consistent start moves.
 *
 * A constrained model's initial state must satisfy its constraints, g(t0, q; p) = 0 (holonomic rows) and
 * c(t0, q, q̇; p) = A q̇ + b = 0 (every row). A change δ of one initial value (x0:x of a Cartesian pendulum) or of a
 * parameter (its l) leaves them; the start that is meant is the consistent state nearest the changed one in the
 * kinetic-energy metric M — what `--project-initial` (project_onto_constraints) does: positions first, then
 * velocities. Its derivative at a consistent x0 is, for a column with raw start (s_q, s_q̇) and the parameter's
 * residual derivatives (g_p, c_p) (zero for an initial value's column),
 *
 *     S_q = s_q + Δ(G, G s_q + g_p),                 G = ∂g/∂q of the holonomic rows,
 *     S_q̇ = s_q̇ + Δ(A, c_q S_q + A s_q̇ + c_p),      Δ(B, r) = −M⁻¹Bᵀ(B M⁻¹ Bᵀ)⁻¹ r,
 *
 * the M-orthogonal corrections that zero the linearized residuals. The index-1 equations preserve the linearized
 * constraints, so S stays on the manifold's tangent thereafter: the sensitivities are the constrained motion's. For
 * a Cartesian pendulum's x0:x the other coordinate follows along the rod; for its l the bob moves out along it.
 *
 * ∂(g, c)/∂(x, p) are exact: M's own constraint_residual_jacobian where it has one (a compiled table), else
 * forward differentiation of M's template (linearize_constraint_residuals).
 */
#pragma once

#include "eomgen/constraints.hpp"
#include "eomgen/linearize.hpp"
#include "eomgen/model_jacobian.hpp"
#include "eomgen/model_traits.hpp"

#include <Eigen/Core>

#include <type_traits>
#include <utility>
#include <vector>

namespace eomgen {

namespace detail {

template <class M, class = void>
struct has_residual_jacobian : std::false_type {};
template <class M>
struct has_residual_jacobian<M, std::void_t<decltype(M::constraint_residual_jacobian(
                                    0.0, std::declval<const typename M::State&>(),
                                    std::declval<const typename M::Params&>(), std::declval<Eigen::MatrixXd&>(),
                                    std::declval<Eigen::MatrixXd&>()))>> : std::true_type {};

}  // namespace detail

/// Rx = ∂(g, c)/∂x and Rp = ∂(g, c)/∂p of constrained Model M's residuals at (t, x; p): the position rows, then the
/// velocity rows.
template <class M>
void constraint_residual_jacobians(double t, const typename M::State& x, const typename M::Params& p,
                                   Eigen::MatrixXd& Rx, Eigen::MatrixXd& Rp) {
    if constexpr (detail::has_residual_jacobian<M>::value)
        M::constraint_residual_jacobian(t, x, p, Rx, Rp);
    else
        linearize_constraint_residuals<detail::model_template<M>::template type>(t, x, p, Rx, Rp);
}

/**
 * The consistent start of the sensitivities of constrained Model M at a consistent (t0, x0; p): `S0` holds each
 * column's raw start (a unit vector for an initial value, 0 for a parameter) and `parameter_of` each column's
 * parameter index (−1 for an initial value's column); S0 is moved onto the constraints' tangent as the file's comment
 * says. A model without constraints leaves S0 as it is.
 */
template <class M>
void consistent_sensitivity_start(double t0, const typename M::State& x0, const typename M::Params& p,
                                  const std::vector<int>& parameter_of, Eigen::MatrixXd& S0) {
    if constexpr (is_constrained<M>::value) {
        const int nc = constraint_count<M>();
        if (nc == 0) return;
        const Eigen::Index nx = x0.size(), nq = nx / 2;
        const auto q = positions<M::nq>(x0);
        const auto qd = velocities<M::nq>(x0);
        typename M::MassMatrix Mq;
        typename M::ConstraintJacobian A;
        typename M::ConstraintVector gamma;
        M::mass_matrix(t0, q, p, Mq);
        M::constraints(t0, q, qd, p, A, gamma);
        Eigen::MatrixXd Rx, Rp;
        constraint_residual_jacobians<M>(t0, x0, p, Rx, Rp);
        int nh = 0;
        for (int k = 0; k < nc; ++k) nh += M::constraint_is_holonomic[std::size_t(k)] ? 1 : 0;
        Eigen::MatrixXd G(nh, nq), Gp(nh, Rp.cols());
        for (int k = 0, r = 0; k < nc; ++k)
            if (M::constraint_is_holonomic[std::size_t(k)]) {
                G.row(r) = Rx.row(k).head(nq);
                Gp.row(r++) = Rp.row(k);
            }
        const Eigen::MatrixXd Cq = Rx.block(nc, 0, nc, nq), Cqd = Rx.block(nc, nq, nc, nq), Cp = Rp.bottomRows(nc);
        const Eigen::MatrixXd Mdyn = Mq, Adyn = A;
        for (Eigen::Index c = 0; c < S0.cols(); ++c) {
            const int k = parameter_of[std::size_t(c)];
            Eigen::VectorXd sq = S0.col(c).head(nq), sqd = S0.col(c).tail(nq);
            if (nh > 0) {
                Eigen::VectorXd r = G * sq;
                if (k >= 0) r += Gp.col(k);
                sq += detail::metric_correction(Mdyn, G, r);
            }
            Eigen::VectorXd r = Cq * sq + Cqd * sqd;
            if (k >= 0) r += Cp.col(k);
            sqd += detail::metric_correction(Mdyn, Adyn, r);
            S0.col(c).head(nq) = sq;
            S0.col(c).tail(nq) = sqd;
        }
    }
}

}  // namespace eomgen
