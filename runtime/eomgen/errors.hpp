/** @file errors.hpp  Errors the runtime and the generated code report: where in time and state it went wrong. */
#pragma once

#include <Eigen/Core>

#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace eomgen {

/// A scalar's value as a double for messages: the number itself, or the value of an automatic-differentiation
/// scalar (Eigen::AutoDiffScalar and the like, through .value()), so that the runtime and generated code
/// compile for such scalars (a Jacobian by forward differentiation: linearize.hpp).
template <class S>
double value_of(const S& x) {
    if constexpr (std::is_arithmetic_v<S>)
        return static_cast<double>(x);
    else if constexpr (std::is_convertible_v<S, double>)
        return static_cast<double>(x);
    else
        return value_of(x.value());
}

/// Base of every simulation error; what() carries the time and the state.
class SimulationError : public std::runtime_error {
public:
    SimulationError(const std::string& what, double t) : std::runtime_error(what), t_(t) {}
    double t() const { return t_; }

private:
    double t_;
};

/// M(q,t) is not positive definite (singular or indefinite) at this state.
class SingularMassMatrix : public SimulationError {
public:
    using SimulationError::SimulationError;
};

/// The state or its derivative has become NaN or infinite.
class NonFiniteState : public SimulationError {
public:
    using SimulationError::SimulationError;
};

/// The adaptive step size fell below the smallest step allowed.
class StepSizeUnderflow : public SimulationError {
public:
    using SimulationError::SimulationError;
};

/// The integrator took more steps than allowed.
class TooManySteps : public SimulationError {
public:
    using SimulationError::SimulationError;
};

/// The constraints' Jacobian A has lost rank at this state (redundant or singular constraints), so
/// the multipliers are not determined.
class SingularConstraints : public SimulationError {
public:
    using SimulationError::SimulationError;
};

/// Initial conditions that violate a constraint (the message names it).
class InconsistentInitialConditions : public SimulationError {
public:
    using SimulationError::SimulationError;
};

/// Formats "message at t = ... with state [...]" at full precision.
template <class Scalar, class Derived>
std::string describe_state(const std::string& message, const Scalar& t, const Eigen::MatrixBase<Derived>& x) {
    std::ostringstream os;
    os << std::setprecision(std::numeric_limits<double>::max_digits10) << message << " at t = " << value_of(t)
       << " with state [";
    for (Eigen::Index i = 0; i < x.size(); ++i) os << (i ? ", " : "") << value_of(x(i));
    os << "]";
    return os.str();
}

}  // namespace eomgen
