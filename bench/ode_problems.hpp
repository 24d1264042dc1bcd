/** @file ode_problems.hpp  The work-precision problems of bench/time_integrators and bench/time_ode_peers: the door's
 * closing time (closed form), and end states against a long-double reference; a repetition timer. */
#pragma once

#include "eomgen/events.hpp"

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>

namespace eomgen::bench {

/// Runs `once` repeatedly for at least ~30 ms (at least `min_reps` times), returning the last run and the
/// fastest time in `seconds`.
template <class F>
auto timed(F&& once, double& seconds, int min_reps = 3) {
    seconds = 1e300;
    double total = 0;
    decltype(once()) r{};
    for (int rep = 0;; ++rep) {
        const auto t0 = std::chrono::steady_clock::now();
        r = once();
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        seconds = std::min(seconds, s);
        total += s;
        if (rep + 1 >= min_reps && (total >= 0.03 || rep >= 10000)) return r;
    }
}

/// The door's closing time from rest at ψ = 0 to ψ = −π/2 (Goldstein Ex. 30): √(w/(3 g sin θ)) (√π/2) Γ(1/4)/Γ(3/4).
inline double door_closing_time(double w, double g, double theta) {
    const double pi = std::acos(-1.0);
    return std::sqrt(pi) / 2 * std::tgamma(0.25) / std::tgamma(0.75) * std::sqrt(w / (3 * g * std::sin(theta)));
}

/// Where g(x) crosses zero within odeint dense-output stepper st's last step [ta, tb] (g(x(tb)) already of the
/// other sign), by eomgen's Brent root finder on calc_state, to 2 ulp of t.
template <class Dense, class G>
double locate_crossing(Dense& st, double ta, double tb, G&& g) {
    auto x = st.current_state();
    const double gb = g(x);
    st.calc_state(ta, x);
    const double ga = g(x);
    const auto g_dense = [&](double s) {
        st.calc_state(s, x);
        return g(x);
    };
    const double tol = 2 * std::numeric_limits<double>::epsilon() * std::max(std::abs(ta), std::abs(tb));
    return eomgen::find_root_brent(g_dense, ta, ga, tb, gb, tol);
}

/**
 * x(t_end) from x0 by Runge–Kutta–Fehlberg 7(8) in long double at rtol = atol = `tol`: the reference end state
 * of a problem. `rhs(t, x, xdot)` on std::array<long double, N>.
 */
template <std::size_t N, class Rhs>
std::array<long double, N> reference_end_state(Rhs&& rhs, std::array<long double, N> x, long double t_end,
                                               long double tol) {
    using S = std::array<long double, N>;
    namespace odeint = boost::numeric::odeint;
    auto sys = [&](const S& xs, S& dxdt, long double t) { rhs(t, xs, dxdt); };
    odeint::integrate_adaptive(
        odeint::make_controlled(tol, tol, odeint::runge_kutta_fehlberg78<S, long double, S, long double>()), sys, x,
        0.0L, t_end, 1e-4L);
    return x;
}

}  // namespace eomgen::bench
