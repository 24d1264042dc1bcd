/** @file time_stiff.cpp  Radau IIA (radau5) against Dormand–Prince (dopri5) on the stiff example model. */
// Usage: time_stiff [--quick]. One JSON object per line:
//   {"problem", "method", "rtol", "error", "steps", "rhs_evals", "jacobians", "lu", "seconds"}
// then {"problem", "jacobian", "seconds_per_call"} for one Jacobian, analytic and by forward differentiation.
// Problem: examples/stiff_spring_pendulum.toml (k = 1e5, c = 1e4: radial rates 10/s and 1e4/s, swing 3.1 rad/s)
// from its default state to t = 10; error = max |x - x_ref| against dopri5 at rtol 1e-12, atol 1e-14. All
// methods at atol = rtol/100. radau5's Jacobian is model_jacobian: the generated analytic state_jacobian();
// radau5_autodiff is the same integrator with eomgen::state_jacobian (forward differentiation through rhs, AutoDiff
// scalars with n_x = 4 derivative lanes). seconds: the fastest of repeated runs (at least 3 and ~30 ms; --quick:
// one), so ratios within one run compare like with like.
#include "eomgen/integrate.hpp"
#include "eomgen/model_jacobian.hpp"
#include "eomgen/models/stiff_spring_pendulum.hpp"
#include "eomgen/radau5.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>

namespace {

using M = eomgen::models::stiff_spring_pendulum::Model<double>;
using State = M::State;
constexpr double kEnd = 10.0;

struct Run {
    State x;
    std::size_t steps = 0, rhs = 0, jacobians = 0, lu = 0;
};

template <class F>
Run timed(F&& once, bool quick, double& seconds) {
    Run r;
    seconds = 1e300;
    double total = 0;
    for (int k = 0; k < (quick ? 1 : 1000) && (k < 3 || total < 0.03); ++k) {
        const auto start = std::chrono::steady_clock::now();
        r = once();
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        seconds = std::min(seconds, s);
        total += s;
        if (quick) break;
    }
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    const M::Params p{};
    const State x0 = M::default_state();
    const auto f = [&p](const double& t, const State& x, State& xdot) { M::rhs(t, x, p, xdot); };
    const auto jac = [&p](const double& t, const State& x, Eigen::Matrix<double, M::nx, M::nx>& J) {
        eomgen::model_jacobian<M>(t, x, p, J);
    };
    const auto jac_ad = [&p](const double& t, const State& x, Eigen::Matrix<double, M::nx, M::nx>& J) {
        eomgen::state_jacobian<eomgen::models::stiff_spring_pendulum::Model>(t, x, p, J);
    };
    eomgen::Dopri5Options<double> tight;
    tight.rtol = 1e-12;
    tight.atol = 1e-14;
    tight.max_steps = 10000000;
    const State ref = eomgen::integrate(f, 0.0, x0, kEnd, tight).x;
    for (const double rtol : {1e-6, 1e-8, 1e-10}) {
        double seconds = 0;
        eomgen::Radau5Options<double> ro;
        ro.rtol = rtol;
        ro.atol = rtol * 1e-2;
        const auto radau = [&](const char* method, const auto& jacobian) {
            const Run r = timed(
                [&] {
                    const auto res = eomgen::integrate_radau5(f, jacobian, 0.0, x0, kEnd, ro);
                    return Run{res.x, res.accepted_steps, res.rhs_evaluations, res.jacobian_evaluations,
                               res.lu_decompositions};
                },
                quick, seconds);
            std::printf("{\"problem\": \"stiff_spring_pendulum\", \"method\": \"%s\", \"rtol\": %g, \"error\": %.3g, "
                        "\"steps\": %zu, \"rhs_evals\": %zu, \"jacobians\": %zu, \"lu\": %zu, \"seconds\": %.4g}\n",
                        method, rtol, (r.x - ref).cwiseAbs().maxCoeff(), r.steps, r.rhs, r.jacobians, r.lu, seconds);
        };
        radau("radau5", jac);
        radau("radau5_autodiff", jac_ad);
        eomgen::Dopri5Options<double> dopt;
        dopt.rtol = rtol;
        dopt.atol = rtol * 1e-2;
        dopt.max_steps = 10000000;
        const Run d = timed(
            [&] {
                const auto res = eomgen::integrate(f, 0.0, x0, kEnd, dopt);
                return Run{res.x, res.accepted_steps, res.rhs_evaluations, 0, 0};
            },
            quick, seconds);
        std::printf("{\"problem\": \"stiff_spring_pendulum\", \"method\": \"dopri5\", \"rtol\": %g, \"error\": %.3g, "
                    "\"steps\": %zu, \"rhs_evals\": %zu, \"jacobians\": 0, \"lu\": 0, \"seconds\": %.4g}\n",
                    rtol, (d.x - ref).cwiseAbs().maxCoeff(), d.steps, d.rhs, seconds);
    }
    // One Jacobian, analytic and by forward differentiation, at states near the initial one.
    const auto per_call = [&](const char* name, const auto& jacobian) {
        constexpr int kCalls = 20000;
        double seconds = 0, sink = 0;
        timed(
            [&] {
                Eigen::Matrix<double, M::nx, M::nx> J;
                State x = x0;
                sink = 0;  // the sum over one repetition's calls: equal for both Jacobians
                for (int k = 0; k < kCalls; ++k) {
                    x(0) = x0(0) + 1e-6 * k;  // a new state each call: nothing to hoist out of the loop
                    jacobian(0.0, x, J);
                    sink += J(3, 0);
                }
                return Run{x, 0, 0, 0, 0};
            },
            quick, seconds);
        std::printf("{\"problem\": \"stiff_spring_pendulum\", \"jacobian\": \"%s\", \"seconds_per_call\": %.4g, "
                    "\"sink\": %.6g}\n",
                    name, seconds / kCalls, sink);
    };
    per_call("analytic", jac);
    per_call("autodiff", jac_ad);
    return 0;
}
