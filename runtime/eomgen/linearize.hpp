/**
 * @file linearize.hpp  The Jacobians of a generated model's equations of motion, exact to round-off, by forward
 * differentiation through its own rhs (Eigen's AutoDiffScalar): for state-space control design about any state,
 * implicit integrators, sensitivities.
 *
 *     Eigen::Matrix<double, M::nx, M::nx> A;
 *     Eigen::Matrix<double, M::nx, M::n_params> B;
 *     eomgen::linearize<eomgen::models::door::Model>(t, x, p, A, B);   // or Model<double>::linearization(...)
 *
 * A = ∂ẋ/∂x and B = ∂ẋ/∂p at (t, x; p), x = [q, q̇], B's columns in param_names order: a parameter that a force
 * is written with (a torque `tau` in [forces]) is an input u, and its column is the B of ẋ = A x + B u. For a
 * constrained model the derivative goes through the multipliers' solve as well. At an equilibrium A is the
 * matrix `eomgen modes` gives (docs/modes.md); tests/physics/exam_modes.cpp checks both against finite
 * differences.
 */
#pragma once

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <cmath>
#include <cstddef>

namespace Eigen {

/// atan, which the model language has and Eigen 3.4's AutoDiff lacks: d atan(v) = dv / (1 + v²).
template <typename DerType>
inline AutoDiffScalar<typename internal::remove_all<DerType>::type::PlainObject> atan(const AutoDiffScalar<DerType>& x) {
    using std::atan;
    using Plain = typename internal::remove_all<DerType>::type::PlainObject;
    const auto v = x.value();
    return AutoDiffScalar<Plain>(atan(v), Plain(x.derivatives() / (1 + v * v)));
}

}  // namespace Eigen

namespace eomgen {

namespace detail {

/// The arguments of ModelT<AD> seeded for forward differentiation at (x; p): derivative j is x_j's (q, then q̇), nx + k
/// parameter k's; `n` is the derivative vector's length (a time's may follow them).
template <template <class> class ModelT, class AD>
struct Seeded {
    using D = ModelT<double>;
    using M = ModelT<AD>;
    typename M::State x;
    typename M::Config q, qd;
    typename M::Params p;

    Seeded(const typename D::State& x0, const typename D::Params& p0, int n) {
        for (int i = 0; i < D::nx; ++i) x(i) = AD(x0(i), n, i);
        for (int i = 0; i < D::nq; ++i) {
            q(i) = x(i);
            qd(i) = x(D::nq + i);
        }
        const auto values = D::param_values(p0);
        for (int k = 0; k < D::n_params; ++k)
            M::set_param(p, D::param_names[std::size_t(k)], AD(values[std::size_t(k)], n, D::nx + k));
    }
};

/// Derivative j of v: 0 where v depends on nothing (an empty derivative vector).
template <class AD>
double derivative(const AD& v, int j) {
    return v.derivatives().size() == 0 ? 0.0 : v.derivatives()(j);
}

/// Rows of values v (a vector of AD) into X = ∂v/∂x and P = ∂v/∂p.
template <int nx, int np, class Values, class MatX, class MatP>
void split_derivatives(const Values& v, MatX& X, MatP& P) {
    const int rows = int(v.size());
    X.resize(rows, nx);
    P.resize(rows, np);
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < nx; ++j) X(i, j) = derivative(v(i), j);
        for (int k = 0; k < np; ++k) P(i, k) = derivative(v(i), nx + k);
    }
}

}  // namespace detail

/// A and B of a generated model class template (`eomgen::models::<name>::Model`) at (t, x) with parameters p.
template <template <class> class ModelT, class MatA, class MatB>
void linearize(double t, const typename ModelT<double>::State& x, const typename ModelT<double>::Params& p, MatA& A,
               MatB& B) {
    using D = ModelT<double>;
    constexpr int nx = D::nx, np = D::n_params, N = nx + np;
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
    const detail::Seeded<ModelT, AD> a(x, p, N);
    typename ModelT<AD>::State f;
    ModelT<AD>::rhs(AD(t), a.x, a.p, f);
    detail::split_derivatives<nx, np>(f, A, B);
}

/// Yx = ∂y/∂x and Yp = ∂y/∂p (param_names order) of a generated model's declared outputs y(t, q, q̇; p) ([outputs]
/// of its file) at (t, x; p), by the same forward differentiation: the outputs' sensitivities are Yx S + Yp.
template <template <class> class ModelT, class MatX, class MatP>
void linearize_outputs(double t, const typename ModelT<double>::State& x, const typename ModelT<double>::Params& p,
                       MatX& Yx, MatP& Yp) {
    using D = ModelT<double>;
    constexpr int nx = D::nx, np = D::n_params, N = nx + np;
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
    const detail::Seeded<ModelT, AD> a(x, p, N);
    typename ModelT<AD>::Outputs y;
    ModelT<AD>::outputs(AD(t), a.q, a.qd, a.p, y);
    detail::split_derivatives<nx, np>(y, Yx, Yp);  // an output that depends on nothing: zero rows
}

/// Lx = ∂λ/∂x and Lp = ∂λ/∂p of a constrained generated model's multipliers λ(t, x; p) at (t, x; p), by the same
/// forward differentiation through its constrained solve: the multipliers' sensitivities are Lx S + Lp.
template <template <class> class ModelT, class MatX, class MatP>
void linearize_multipliers(double t, const typename ModelT<double>::State& x, const typename ModelT<double>::Params& p,
                           MatX& Lx, MatP& Lp) {
    using D = ModelT<double>;
    constexpr int nx = D::nx, np = D::n_params, N = nx + np;
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
    const detail::Seeded<ModelT, AD> a(x, p, N);
    typename ModelT<AD>::ConstraintVector lambda;
    ModelT<AD>::multipliers(AD(t), a.x, a.p, lambda);
    detail::split_derivatives<nx, np>(lambda, Lx, Lp);
}

/// Rx = ∂(g, c)/∂x and Rp = ∂(g, c)/∂p (2 n_constraints rows: the position residuals g, then the velocity
/// residuals c = A q̇ + b) of a constrained generated model's constraint_residuals at (t, x; p), by the same forward
/// differentiation: what a consistent start of the sensitivities needs (consistent_sensitivities.hpp).
template <template <class> class ModelT, class MatX, class MatP>
void linearize_constraint_residuals(double t, const typename ModelT<double>::State& x,
                                    const typename ModelT<double>::Params& p, MatX& Rx, MatP& Rp) {
    using D = ModelT<double>;
    constexpr int nx = D::nx, np = D::n_params, nc = D::n_constraints, N = nx + np;
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
    const detail::Seeded<ModelT, AD> a(x, p, N);
    typename ModelT<AD>::ConstraintVector g, c;
    ModelT<AD>::constraint_residuals(AD(t), a.q, a.qd, a.p, g, c);
    Eigen::Matrix<AD, 2 * nc, 1> both;
    both << g, c;
    detail::split_derivatives<nx, np>(both, Rx, Rp);
}

/// Px = ∂P/∂x, Pp = ∂P/∂p of the momenta P = ∂L/∂q̇ and Gx = ∂G/∂x, Gp = ∂G/∂p of G = ∂L/∂q (nq rows each; x = (q,
/// q̇)) of a generated model at (t, x; p), by the same forward differentiation: the derivative of a step of the
/// variational integrator (variational_sensitivities.hpp) is made of these.
template <template <class> class ModelT, class MatX, class MatP>
void linearize_lagrangian(double t, const typename ModelT<double>::State& x, const typename ModelT<double>::Params& p,
                          MatX& Px, MatP& Pp, MatX& Gx, MatP& Gp) {
    using D = ModelT<double>;
    constexpr int nx = D::nx, np = D::n_params, N = nx + np;
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
    const detail::Seeded<ModelT, AD> a(x, p, N);
    typename ModelT<AD>::Config momenta, gradient;
    ModelT<AD>::momenta(AD(t), a.q, a.qd, a.p, momenta);
    ModelT<AD>::lagrangian_gradient(AD(t), a.q, a.qd, a.p, gradient);
    detail::split_derivatives<nx, np>(momenta, Px, Pp);
    detail::split_derivatives<nx, np>(gradient, Gx, Gp);
}

/// Sx = ∂s/∂x, Sp = ∂s/∂p and St = ∂s/∂t of a generated model's switching functions s(t, q, q̇; p) (the surfaces
/// where its rhs() jumps or kinks) at (t, x; p), by the same forward differentiation: where a motion crosses one,
/// the sensitivities jump by the saltation matrix (saltation.hpp).
template <template <class> class ModelT, class MatX, class MatP, class VecT>
void linearize_switching(double t, const typename ModelT<double>::State& x, const typename ModelT<double>::Params& p,
                         MatX& Sx, MatP& Sp, VecT& St) {
    using D = ModelT<double>;
    constexpr int nx = D::nx, np = D::n_params, ns = D::n_switches, N = nx + np + 1;
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
    const detail::Seeded<ModelT, AD> a(x, p, N);
    typename ModelT<AD>::Switches s;
    ModelT<AD>::switching(AD(t, N, nx + np), a.q, a.qd, a.p, s);
    detail::split_derivatives<nx, np>(s, Sx, Sp);
    St.resize(ns);
    for (int i = 0; i < ns; ++i) St(i) = detail::derivative(s(i), nx + np);
}

}  // namespace eomgen
