/** @file differences_support.hpp  Central differences of a generated model's rhs in the state and in the parameters,
 * the reference the exact Jacobians (model_jacobian.hpp, the generated state_jacobian()) are checked against. */
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstddef>

namespace differences_support {

/// Central differences of rhs at (t, x; p) in each state direction, step scaled to the component.
template <class M>
Eigen::Matrix<double, M::nx, M::nx> state_differences(double t, const typename M::State& x,
                                                      const typename M::Params& p) {
    Eigen::Matrix<double, M::nx, M::nx> J;
    for (int j = 0; j < M::nx; ++j) {
        const double h = 1e-6 * (1 + std::abs(x(j)));
        typename M::State xp = x, xm = x, fp, fm;
        xp(j) += h;
        xm(j) -= h;
        M::rhs(t, xp, p, fp);
        M::rhs(t, xm, p, fm);
        J.col(j) = (fp - fm) / (2 * h);
    }
    return J;
}

/// Central differences of rhs in each parameter (set through set_param, in param_names order).
template <class M>
Eigen::Matrix<double, M::nx, M::n_params> parameter_differences(double t, const typename M::State& x,
                                                                const typename M::Params& p) {
    Eigen::Matrix<double, M::nx, M::n_params> Jp;
    const auto values = M::param_values(p);
    for (int j = 0; j < M::n_params; ++j) {
        const double h = 1e-6 * (1 + std::abs(values[std::size_t(j)]));
        typename M::Params pp = p, pm = p;
        M::set_param(pp, M::param_names[std::size_t(j)], values[std::size_t(j)] + h);
        M::set_param(pm, M::param_names[std::size_t(j)], values[std::size_t(j)] - h);
        typename M::State fp, fm;
        M::rhs(t, x, pp, fp);
        M::rhs(t, x, pm, fm);
        Jp.col(j) = (fp - fm) / (2 * h);
    }
    return Jp;
}

}  // namespace differences_support
