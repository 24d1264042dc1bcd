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

/// A and B of a generated model class template (`eomgen::models::<name>::Model`) at (t, x) with parameters p.
template <template <class> class ModelT, class MatA, class MatB>
void linearize(double t, const typename ModelT<double>::State& x, const typename ModelT<double>::Params& p, MatA& A,
               MatB& B) {
    using D = ModelT<double>;
    constexpr int nx = D::nx, np = D::n_params, N = nx + np;
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
    using M = ModelT<AD>;
    typename M::State xa;
    for (int i = 0; i < nx; ++i) xa(i) = AD(x(i), N, i);
    typename M::Params pa;
    const auto values = D::param_values(p);
    for (int k = 0; k < np; ++k) M::set_param(pa, D::param_names[std::size_t(k)], AD(values[std::size_t(k)], N, nx + k));
    typename M::State f;
    M::rhs(AD(t), xa, pa, f);
    A.resize(nx, nx);
    B.resize(nx, np);
    for (int i = 0; i < nx; ++i) {
        for (int j = 0; j < nx; ++j) A(i, j) = f(i).derivatives()(j);
        for (int k = 0; k < np; ++k) B(i, k) = f(i).derivatives()(nx + k);
    }
}

/// Yx = ∂y/∂x and Yp = ∂y/∂p (param_names order) of a generated model's declared outputs y(t, q, q̇; p) ([outputs]
/// of its file) at (t, x; p), by the same forward differentiation: the outputs' sensitivities are Yx S + Yp.
template <template <class> class ModelT, class MatX, class MatP>
void linearize_outputs(double t, const typename ModelT<double>::State& x, const typename ModelT<double>::Params& p,
                       MatX& Yx, MatP& Yp) {
    using D = ModelT<double>;
    constexpr int nq = D::nq, nx = D::nx, np = D::n_params, ny = D::n_outputs, N = nx + np;
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
    using M = ModelT<AD>;
    typename M::Config q, qd;
    for (int i = 0; i < nq; ++i) {
        q(i) = AD(x(i), N, i);
        qd(i) = AD(x(nq + i), N, nq + i);
    }
    typename M::Params pa;
    const auto values = D::param_values(p);
    for (int k = 0; k < np; ++k) M::set_param(pa, D::param_names[std::size_t(k)], AD(values[std::size_t(k)], N, nx + k));
    typename M::Outputs y;
    M::outputs(AD(t), q, qd, pa, y);
    Yx.resize(ny, nx);
    Yp.resize(ny, np);
    for (int i = 0; i < ny; ++i) {
        // An output that does not depend on anything has an empty derivative vector.
        const bool constant = y(i).derivatives().size() == 0;
        for (int j = 0; j < nx; ++j) Yx(i, j) = constant ? 0.0 : y(i).derivatives()(j);
        for (int k = 0; k < np; ++k) Yp(i, k) = constant ? 0.0 : y(i).derivatives()(nx + k);
    }
}

/// Lx = ∂λ/∂x and Lp = ∂λ/∂p of a constrained generated model's multipliers λ(t, x; p) at (t, x; p), by the same
/// forward differentiation through its constrained solve: the multipliers' sensitivities are Lx S + Lp.
template <template <class> class ModelT, class MatX, class MatP>
void linearize_multipliers(double t, const typename ModelT<double>::State& x, const typename ModelT<double>::Params& p,
                           MatX& Lx, MatP& Lp) {
    using D = ModelT<double>;
    constexpr int nx = D::nx, np = D::n_params, nc = D::n_constraints, N = nx + np;
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
    using M = ModelT<AD>;
    typename M::State xa;
    for (int i = 0; i < nx; ++i) xa(i) = AD(x(i), N, i);
    typename M::Params pa;
    const auto values = D::param_values(p);
    for (int k = 0; k < np; ++k) M::set_param(pa, D::param_names[std::size_t(k)], AD(values[std::size_t(k)], N, nx + k));
    typename M::ConstraintVector lambda;
    M::multipliers(AD(t), xa, pa, lambda);
    Lx.resize(nc, nx);
    Lp.resize(nc, np);
    for (int i = 0; i < nc; ++i) {
        for (int j = 0; j < nx; ++j) Lx(i, j) = lambda(i).derivatives()(j);
        for (int k = 0; k < np; ++k) Lp(i, k) = lambda(i).derivatives()(nx + k);
    }
}

}  // namespace eomgen
