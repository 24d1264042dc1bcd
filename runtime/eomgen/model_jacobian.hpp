/**
 * @file model_jacobian.hpp  J = ∂ẋ/∂x of a model's rhs, for implicit integrators (radau5.hpp): exact to round-off,
 * by forward differentiation through the model's own rhs (Eigen's AutoDiffScalar, as linearize.hpp), constrained
 * solve included, with only the n_x state directions seeded (linearize() seeds the parameters as well).
 *
 *     Eigen::Matrix<double, M::nx, M::nx> J;
 *     eomgen::model_jacobian<M>(t, x, p, J);   // M = eomgen::models::door::Model<double>, or TableModel
 *
 * A model that brings its own `static void jacobian(t, x, p, J)` (TableModel: the one computed in the compiled
 * model's shared object) is asked for it; an unconstrained generated Model<double> has an analytic one, its member
 * state_jacobian() (generated from the symbolic equations, docs/generated_code.md), and is asked for that; a
 * constrained one is differentiated as Model<AutoDiffScalar>.
 */
#pragma once

#include "eomgen/linearize.hpp"
#include "eomgen/model_traits.hpp"

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <cstddef>
#include <type_traits>
#include <utility>

namespace eomgen {

/// J = ∂ẋ/∂x of a generated model class template (`eomgen::models::<name>::Model`) at (t, x) with parameters p.
template <template <class> class ModelT, class MatJ>
void state_jacobian(double t, const typename ModelT<double>::State& x, const typename ModelT<double>::Params& p,
                    MatJ& J) {
    using D = ModelT<double>;
    constexpr int nx = D::nx;
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, nx, 1>>;
    using M = ModelT<AD>;
    typename M::State xa;
    for (int i = 0; i < nx; ++i) xa(i) = AD(x(i), nx, i);
    typename M::Params pa;
    const auto values = D::param_values(p);
    for (std::size_t k = 0; k < values.size(); ++k) M::set_param(pa, D::param_names[k], AD(values[k]));
    typename M::State f;
    M::rhs(AD(t), xa, pa, f);
    J.resize(nx, nx);
    for (int i = 0; i < nx; ++i) J.row(i) = f(i).derivatives().transpose();
}

namespace detail {

/// The class template a generated Model<double> was made from.
template <class M>
struct model_template;
template <template <class> class T, class S>
struct model_template<T<S>> {
    template <class U>
    using type = T<U>;
};

template <class M, class = void>
struct has_own_jacobian : std::false_type {};
template <class M>
struct has_own_jacobian<M, std::void_t<decltype(M::jacobian(0.0, std::declval<const typename M::State&>(),
                                                            std::declval<const typename M::Params&>(),
                                                            std::declval<Eigen::MatrixXd&>()))>> : std::true_type {};

}  // namespace detail

/// J = ∂ẋ/∂x of Model M at (t, x; p): M::jacobian where M has one, else the analytic M::state_jacobian where M has
/// one, else state_jacobian (forward differentiation) of M's template.
template <class M, class MatJ>
void model_jacobian(double t, const typename M::State& x, const typename M::Params& p, MatJ& J) {
    if constexpr (detail::has_own_jacobian<M>::value)
        M::jacobian(t, x, p, J);
    else if constexpr (has_analytic_jacobian<M>::value)
        M::state_jacobian(t, x, p, J);
    else
        state_jacobian<detail::model_template<M>::template type>(t, x, p, J);
}

}  // namespace eomgen
