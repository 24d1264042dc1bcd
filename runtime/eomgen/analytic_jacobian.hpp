/**
 * @file analytic_jacobian.hpp  A generated header's analytic state_jacobian() and parameter_jacobian()
 * (docs/generated_code.md), which call analytic_state_jacobian and analytic_parameter_jacobian below: q̈ from
 * M q̈ = f, then the columns X = M⁻¹ R(q̈) of ∂q̈/∂x or ∂q̈/∂p, with one factorization of M for both. The header
 * holds only what differs between models, the CSE'd terms R (jacobian_terms(), parameter_jacobian_terms()).
 */
#pragma once

#include "eomgen/linear_solve.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace eomgen {

/**
 * Solves M qdd = f, calls terms(qdd, R) for the right-hand sides R (the generated jacobian_terms(): ∂(f − M q̈)/∂z at
 * the solved q̈), and overwrites R with M⁻¹ R, all with one factorization of M (solve_mass_matrix_then): the
 * L D Lᵀ of solve_mass_matrix up to kLoopSolveMaxN, Eigen's LLT above, as there. rhs() of a model with at most
 * kUnrolledSolveMaxN (12) coordinates solves by the same L D Lᵀ unrolled, so q̈ agrees with its q̈ to round-off. The
 * same failures as solve_mass_matrix: SingularMassMatrix when the pivots are not regular (pivots_regular),
 * NonFiniteState when M, f, q̈ or the solved columns are not finite. `t` and `x` only go into the message.
 */
template <class MatM, class VecF, class VecQdd, class MatR, class Scalar, class VecX, class Terms>
void solve_jacobian_columns(const MatM& M, const VecF& f, VecQdd& qdd, MatR& R, const Scalar& t, const VecX& x,
                            Terms&& terms) {
    solve_mass_matrix_then(M, f, qdd, t, x, [&](const auto& solve) {
        terms(qdd, R);
        solve(R);
    });
    if (!R.allFinite()) throw NonFiniteState(describe_state("Jacobian columns are not finite", t, x), value_of(t));
}

namespace detail {

/// M⁻¹ R at (t, x) of a generated Model, R (nq × Columns) filled by terms(q, q̇, q̈, R) at the solved q̈.
template <class Model, int Columns, class Terms>
Eigen::Matrix<typename Model::Config::Scalar, Model::nq, Columns> solved_terms(
    const typename Model::Config::Scalar& t, const typename Model::State& x, const typename Model::Params& p,
    Terms&& terms) {
    using Config = typename Model::Config;
    const Config q = x.template head<Model::nq>();
    const Config qd = x.template tail<Model::nq>();
    typename Model::MassMatrix M;
    Config f, qdd;
    Model::dynamics(t, q, qd, p, M, f);
    Eigen::Matrix<typename Config::Scalar, Model::nq, Columns> R;
    solve_jacobian_columns(M, f, qdd, R, t, x, [&](const Config& a, auto& r) { terms(q, qd, a, r); });
    return R;
}

}  // namespace detail

/// J = dx'/dx = [[0, I], [M⁻¹ dr/dq, M⁻¹ dr/dq']] of a generated Model at (t, x), from its jacobian_terms(); a
/// singular M throws as in rhs().
template <class Model, class MatJ>
void analytic_state_jacobian(const typename Model::Config::Scalar& t, const typename Model::State& x,
                             const typename Model::Params& p, MatJ& J) {
    constexpr int nq = Model::nq, nx = Model::nx;
    const auto R = detail::solved_terms<Model, nx>(t, x, p, [&](const auto& q, const auto& qd, const auto& a, auto& r) {
        Model::jacobian_terms(t, q, qd, a, p, r);
    });
    J.resize(nx, nx);
    J.template topLeftCorner<nq, nq>().setZero();
    J.template topRightCorner<nq, nq>().setIdentity();
    J.template bottomRows<nq>() = R;
}

/// Jp = dx'/dp = [[0], [M⁻¹ dr/dp]] of a generated Model at (t, x), columns in param_names order, from its
/// parameter_jacobian_terms().
template <class Model, class MatJp>
void analytic_parameter_jacobian(const typename Model::Config::Scalar& t, const typename Model::State& x,
                                 const typename Model::Params& p, MatJp& Jp) {
    constexpr int nq = Model::nq;
    const auto R = detail::solved_terms<Model, Model::n_params>(
        t, x, p, [&](const auto& q, const auto& qd, const auto& a, auto& r) {
            Model::parameter_jacobian_terms(t, q, qd, a, p, r);
        });
    Jp.resize(Model::nx, Model::n_params);
    Jp.template topRows<nq>().setZero();
    Jp.template bottomRows<nq>() = R;
}

}  // namespace eomgen
