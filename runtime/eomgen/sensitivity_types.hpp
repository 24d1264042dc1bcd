/**
 * @file sensitivity_types.hpp  The plain data of a run with sensitivities (sensitivities.hpp): which columns S has,
 * the events whose times are differentiated, and what the run returns. Nothing here integrates.
 */
#pragma once

#include "eomgen/events.hpp"
#include "eomgen/integrate.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace eomgen {

/// One column of S: the derivative with respect to a parameter (index in param_names) or to an initial value
/// (index in state_names: q, then q̇).
struct SensitivityColumn {
    enum class Kind { Parameter, InitialValue };
    Kind kind = Kind::Parameter;
    int index = 0;
};

/// The column of parameter `name` (std::invalid_argument when `names` has none).
template <class Names>
SensitivityColumn parameter_column(const Names& names, const std::string& name) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (name == names[i]) return {SensitivityColumn::Kind::Parameter, int(i)};
    throw std::invalid_argument("no parameter '" + name + "'");
}

/// The column of the initial value of state `name` (a coordinate or NAME_dot).
template <class Names>
SensitivityColumn initial_column(const Names& names, const std::string& name) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (name == names[i]) return {SensitivityColumn::Kind::InitialValue, int(i)};
    throw std::invalid_argument("no state '" + name + "'");
}

/**
 * An event for integrate_sensitivities: `event.g(t, x)` of the model's state, and, where it is known, its
 * gradient (g_t, g_x) at (t, x) for the event time's sensitivity. Without one, g_t and g_x are taken by central
 * differences (steps of 1e-5 relative: about 1e-10 relative error for a smooth g).
 */
struct SensitivityEvent {
    Event<Eigen::VectorXd> event;
    std::function<void(double t, const Eigen::VectorXd& x, double& g_t, Eigen::RowVectorXd& g_x)> gradient = {};
};

/// The event where state i crosses `value` (g = x_i − value), with its exact gradient.
inline SensitivityEvent state_crossing(std::string name, int i, double value,
                                       EventDirection direction = EventDirection::Both,
                                       EventAction action = EventAction::Stop) {
    SensitivityEvent e;
    e.event = {std::move(name), [i, value](const double&, const Eigen::VectorXd& x) { return x(i) - value; },
               direction, action};
    e.gradient = [i](double, const Eigen::VectorXd& x, double& g_t, Eigen::RowVectorXd& g_x) {
        g_t = 0;
        g_x = Eigen::RowVectorXd::Zero(x.size());
        g_x(i) = 1;
    };
    return e;
}

/// The state and S at a requested time, and the declared outputs with theirs.
struct SensitivitySample {
    double t = 0;
    Eigen::VectorXd x;
    Eigen::MatrixXd S;  ///< nx × columns
    Eigen::VectorXd y;  ///< the declared outputs ([outputs] of the model file): empty where there are none
    Eigen::MatrixXd Y;  ///< ∂y/∂(columns) = Yx S + Yp (n_outputs × columns)
    Eigen::VectorXd lambda;  ///< a constrained model's multipliers: empty without constraints
    Eigen::MatrixXd L;       ///< ∂λ/∂(columns) = Lx S + Lp (n_constraints × columns)
};

/// A located event with the sensitivities of its time and of the state there.
struct SensitivityEventHit {
    std::string name;
    double t = 0;
    Eigen::VectorXd x;
    Eigen::MatrixXd S;       ///< ∂x/∂(columns) at fixed t = t*
    Eigen::RowVectorXd dt;   ///< ∂t⁎/∂(columns) = −g_x S / (g_t + g_x ẋ) (g does not depend on p)
    Eigen::MatrixXd dx;      ///< the total derivative of the state at the event, S + ẋ dt
};

/// What integrate_sensitivities returns: integrate()'s result for the state, with S beside it.
struct SensitivityResult {
    double t = 0;
    Eigen::VectorXd x;
    Eigen::MatrixXd S;
    std::vector<SensitivitySample> samples;
    SensitivitySample end;  ///< where the run ended (t, x, S as above) with the outputs' and multipliers' sensitivities
    std::vector<SensitivityEventHit> events;
    /// In time order, where the motion crossed a switching surface and S jumped by the saltation matrix (the surface
    /// and the time), began or ended sliding along one ("<surface>: slides", "<surface>: leaves to s > 0") and
    /// grazed one without crossing it ("<surface>: grazes", grazing.hpp: no derivative exists there in general).
    std::vector<std::pair<std::string, double>> switches;
    StopReason stop_reason = StopReason::ReachedEnd;
    std::string stopped_by;
    std::size_t accepted_steps = 0, rejected_steps = 0, rhs_evaluations = 0;
    std::size_t jacobian_evaluations = 0;  ///< of J and Jp (each rhs evaluation of the augmented system has one)
};

}  // namespace eomgen
