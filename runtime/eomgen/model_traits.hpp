/**
 * @file model_traits.hpp  What the runtime asks of a Model (docs/generated_code.md) whatever its storage: a
 * generated model has sizes fixed at compile time (nq = 2), a model loaded at run time (TableModel,
 * model_table.hpp) has nq = Eigen::Dynamic and its sizes in its vectors. The drivers go through these so
 * that one implementation serves both.
 */
#pragma once

#include <Eigen/Core>

#include <type_traits>
#include <utility>

namespace eomgen {

/// Models with constraints declare n_constraints (and constraints(), constraint_residuals(), multipliers()).
template <class M, class = void>
struct is_constrained : std::false_type {};
template <class M>
struct is_constrained<M, std::void_t<decltype(M::n_constraints)>> : std::true_type {};

/// Unconstrained generated models have an analytic state_jacobian(t, x, p, J) (docs/generated_code.md);
/// constrained ones and models loaded at run time do not.
template <class M, class = void>
struct has_analytic_jacobian : std::false_type {};
template <class M>
struct has_analytic_jacobian<M, std::void_t<decltype(M::state_jacobian(
                                    0.0, std::declval<const typename M::State&>(),
                                    std::declval<const typename M::Params&>(), std::declval<Eigen::MatrixXd&>()))>>
    : std::true_type {};

/// Models with their own Jp = ∂ẋ/∂p, parameter_jacobian(t, x, p, Jp): an unconstrained generated model with analytic
/// Jacobians, a compiled table (model_table.hpp); the others are differentiated forward (sensitivities.hpp).
template <class M, class = void>
struct has_parameter_jacobian : std::false_type {};
template <class M>
struct has_parameter_jacobian<M, std::void_t<decltype(M::parameter_jacobian(
                                     0.0, std::declval<const typename M::State&>(),
                                     std::declval<const typename M::Params&>(), std::declval<Eigen::MatrixXd&>()))>>
    : std::true_type {};

/// Models whose rhs() has kinks or jumps (abs, sign, heaviside, max, min in the model file) declare n_switches,
/// switch_names and switching(t, q, q', p, s): the integrators stop their steps at each s_k = 0
/// (EventAction::Switch).
template <class M, class = void>
struct has_switching : std::false_type {};
template <class M>
struct has_switching<M, std::void_t<decltype(M::n_switches)>> : std::true_type {};

/// Models whose h is not conserved (forces, or L depending on t; unconstrained) declare has_power and
/// power(t, q, q', p) = dh/dt: the energy balance h(t) − h(0) − ∫ P dt stays 0.
template <class M, class = void>
struct declares_power : std::false_type {};
template <class M>
struct declares_power<M, std::void_t<decltype(M::has_power)>> : std::true_type {};

/// Whether M has power() to call (a table model knows at run time).
template <class M>
bool power_available() {
    if constexpr (declares_power<M>::value)
        return bool(M::has_power);
    else
        return false;
}

/// How many constraints a model has at run time (0 for a model without the constraint interface).
template <class M>
int constraint_count() {
    if constexpr (is_constrained<M>::value)
        return int(M::n_constraints);
    else
        return 0;
}

/// q, the first half of a state x = [q, q̇], as a block of x (writable when x is).
template <int NQ, class Derived>
auto positions(const Eigen::MatrixBase<Derived>& x) {
    if constexpr (NQ == Eigen::Dynamic)
        return x.head(x.size() / 2);
    else
        return x.template head<NQ>();
}
template <int NQ, class Derived>
auto positions(Eigen::MatrixBase<Derived>& x) {
    if constexpr (NQ == Eigen::Dynamic)
        return x.head(x.size() / 2);
    else
        return x.template head<NQ>();
}

/// q̇, the second half of a state x = [q, q̇].
template <int NQ, class Derived>
auto velocities(const Eigen::MatrixBase<Derived>& x) {
    if constexpr (NQ == Eigen::Dynamic)
        return x.tail(x.size() / 2);
    else
        return x.template tail<NQ>();
}
template <int NQ, class Derived>
auto velocities(Eigen::MatrixBase<Derived>& x) {
    if constexpr (NQ == Eigen::Dynamic)
        return x.tail(x.size() / 2);
    else
        return x.template tail<NQ>();
}

}  // namespace eomgen
