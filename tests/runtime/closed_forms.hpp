/** @file closed_forms.hpp  Test problems with known solutions for the integrators: oscillator, Kepler orbit.
 */
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace eomgen::test {

/// x'' = -ω² x as [x, v]; exact x = x0 cos ωt + v0/ω sin ωt.
template <class State>
struct Oscillator {
    using Scalar = typename State::Scalar;
    Scalar omega = Scalar(1);
    void operator()(const Scalar&, const State& x, State& xdot) const {
        xdot(0) = x(1);
        xdot(1) = -omega * omega * x(0);
    }
    State exact(const Scalar& t, const State& x0) const {
        using std::cos;
        using std::sin;
        State x = x0;
        x(0) = x0(0) * cos(omega * t) + x0(1) / omega * sin(omega * t);
        x(1) = -x0(0) * omega * sin(omega * t) + x0(1) * cos(omega * t);
        return x;
    }
};

/// Kepler problem, μ = 1, [x, y, vx, vy].
template <class State>
void kepler(const typename State::Scalar&, const State& x, State& xdot) {
    using std::sqrt;
    const auto r2 = x(0) * x(0) + x(1) * x(1);
    const auto r3 = r2 * sqrt(r2);
    xdot(0) = x(2);
    xdot(1) = x(3);
    xdot(2) = -x(0) / r3;
    xdot(3) = -x(1) / r3;
}

/// The exact orbit with semi-major axis 1 and eccentricity e, starting at periapsis on the +x axis,
/// from Kepler's equation M = E − e sin E (solved by Newton, independently of the integrators).
inline Eigen::Vector4d kepler_exact(double t, double e) {
    double E = t;  // mean motion n = 1 for a = μ = 1
    for (int i = 0; i < 50; ++i) E -= (E - e * std::sin(E) - t) / (1 - e * std::cos(E));
    const double b = std::sqrt(1 - e * e), Edot = 1 / (1 - e * std::cos(E));
    return {std::cos(E) - e, b * std::sin(E), -std::sin(E) * Edot, b * std::cos(E) * Edot};
}

/// The least-squares slope of log(y) against log(x): an observed order of convergence (y the error, x the step
/// or the tolerance).
inline double fitted_slope(const std::vector<double>& xs, const std::vector<double>& ys) {
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) mx += std::log(xs[i]), my += std::log(ys[i]);
    mx /= double(xs.size());
    my /= double(xs.size());
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        sxy += (std::log(xs[i]) - mx) * (std::log(ys[i]) - my);
        sxx += (std::log(xs[i]) - mx) * (std::log(xs[i]) - mx);
    }
    return sxy / sxx;
}

}  // namespace eomgen::test
