/** @file differences_support.hpp  Central differences of a generated model's rhs in the state and in the parameters,
 * the reference the exact Jacobians (model_jacobian.hpp, the generated state_jacobian()) are checked against; and of
 * whole motions in one sensitivity column, the reference of the sensitivities (sensitivities.hpp). */
#pragma once

#include "eomgen/sensitivities.hpp"

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

/// The value a sensitivity column differentiates by: its parameter's, or its state's at the start.
template <class M>
double column_value(const typename M::Params& p, const typename M::State& x0, const eomgen::SensitivityColumn& c) {
    return c.kind == eomgen::SensitivityColumn::Kind::Parameter ? M::param_values(p)[std::size_t(c.index)]
                                                                : x0(c.index);
}

/// ∂(end of a motion)/∂(column) by fourth-order central differences with step h: `end(params, x0)` is the motion's
/// end with the column's value moved by ±h and ±2h.
template <class M, class End>
Eigen::VectorXd column_difference(const typename M::Params& p, const typename M::State& x0,
                                  const eomgen::SensitivityColumn& c, double h, End&& end) {
    const double v = column_value<M>(p, x0, c);
    auto at = [&](double offset) {
        typename M::Params q = p;
        typename M::State y = x0;
        if (c.kind == eomgen::SensitivityColumn::Kind::Parameter)
            M::set_param(q, M::param_names[std::size_t(c.index)], v + offset);
        else
            y(c.index) = v + offset;
        return Eigen::VectorXd(end(q, y));
    };
    return (-at(2 * h) + 8 * at(h) - 8 * at(-h) + at(-2 * h)) / (12 * h);
}

}  // namespace differences_support
