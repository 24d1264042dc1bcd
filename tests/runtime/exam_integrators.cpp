/** @file exam_integrators.cpp  RK4 and DOPRI5 against closed-form solutions: oscillator, Kepler orbit. */
#include "../approx.hpp"
#include "closed_forms.hpp"

#include "eomgen/dopri5.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/rk4.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace {

using eomgen::test::AllClose;
using eomgen::test::kepler;
using eomgen::test::kepler_exact;
using eomgen::test::Oscillator;

template <class State>
typename State::Scalar max_error(const std::vector<eomgen::Sample<State>>& samples,
                                 const Oscillator<State>& osc, const State& x0) {
    typename State::Scalar err(0);
    for (const auto& s : samples)
        err = std::max(err, (s.x - osc.exact(s.t, x0)).template lpNorm<Eigen::Infinity>());
    return err;
}

}  // namespace

TEST_CASE("RK4 matches the oscillator and converges with order 4", "[runtime][rk4]") {
    using State = Eigen::Vector2d;
    const Oscillator<State> osc{2.0};
    const State x0(1.0, 0.5);
    double errors[3];
    const double dts[3] = {0.1, 0.05, 0.025};
    for (int i = 0; i < 3; ++i) {
        const auto result = eomgen::integrate_rk4(osc, 0.0, x0, 10.0, dts[i]);
        REQUIRE(result.t == 10.0);
        CHECK(result.accepted_steps == std::size_t(std::lround(10.0 / dts[i])));
        CHECK(result.rhs_evaluations == 4 * result.accepted_steps + 1);
        errors[i] = (result.x - osc.exact(10.0, x0)).lpNorm<Eigen::Infinity>();
    }
    const double order1 = std::log2(errors[0] / errors[1]), order2 = std::log2(errors[1] / errors[2]);
    INFO("RK4 errors " << errors[0] << " " << errors[1] << " " << errors[2] << ", orders " << order1 << " "
                       << order2);
    CHECK(order1 == Approx(4.0).margin(0.15));
    CHECK(order2 == Approx(4.0).margin(0.15));
}

TEST_CASE("RK4 grid: a remainder is a short last step ending exactly at t_end, backwards works",
          "[runtime][rk4]") {
    using State = Eigen::Vector2d;
    const Oscillator<State> osc;
    const State x0(1.0, 0.0);
    const auto r = eomgen::integrate_rk4(osc, 0.0, x0, 1.05, 0.1);
    CHECK(r.t == 1.05);
    CHECK(r.accepted_steps == 11);
    const auto back = eomgen::integrate_rk4(osc, 1.05, r.x, 0.0, 0.1);
    CHECK(back.t == 0.0);
    REQUIRE_THAT(Eigen::MatrixXd(back.x), AllClose(x0, 0, 1e-6));
}

TEST_CASE("DOPRI5 on the oscillator at tight tolerance", "[runtime][dopri5]") {
    using State = Eigen::Vector2d;
    const Oscillator<State> osc{3.0};
    const State x0(0.3, -1.0);
    eomgen::Dopri5Options<double> opts;
    opts.rtol = 1e-12;
    opts.atol = 1e-14;
    std::vector<double> times;
    for (int i = 0; i <= 100; ++i) times.push_back(0.2 * i);
    const auto r = eomgen::integrate(osc, 0.0, x0, 20.0, opts, {}, times);
    REQUIRE(r.t == 20.0);
    REQUIRE(r.samples.size() == times.size());
    const double err = max_error(r.samples, osc, x0);
    INFO("max sample error " << err << " in " << r.accepted_steps << " steps, " << r.rejected_steps
                             << " rejected");
    CHECK(err < 1e-10);
    CHECK(r.stop_reason == eomgen::StopReason::ReachedEnd);
    CHECK(r.stopped_by.empty());
    // FSAL: six new evaluations per attempted step, plus f(t0) and the initial-step probe.
    CHECK(r.rhs_evaluations == 6 * (r.accepted_steps + r.rejected_steps) + 2);
}

TEST_CASE("DOPRI5 on a Kepler orbit (e = 0.5) over two periods, fixed and dynamic state",
          "[runtime][dopri5]") {
    const double e = 0.5, period = 2 * std::acos(-1.0);
    eomgen::Dopri5Options<double> opts;
    opts.rtol = 1e-12;
    opts.atol = 1e-14;
    std::vector<double> times;
    for (int i = 0; i <= 40; ++i) times.push_back(i * period / 20);
    const Eigen::Vector4d x0 = kepler_exact(0.0, e);
    const auto r = eomgen::integrate(kepler<Eigen::Vector4d>, 0.0, x0, 2 * period, opts, {}, times);
    double err = 0;
    for (const auto& s : r.samples)
        err = std::max(err, (s.x - kepler_exact(s.t, e)).lpNorm<Eigen::Infinity>());
    INFO("Kepler max error " << err << " in " << r.accepted_steps << " steps");
    CHECK(err < 1e-9);
    REQUIRE_THAT(Eigen::MatrixXd(r.x), AllClose(x0, 0, 1e-9));

    const Eigen::VectorXd x0d = x0;
    const auto rd = eomgen::integrate(kepler<Eigen::VectorXd>, 0.0, x0d, 2 * period, opts, {}, times);
    CHECK(rd.accepted_steps == r.accepted_steps);
    REQUIRE_THAT(Eigen::MatrixXd(rd.x), AllClose(r.x, 1e-14, 1e-14));
}

TEST_CASE("DOPRI5 dense output is accurate inside steps, with local error O(h^5)", "[runtime][dopri5]") {
    using State = Eigen::Vector2d;
    const Oscillator<State> osc;
    const State x0(1.0, 0.0);
    // Fixed step h (loose tolerance, hmax = h0 = h): the interpolation error in the middle of the first
    // step is the dense output's local error, which must shrink like h^5 for a 4th-order interpolant.
    double errs[2];
    const double hs[2] = {0.2, 0.1};
    for (int i = 0; i < 2; ++i) {
        eomgen::Dopri5Options<double> opts;
        opts.rtol = opts.atol = 1.0;
        opts.h0 = opts.hmax = hs[i];
        eomgen::Dopri5<State> stepper(osc, 0.0, x0, 1.0, opts);
        stepper.step(osc);
        REQUIRE(stepper.t() == hs[i]);
        errs[i] = 0;
        for (double th : {0.1, 0.3, 0.5, 0.7, 0.9}) {
            State x;
            stepper.dense(th * hs[i], x);
            errs[i] = std::max(errs[i], (x - osc.exact(th * hs[i], x0)).lpNorm<Eigen::Infinity>());
        }
    }
    INFO("dense local errors " << errs[0] << " " << errs[1]);
    CHECK(std::log2(errs[0] / errs[1]) > 4.6);

    // Adaptive run: mid-step dense values are as good as the step ends.
    eomgen::Dopri5Options<double> opts;
    opts.rtol = 1e-10;
    opts.atol = 1e-12;
    eomgen::Dopri5<State> stepper(osc, 0.0, x0, 10.0, opts);
    double node_err = 0, mid_err = 0;
    while (!stepper.done()) {
        stepper.step(osc);
        node_err = std::max(node_err, (stepper.x() - osc.exact(stepper.t(), x0)).lpNorm<Eigen::Infinity>());
        for (double th : {0.25, 0.5, 0.75}) {
            const double t = stepper.t_prev() + th * (stepper.t() - stepper.t_prev());
            State x;
            stepper.dense(t, x);
            mid_err = std::max(mid_err, (x - osc.exact(t, x0)).lpNorm<Eigen::Infinity>());
        }
    }
    INFO("node error " << node_err << ", mid-step error " << mid_err);
    CHECK(mid_err < 3 * node_err + 1e-11);
}

TEST_CASE("Samples come from dense output: requesting them does not change the steps", "[runtime][dopri5]") {
    using State = Eigen::Vector2d;
    const Oscillator<State> osc;
    const State x0(1.0, 0.0);
    eomgen::Dopri5Options<double> opts;
    opts.rtol = 1e-9;
    const auto plain = eomgen::integrate(osc, 0.0, x0, 10.0, opts);
    const std::vector<double> times{0.0, 0.123, 1.0, 3.3333, 5.0, 9.99, 10.0};
    const auto sampled = eomgen::integrate(osc, 0.0, x0, 10.0, opts, {}, times);
    CHECK(sampled.accepted_steps == plain.accepted_steps);
    CHECK(sampled.rhs_evaluations == plain.rhs_evaluations);
    REQUIRE(sampled.samples.size() == times.size());
    for (std::size_t i = 0; i < times.size(); ++i) {
        CHECK(sampled.samples[i].t == times[i]);
        REQUIRE_THAT(Eigen::MatrixXd(sampled.samples[i].x), AllClose(osc.exact(times[i], x0), 0, 1e-8));
    }
    CHECK(sampled.samples.front().x == x0);
    CHECK(sampled.samples.back().x == plain.x);

    // With an observer, samples stream to it; without sample times it sees every step end.
    std::vector<double> seen;
    const auto observed = eomgen::integrate(osc, 0.0, x0, 10.0, opts, {}, times,
                                            [&](const double& t, const State&) { seen.push_back(t); });
    CHECK(seen == times);
    CHECK(observed.samples.empty());
    seen.clear();
    eomgen::integrate(osc, 0.0, x0, 10.0, opts, {}, {},
                      [&](const double& t, const State&) { seen.push_back(t); });
    CHECK(seen.size() == plain.accepted_steps + 1);
    CHECK(seen.back() == 10.0);
}

TEST_CASE("DOPRI5 integrates backwards in time", "[runtime][dopri5]") {
    using State = Eigen::Vector2d;
    const Oscillator<State> osc;
    const State x0(1.0, 0.0);
    eomgen::Dopri5Options<double> opts;
    opts.rtol = 1e-11;
    opts.atol = 1e-13;
    const auto r = eomgen::integrate(osc, 5.0, osc.exact(5.0, x0), -1.0, opts, {}, {2.5, 0.0});
    CHECK(r.t == -1.0);
    REQUIRE_THAT(Eigen::MatrixXd(r.x), AllClose(osc.exact(-1.0, x0), 0, 1e-9));
    REQUIRE(r.samples.size() == 2);
    REQUIRE_THAT(Eigen::MatrixXd(r.samples[1].x), AllClose(x0, 0, 1e-9));
}

TEST_CASE("long double: DOPRI5 and RK4 reach beyond double precision", "[runtime][long double]") {
    using State = Eigen::Matrix<long double, 2, 1>;
    const Oscillator<State> osc;
    const State x0(1.0L, 0.0L);
    eomgen::Dopri5Options<long double> opts;
    opts.rtol = 1e-17L;
    opts.atol = 1e-19L;
    const long double t_end = 2 * 3.14159265358979323846264338327950288L;
    const auto r = eomgen::integrate(osc, 0.0L, x0, t_end, opts, {}, {t_end / 3});
    const long double err = (r.x - osc.exact(t_end, x0)).lpNorm<Eigen::Infinity>();
    const long double sample_err = (r.samples.at(0).x - osc.exact(t_end / 3, x0)).lpNorm<Eigen::Infinity>();
    INFO("long double DOPRI5 error " << double(err) << ", sample " << double(sample_err) << " in "
                                     << r.accepted_steps << " steps");
    CHECK(err < 1e-16L);
    CHECK(sample_err < 1e-16L);

    // RK4's order is still 4 at errors of 1e-14..1e-15, where double's rounding would blur it.
    long double errors[2];
    const long double dts[2] = {0.002L, 0.001L};
    for (int i = 0; i < 2; ++i) {
        const auto ri = eomgen::integrate_rk4(osc, 0.0L, x0, 1.0L, dts[i]);
        errors[i] = (ri.x - osc.exact(1.0L, x0)).lpNorm<Eigen::Infinity>();
    }
    const double order = double(std::log2(errors[0] / errors[1]));
    INFO("long double RK4 errors " << double(errors[0]) << " " << double(errors[1]) << ", order " << order);
    CHECK(order == Approx(4.0).margin(0.15));
}
