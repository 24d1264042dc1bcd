/** @file constraints.hpp  Constrained dynamics: the KKT solve, projection onto the constraint manifold, checks. */
#pragma once

#include "eomgen/errors.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/linear_solve.hpp"
#include "eomgen/model_traits.hpp"
#include "eomgen/sliding.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace eomgen {

namespace detail {

/// The weight w of the augmented mass matrix M + w AᵀA: M's scale over A's, so that neither swamps the other.
template <class MatM, class MatA>
typename MatM::Scalar augmentation_weight(const MatM& M, const MatA& A) {
    using S = typename MatM::Scalar;
    using std::abs;
    S m = 0, a = 0;
    for (Eigen::Index i = 0; i < M.rows(); ++i) m = std::max(m, S(abs(M(i, i))));
    for (Eigen::Index k = 0; k < A.rows(); ++k) a = std::max(a, S(A.row(k).squaredNorm()));
    if (!(m > 0)) m = S(1);
    return a > 0 ? m / a : S(1);
}

}  // namespace detail

/**
 * Solves the constrained equations of motion (Goldstein §2.4; Bauchau & Laulusa, J. Comput. Nonlinear
 * Dynam. 3 (2008), "Review of contemporary approaches for constraint enforcement in multibody systems")
 * \f[ M\ddot q = f + A^T\lambda,\qquad A\ddot q = \gamma \f]
 * by a Schur complement on M's factor (MassFactor, linear_solve.hpp: the L D Lᵀ of solve_mass_matrix), never an
 * LDLᵀ of the indefinite KKT matrix: Y = M⁻¹Aᵀ, S = A Y (symmetric positive definite when A has full row rank),
 * λ = S⁻¹(γ − A M⁻¹ f), q̈ = M⁻¹(f + Aᵀλ). Sizes: M n×n, f n, A m×n, γ m; outputs q̈ (n) and λ (m). Both
 * factorizations are tested on their pivots (pivots_regular; S with a 1e3 margin), not by a condition estimate.
 *
 * M may be singular where the constraints supply what it lacks: a coordinate driven by a rheonomic
 * constraint (a hoop spun at a prescribed rate) has no inertia of its own where the bead sits on the axis.
 * Then the same equations are solved with the augmented M̃ = M + w AᵀA and f̃ = f + w Aᵀγ (adding
 * w AᵀA q̈ = w Aᵀγ to both sides changes neither q̈ nor λ), which is positive definite exactly when M is
 * positive definite on the motions the constraints allow (Bauchau & Laulusa §4, the augmented Lagrangian
 * formulation). Only a singular constrained system is an error.
 *
 * Throws SingularMassMatrix when M is not positive definite on the null space of A, SingularConstraints
 * when S is singular (A lost rank), NonFiniteState for non-finite inputs; `t` and `x` go into the message.
 */
template <class MatM, class VecF, class MatA, class VecG, class VecQdd, class VecL, class Scalar, class VecX>
void solve_constrained(const MatM& M, const VecF& f, const MatA& A, const VecG& gamma, VecQdd& qdd, VecL& lambda,
                       const Scalar& t, const VecX& x) {
    using S = typename MatM::Scalar;
    // Nothing passes over the inputs on the way: they are tested for finiteness only once something failed.
    const auto not_finite = [&](const char* what) {
        if (!M.allFinite() || !f.allFinite() || !A.allFinite() || !gamma.allFinite())
            return NonFiniteState(describe_state("mass matrix, forcing or constraints are not finite", t, x),
                                  value_of(t));
        return NonFiniteState(describe_state(what, t, x), value_of(t));
    };
    // The products by loops, as MassFactor's factorization: Eigen's products for each fixed size cost compile time
    // in every constrained model's shared object, not speed at these sizes.
    const Eigen::Index n = M.rows(), m = A.rows();
    MassFactor<S, MatM::RowsAtCompileTime> m_factor;
    typename VecF::PlainObject rhs = f;
    if (!m_factor.compute(M)) {
        const S w = detail::augmentation_weight(M, A);
        typename MatM::PlainObject augmented = M;  // M + w AᵀA
        for (Eigen::Index i = 0; i < n; ++i)
            for (Eigen::Index j = 0; j < n; ++j) {
                S s(0);
                for (Eigen::Index k = 0; k < m; ++k) s += A(k, i) * A(k, j);
                augmented(i, j) += w * s;
            }
        if (!m_factor.compute(augmented)) {
            if (!M.allFinite() || !A.allFinite()) throw not_finite("");
            throw SingularMassMatrix(
                describe_state("mass matrix is singular or not positive definite on the motions the constraints allow",
                               t, x),
                value_of(t));
        }
        for (Eigen::Index i = 0; i < n; ++i) {  // f + w Aᵀγ
            S s(0);
            for (Eigen::Index k = 0; k < m; ++k) s += A(k, i) * gamma(k);
            rhs(i) += w * s;
        }
    }
    Eigen::Matrix<S, MatA::ColsAtCompileTime, MatA::RowsAtCompileTime> Y(n, m);  // Aᵀ (n×m), then M⁻¹Aᵀ
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index k = 0; k < m; ++k) Y(i, k) = A(k, i);
    m_factor.solve_in_place(Y);
    m_factor.solve_in_place(rhs);  // M⁻¹ f
    Eigen::Matrix<S, MatA::RowsAtCompileTime, MatA::RowsAtCompileTime> schur(m, m);  // A M⁻¹ Aᵀ
    for (Eigen::Index a = 0; a < m; ++a)
        for (Eigen::Index b = 0; b < m; ++b) {
            S s(0);
            for (Eigen::Index i = 0; i < n; ++i) s += A(a, i) * Y(i, b);
            schur(a, b) = s;
        }
    MassFactor<S, MatA::RowsAtCompileTime> s_factor;
    if (!s_factor.compute(schur, 1e3)) {
        if (!schur.allFinite()) throw not_finite("the constraints' Schur complement is not finite");
        throw SingularConstraints(
            describe_state("constraint Jacobian lost rank (redundant constraints or a singular configuration)", t, x),
            value_of(t));
    }
    lambda.resize(m);
    for (Eigen::Index a = 0; a < m; ++a) {  // γ − A M⁻¹ f
        S s = gamma(a);
        for (Eigen::Index i = 0; i < n; ++i) s -= A(a, i) * rhs(i);
        lambda(a) = s;
    }
    s_factor.solve_in_place(lambda);
    qdd.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {  // M⁻¹ f + M⁻¹Aᵀ λ
        S s = rhs(i);
        for (Eigen::Index a = 0; a < m; ++a) s += Y(i, a) * lambda(a);
        qdd(i) = s;
    }
    if (!qdd.allFinite() || !lambda.allFinite()) throw not_finite("accelerations or multipliers are not finite");
}

/// The residuals of a constrained Model at (t, x): the largest |g_k| over holonomic constraints (position
/// level) and the largest |A_k q̇ + b_k| over all (velocity level), with the worst constraint's index.
template <class Model>
struct ConstraintResidual {
    typename Model::Config::Scalar position = 0, velocity = 0;
    int worst_position = -1, worst_velocity = -1;
};

template <class Model>
ConstraintResidual<Model> constraint_residual(const typename Model::Config::Scalar& t, const typename Model::State& x,
                                              const typename Model::Params& p) {
    typename Model::ConstraintVector g, c;
    Model::constraint_residuals(t, positions<Model::nq>(x), velocities<Model::nq>(x), p, g, c);
    ConstraintResidual<Model> r;
    for (int k = 0; k < Model::n_constraints; ++k) {
        using std::abs;
        if (Model::constraint_is_holonomic[std::size_t(k)] && abs(g(k)) > r.position) {
            r.position = abs(g(k));
            r.worst_position = k;
        }
        if (abs(c(k)) > r.velocity) {
            r.velocity = abs(c(k));
            r.worst_velocity = k;
        }
    }
    return r;
}

namespace detail {

/// Δ = −M⁻¹Bᵀ(B M⁻¹ Bᵀ)⁻¹ r: the M-orthogonal (kinetic-energy metric) correction that zeroes B Δ + r.
template <class MatM, class MatB, class VecR>
Eigen::Matrix<typename MatM::Scalar, MatM::RowsAtCompileTime, 1> metric_correction(const MatM& M, const MatB& B,
                                                                                     const VecR& r) {
    // Where M is singular (see solve_constrained) the metric is M + w BᵀB: positive definite, and the
    // correction still zeroes B Δ + r.
    MassFactor<typename MatM::Scalar, MatM::RowsAtCompileTime> factor;
    if (!factor.compute(M)) factor.compute((M + augmentation_weight(M, B) * B.transpose() * B).eval());
    Eigen::Matrix<typename MatM::Scalar, MatB::ColsAtCompileTime, MatB::RowsAtCompileTime> Y = B.transpose();
    factor.solve_in_place(Y);
    const auto S = (B * Y).eval();
    return -Y * S.ldlt().solve(r);
}

}  // namespace detail

/**
 * Projects x = [q, q̇] back onto the constraint manifold: Gauss–Newton on the holonomic positions
 * g(q,t) = 0 in M's metric, then the velocities onto A q̇ + b = 0 (one linear step, exact). Used after
 * steps to stop drift (Hairer–Lubich–Wanner, "Geometric Numerical Integration", §IV.4; Ascher et al.
 * 1995 for the metric). Throws SimulationError when the positions do not converge.
 */
template <class Model>
void project_onto_constraints(const typename Model::Config::Scalar& t, typename Model::State& x,
                              const typename Model::Params& p,
                              const typename Model::Config::Scalar& tol = typename Model::Config::Scalar(1e-13)) {
    using Scalar = typename Model::Config::Scalar;
    using Config = typename Model::Config;
    constexpr int nq = Model::nq;
    const int nc = Model::n_constraints;
    int nh = 0;
    for (bool h : Model::constraint_is_holonomic) nh += h ? 1 : 0;
    typename Model::MassMatrix M;
    typename Model::ConstraintJacobian A;
    typename Model::ConstraintVector gamma, g, c;
    Config q = positions<nq>(x), qd = velocities<nq>(x);
    if (nh > 0) {
        Eigen::Matrix<Scalar, Eigen::Dynamic, nq> G(nh, q.size());
        Eigen::Matrix<Scalar, Eigen::Dynamic, 1> gh(nh);
        for (int iteration = 0;; ++iteration) {
            Model::constraint_residuals(t, q, qd, p, g, c);
            Model::constraints(t, q, qd, p, A, gamma);
            for (int k = 0, r = 0; k < nc; ++k)
                if (Model::constraint_is_holonomic[std::size_t(k)]) {
                    G.row(r) = A.row(k);
                    gh(r++) = g(k);
                }
            const Scalar scale = Scalar(1) + q.cwiseAbs().maxCoeff();
            if (gh.cwiseAbs().maxCoeff() <= tol * scale) break;
            if (iteration == 50)
                throw SimulationError(describe_state("projection onto the holonomic constraints did not converge", t, x),
                                      value_of(t));
            Model::mass_matrix(t, q, p, M);
            q += detail::metric_correction(M, G, gh);
        }
    }
    Model::mass_matrix(t, q, p, M);
    Model::constraints(t, q, qd, p, A, gamma);
    Model::constraint_residuals(t, q, qd, p, g, c);
    qd += detail::metric_correction(M, A, c);
    positions<nq>(x) = q;
    velocities<nq>(x) = qd;
}

/**
 * Checks that x satisfies every constraint to `tol` (relative to the size of q and q̇) and throws
 * InconsistentInitialConditions naming the first violated constraint and its residual otherwise.
 */
template <class Model>
void check_consistent(const typename Model::Config::Scalar& t, const typename Model::State& x,
                      const typename Model::Params& p,
                      const typename Model::Config::Scalar& tol = typename Model::Config::Scalar(1e-9)) {
    typename Model::ConstraintVector g, c;
    Model::constraint_residuals(t, positions<Model::nq>(x), velocities<Model::nq>(x), p, g, c);
    const auto scale = typename Model::Config::Scalar(1) + x.cwiseAbs().maxCoeff();
    for (int k = 0; k < Model::n_constraints; ++k) {
        using std::abs;
        const bool holonomic = Model::constraint_is_holonomic[std::size_t(k)];
        const bool bad_position = holonomic && !(abs(g(k)) <= tol * scale);
        const bool bad_velocity = !(abs(c(k)) <= tol * scale);
        if (!bad_position && !bad_velocity) continue;
        std::ostringstream os;
        os.precision(17);
        os << "initial conditions violate constraint '" << Model::constraint_names[std::size_t(k)] << "' at "
           << (bad_position ? "position" : "velocity") << " level (residual "
           << value_of(bad_position ? g(k) : c(k)) << ")";
        throw InconsistentInitialConditions(describe_state(os.str(), t, x), value_of(t));
    }
}

/// What integrate_constrained() measured besides the trajectory.
template <class State>
struct ConstrainedResult {
    IntegrationResult<State> run;                     ///< samples, counters (summed over the segments)
    typename State::Scalar max_position_residual = 0;  ///< before each projection: the drift of one segment
    typename State::Scalar max_velocity_residual = 0;
};

/**
 * Integrates a constrained Model with the adaptive stepper Method (Dopri5 by default, Dop853, Adams; see
 * integrate_with) from sample time to sample time, projecting the
 * state onto the constraints after each segment (drift control on top of any Baumgarte terms). The
 * residuals reached before each projection are reported; `observer` sees each projected sample. x0 is checked first (check_consistent) unless
 * `project_initial` is set, in which case it is projected. `events` are located within each segment as by
 * integrate(); a terminal one ends the run at the event (its state projected, and kept as the last sample).
 *
 * Where the motion would slide along a Switch event without a stop_at_switch of its own (static friction holds it:
 * both sides of the jump push into the surface), it follows Filippov's sliding motion as integrate_sliding does,
 * across the segments: each one-sided field is the constrained one, so their convex combination keeps the
 * constraints' accelerations too, and the projection after each segment leaves s = 0 to the order of the drift it
 * removes. The run's events say where sliding began ("<switch>: slides") and ended ("<switch>: leaves to s > 0").
 */
template <class Model, template <class> class Method = Dopri5>
ConstrainedResult<typename Model::State> integrate_constrained(const typename Model::Params& p,
                                                               const typename Model::Config::Scalar& t0,
                                                               typename Model::State x0,
                                                               const std::vector<typename Model::Config::Scalar>& times,
                                                               const typename Method<typename Model::State>::Options& opt,
                                                               bool project_initial = false,
                                                               const std::vector<Event<typename Model::State>>& events = {},
                                                               const Observer<typename Model::State>& observer = {}) {
    using Scalar = typename Model::Config::Scalar;
    using State = typename Model::State;
    if (project_initial)
        project_onto_constraints<Model>(t0, x0, p);
    else
        check_consistent<Model>(t0, x0, p);
    auto f = [&p](const Scalar& t, const State& x, State& xdot) { Model::rhs(t, x, p, xdot); };
    const SlidingRules<State> rules = filippov_rules<State>(f, events);
    SlidingCarry carry;
    ConstrainedResult<State> out;
    out.run.t = t0;
    out.run.x = x0;
    out.run.samples.push_back({t0, x0});
    Scalar t = t0;
    State x = x0;
    for (const Scalar& next : times) {
        if (!(next > t)) continue;
        const IntegrationResult<State> seg =
            integrate_sliding_with<Method>(f, t, x, next, opt, events, rules, {}, {}, &carry);
        out.run.events.insert(out.run.events.end(), seg.events.begin(), seg.events.end());
        out.run.switches.insert(out.run.switches.end(), seg.switches.begin(), seg.switches.end());
        out.run.accepted_steps += seg.accepted_steps;
        out.run.rejected_steps += seg.rejected_steps;
        out.run.rhs_evaluations += seg.rhs_evaluations;
        t = seg.t;
        x = seg.x;
        const ConstraintResidual<Model> r = constraint_residual<Model>(t, x, p);
        out.max_position_residual = std::max(out.max_position_residual, r.position);
        out.max_velocity_residual = std::max(out.max_velocity_residual, r.velocity);
        project_onto_constraints<Model>(t, x, p);
        out.run.samples.push_back({t, x});
        if (observer) observer(t, x);
        if (seg.stop_reason == StopReason::TerminalEvent) {
            out.run.stop_reason = seg.stop_reason;
            out.run.stopped_by = seg.stopped_by;
            break;
        }
    }
    out.run.t = t;
    out.run.x = x;
    return out;
}

}  // namespace eomgen
