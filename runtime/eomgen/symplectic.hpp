/** @file symplectic.hpp  Midpoint variational integrator for generated Lagrangian models, stepping (q, p). */
#pragma once

#include "eomgen/errors.hpp"
#include "eomgen/linear_solve.hpp"
#include "eomgen/lu_factor.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace eomgen {

/// Settings of the implicit solve in each variational step.
template <class Scalar>
struct VariationalOptions {
    /// Converged when every |Δq_{k+1,i}| ≤ tolerance·(1 + |q_{k+1,i}|) for the last Newton update.
    Scalar tolerance = Scalar(64) * std::numeric_limits<Scalar>::epsilon();
    int max_iterations = 50;  ///< Newton iterations per step before SimulationError
};

namespace detail {

/// [q; p] as one vector, only for error messages. Element by element: GCC 12 at -O3 warns (-Warray-bounds)
/// about Eigen's vectorised copy of a 1×1 block into a dynamic one, which single-coordinate models hit.
template <class Config>
Eigen::Matrix<typename Config::Scalar, Eigen::Dynamic, 1> phase_point(const Config& q, const Config& p) {
    const Eigen::Index n = q.size();
    Eigen::Matrix<typename Config::Scalar, Eigen::Dynamic, 1> x(2 * n);
    for (Eigen::Index i = 0; i < n; ++i) {
        x(i) = q(i);
        x(n + i) = p(i);
    }
    return x;
}

/**
 * Solves the discrete Euler–Lagrange equation of the midpoint rule for the midpoint velocity v, starting
 * from the guess in `v`:
 *   R(v) = ∂L/∂q̇(qm, v, tm) − (h/2) ∂L/∂q(qm, v, tm) − p = 0,   qm = q + (h/2) v,  tm = t + h/2,
 * by Newton's method with a forward-difference Jacobian, kept while the iteration contracts fast and
 * refreshed when it slows (the "simplified Newton" of Hairer–Lubich–Wanner, GNI §VIII.6). The Jacobian is
 * M(qm) + O(h), so for small h even a stale one contracts at rate O(h). Returns the iterations used.
 */
template <class Model>
int solve_midpoint_velocity(const typename Model::Config::Scalar& t, const typename Model::Config& q,
                            const typename Model::Config& p, const typename Model::Config::Scalar& h,
                            const typename Model::Params& params,
                            const VariationalOptions<typename Model::Config::Scalar>& options,
                            typename Model::Config& v) {
    using Config = typename Model::Config;
    using Scalar = typename Config::Scalar;
    using Jacobian = typename Model::MassMatrix;
    using std::abs;
    using std::max;
    using std::sqrt;
    const Scalar half_h = h / Scalar(2), tm = t + half_h;
    const Eigen::Index n = q.size();
    Config qm = q, mom = q, grad = q, r = q, r_plus = q, dv = q, v_plus = q;
    const auto residual = [&](const Config& vel, Config& out) {
        qm = q + half_h * vel;
        Model::momenta(tm, qm, vel, params, mom);
        Model::lagrangian_gradient(tm, qm, vel, params, grad);
        out = mom - half_h * grad - p;
    };
    Jacobian jac;
    if constexpr (Jacobian::RowsAtCompileTime == Eigen::Dynamic) jac.resize(n, n);
    LuFactor<Jacobian> lu;
    const Scalar sqrt_eps = sqrt(std::numeric_limits<Scalar>::epsilon());
    const auto refresh_jacobian = [&]() {
        const Scalar scale = v.template lpNorm<Eigen::Infinity>() + Scalar(1);
        for (Eigen::Index j = 0; j < n; ++j) {
            const Scalar delta = sqrt_eps * max(abs(v(j)), scale);
            v_plus = v;
            v_plus(j) += delta;
            residual(v_plus, r_plus);
            jac.col(j) = (r_plus - r) / (v_plus(j) - v(j));
        }
        if (!lu.compute(jac))
            throw SimulationError(describe_state("variational step: the Newton iteration's Jacobian is singular or "
                                                 "not finite, from [q; p]",
                                                 t, phase_point(q, p)),
                                  value_of(t));
    };

    residual(v, r);
    refresh_jacobian();
    Scalar err_prev = std::numeric_limits<Scalar>::infinity();
    for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
        dv = -lu.solve(r);
        v += dv;
        if (!v.allFinite())
            throw SimulationError(describe_state("variational step: Newton iteration produced a non-finite "
                                                 "velocity (singular Jacobian?), from [q; p]",
                                                 t, phase_point(q, p)),
                                  value_of(t));
        Scalar err(0);
        for (Eigen::Index i = 0; i < n; ++i)
            err = max(err, abs(h * dv(i)) / (Scalar(1) + abs(q(i) + h * v(i))));
        if (err <= options.tolerance) return iteration;
        residual(v, r);
        if (err > Scalar(0.25) * err_prev) refresh_jacobian();  // slow contraction: the Jacobian is stale
        err_prev = err;
    }
    throw SimulationError(
        describe_state("variational step: Newton did not converge in " +
                           std::to_string(options.max_iterations) + " iterations (last update " +
                           std::to_string(value_of(err_prev)) + "), from [q; p]",
                       t, phase_point(q, p)),
        value_of(t));
}

}  // namespace detail

/**
 * Velocity from momentum by the inverse Legendre map at one point: solves ∂L/∂q̇(t, q, q̇) = p for q̇.
 * The generated models have L quadratic in q̇ (M depends on (t, q) only), so ∂L/∂q̇ = M q̇ + b(t, q) and
 *   M(t, q) q̇ = p − ∂L/∂q̇(t, q, 0)
 * is exact; b holds gyroscopic / moving-frame terms. Throws SingularMassMatrix via solve_mass_matrix.
 */
template <class Model>
void legendre_velocity(const typename Model::Config::Scalar& t, const typename Model::Config& q,
                       const typename Model::Config& p, const typename Model::Params& params,
                       typename Model::Config& qd) {
    typename Model::MassMatrix M;
    if constexpr (Model::MassMatrix::RowsAtCompileTime == Eigen::Dynamic) M.resize(q.size(), q.size());
    typename Model::Config zero = q, b = q;
    zero.setZero();
    Model::mass_matrix(t, q, params, M);
    Model::momenta(t, q, zero, params, b);
    const typename Model::Config rhs = p - b;
    solve_mass_matrix(M, rhs, qd, t, detail::phase_point(q, p));
}

/**
 * One step of the midpoint variational integrator (Marsden & West, "Discrete mechanics and variational
 * integrators", Acta Numerica 10, 2001, §2.1–2.2 and §4.2; Hairer–Lubich–Wanner, "Geometric Numerical
 * Integration", §VI.6). The discrete Lagrangian
 *   L_d(q0, q1) = h L((q0 + q1)/2, (q1 − q0)/h, t + h/2)
 * gives, in position–momentum form, p_k = −D1 L_d(q_k, q_{k+1}) and p_{k+1} = D2 L_d(q_k, q_{k+1}):
 *   p_k     = ∂L/∂q̇(qm, v) − (h/2) ∂L/∂q(qm, v)     (implicit in v, solved by Newton),
 *   p_{k+1} = ∂L/∂q̇(qm, v) + (h/2) ∂L/∂q(qm, v),     q_{k+1} = q_k + h v,   qm = q_k + (h/2) v.
 * The map (q_k, p_k) → (q_{k+1}, p_{k+1}) is symplectic, second order and symmetric: the step with −h from
 * (q_{k+1}, p_{k+1}) returns to (q_k, p_k). So energy errors stay bounded (O(h²), no drift) over
 * exponentially long times (GNI §IX.8) when L has no explicit t.
 *
 * `Model` has the static interface of docs/generated_code.md (Config, MassMatrix, Params, mass_matrix,
 * momenta, lagrangian_gradient). The Newton guess is `v_guess`; the solved midpoint velocity is returned in
 * `v_mid`. Returns the Newton iterations used; throws SimulationError when Newton does not converge.
 */
template <class Model>
int variational_midpoint_step(const typename Model::Config::Scalar& t, const typename Model::Config& q,
                              const typename Model::Config& p, const typename Model::Config::Scalar& h,
                              const typename Model::Params& params, const typename Model::Config& v_guess,
                              const VariationalOptions<typename Model::Config::Scalar>& options,
                              typename Model::Config& q_next, typename Model::Config& p_next,
                              typename Model::Config& v_mid) {
    using Config = typename Model::Config;
    using Scalar = typename Config::Scalar;
    v_mid = v_guess;
    const int iterations = detail::solve_midpoint_velocity<Model>(t, q, p, h, params, options, v_mid);
    const Scalar half_h = h / Scalar(2), tm = t + half_h;
    const Config qm = q + half_h * v_mid;
    Config mom = q, grad = q;
    Model::momenta(tm, qm, v_mid, params, mom);
    Model::lagrangian_gradient(tm, qm, v_mid, params, grad);
    q_next = q + h * v_mid;
    p_next = mom + half_h * grad;
    return iterations;
}

/// The same step with the Legendre velocity at (t, q, p) as the Newton guess.
template <class Model>
int variational_midpoint_step(const typename Model::Config::Scalar& t, const typename Model::Config& q,
                              const typename Model::Config& p, const typename Model::Config::Scalar& h,
                              const typename Model::Params& params,
                              const VariationalOptions<typename Model::Config::Scalar>& options,
                              typename Model::Config& q_next, typename Model::Config& p_next) {
    typename Model::Config guess = q, v_mid = q;
    legendre_velocity<Model>(t, q, p, params, guess);
    return variational_midpoint_step<Model>(t, q, p, h, params, guess, options, q_next, p_next, v_mid);
}

/**
 * Fixed-step midpoint variational integrator for a generated model: holds (t_k, q_k, p_k) with
 * t_k = t0 + k·h, and steps it with variational_midpoint_step (each step's Newton guess is the previous
 * midpoint velocity). The velocity at the nodes, q̇_k, is the inverse Legendre map of (q_k, p_k) (see
 * legendre_velocity): it is the one consistent with the conserved momenta, and energy() evaluates
 * Model::energy(t_k, q_k, q̇_k) with it.
 *
 *   VariationalIntegrator<Model> vi(params, h);
 *   vi.set_state(t0, q0, qd0);               // p0 = ∂L/∂q̇(t0, q0, q̇0)
 *   for (...) { vi.step(); use(vi.t(), vi.q(), vi.p(), vi.velocity(), vi.energy()); }
 */
template <class Model>
class VariationalIntegrator {
  public:
    using Config = typename Model::Config;
    using Scalar = typename Config::Scalar;
    using Params = typename Model::Params;
    using Options = VariationalOptions<Scalar>;

    VariationalIntegrator(const Params& params, const Scalar& h, const Options& options = {})
        : params_(params), h_(h), options_(options) {
        if (!(h != Scalar(0)) || !std::isfinite(h))
            throw std::invalid_argument("VariationalIntegrator: h must be finite and non-zero");
    }

    /// Starts from configuration and velocity; the momentum is p0 = ∂L/∂q̇(t0, q0, q̇0).
    void set_state(const Scalar& t0, const Config& q0, const Config& qd0) {
        Config p0 = q0;
        Model::momenta(t0, q0, qd0, params_, p0);
        set_phase_state(t0, q0, p0);
    }

    /// Starts from configuration and momentum.
    void set_phase_state(const Scalar& t0, const Config& q0, const Config& p0) {
        if (!q0.allFinite() || !p0.allFinite())
            throw NonFiniteState(
                describe_state("initial [q; p] is not finite", t0, detail::phase_point(q0, p0)), value_of(t0));
        t0_ = t0;
        t_ = t0;
        k_ = 0;
        q_ = q0;
        p_ = p0;
        v_mid_ = q0;
        legendre_velocity<Model>(t0, q0, p0, params_, v_mid_);  // the first Newton guess
        started_ = true;
    }

    /// Advances one step of size h. Throws SimulationError (Newton failure) or NonFiniteState.
    void step() {
        if (!started_) throw std::logic_error("VariationalIntegrator::step before set_state");
        Config q_next = q_, p_next = p_;
        iterations_ += std::size_t(variational_midpoint_step<Model>(t_, q_, p_, h_, params_, v_mid_, options_,
                                                                    q_next, p_next, v_mid_));
        if (!q_next.allFinite() || !p_next.allFinite())
            throw NonFiniteState(describe_state("variational step produced a non-finite state, from [q; p]",
                                                t_, detail::phase_point(q_, p_)),
                                 value_of(t_));
        q_.swap(q_next);
        p_.swap(p_next);
        ++k_;
        t_ = t0_ + Scalar(k_) * h_;
    }

    /// n steps.
    void step(std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) step();
    }

    const Scalar& t() const { return t_; }
    const Config& q() const { return q_; }
    const Config& p() const { return p_; }
    const Scalar& step_size() const { return h_; }
    std::size_t steps() const { return k_; }
    std::size_t newton_iterations() const { return iterations_; }  ///< total over all steps
    const Config& midpoint_velocity() const { return v_mid_; }     ///< (q_k − q_{k−1})/h of the last step

    /// q̇_k from (q_k, p_k) by the inverse Legendre map.
    Config velocity() const {
        Config qd = q_;
        legendre_velocity<Model>(t_, q_, p_, params_, qd);
        return qd;
    }

    /// Model::energy at (t_k, q_k, q̇_k).
    Scalar energy() const { return Model::energy(t_, q_, velocity(), params_); }

  private:
    Params params_;
    Scalar h_;
    Options options_;
    Scalar t0_ = Scalar(0), t_ = Scalar(0);
    Config q_, p_, v_mid_;
    std::size_t k_ = 0, iterations_ = 0;
    bool started_ = false;
};

}  // namespace eomgen
