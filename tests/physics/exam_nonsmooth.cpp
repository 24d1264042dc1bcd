/**
 * @file exam_nonsmooth.cpp  Models with abs and sign (docs/model_files.md, "Non-smooth functions"): the quadratic-drag
 * pendulum's energy balance, the order of the adaptive methods across its switching surface, Coulomb friction's
 * sticking against the closed form, and the generated switching() and rest linearization.
 */
#include "eomgen/integrate.hpp"
#include "eomgen/model_traits.hpp"
#include "eomgen/sliding.hpp"
#include "eomgen/models/block_on_belt.hpp"
#include "eomgen/models/damped_pendulum.hpp"
#include "eomgen/models/quadratic_drag_pendulum.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace {

using Drag = eomgen::models::quadratic_drag_pendulum::Model<double>;
using Smooth = eomgen::models::damped_pendulum::Model<double>;

/// The model's switching surfaces as EventAction::Switch events (none for a smooth model), or as nothing.
template <class M>
std::vector<eomgen::Event<typename M::State>> switches(const typename M::Params& p, bool on) {
    std::vector<eomgen::Event<typename M::State>> events;
    if constexpr (eomgen::has_switching<M>::value) {
        for (int k = 0; k < M::n_switches && on; ++k)
            events.push_back({M::switch_names[std::size_t(k)],
                              [k, &p](const double& t, const typename M::State& x) {
                                  typename M::Switches s;
                                  M::switching(t, x.template head<M::nq>(), x.template tail<M::nq>(), p, s);
                                  return s(k);
                              },
                              eomgen::EventDirection::Both, eomgen::EventAction::Switch});
    }
    return events;
}

struct Run {
    double error;  ///< |x(t_end) − reference|
    double work;   ///< right-hand sides
    std::size_t switches;
};

template <class M, template <class> class Method>
Run run(const typename M::Params& p, double rtol, bool switching, const typename M::State* reference, double t_end) {
    using State = typename M::State;
    const auto f = [&p](const double& t, const State& x, State& xdot) { M::rhs(t, x, p, xdot); };
    typename Method<State>::Options o;
    o.rtol = rtol;
    o.atol = rtol * 1e-2;
    const auto r = eomgen::integrate_with<Method>(f, 0.0, M::default_state(), t_end, o, switches<M>(p, switching));
    return {reference ? (r.x - *reference).norm() : 0.0, double(r.rhs_evaluations), r.switches.size()};
}

struct Order {
    double slope;   ///< of log(1/error) against log(work)
    double spread;  ///< max/min of error/rtol over the tolerances
};

/// The slope of log(1/error) against log(work) over the tolerances (the order the method shows), and how far
/// error/rtol strays; the reference a dop853 run at rtol 1e-14 that ends its steps at the switches.
template <class M, template <class> class Method>
Order observed_order(const typename M::Params& p, bool switching, double t_end, const std::vector<double>& rtols) {
    using State = typename M::State;
    const auto f = [&p](const double& t, const State& x, State& xdot) { M::rhs(t, x, p, xdot); };
    eomgen::Dop853Options<double> o;
    o.rtol = 1e-14;
    o.atol = 1e-16;
    const State reference = eomgen::integrate_dop853(f, 0.0, M::default_state(), t_end, o, switches<M>(p, true)).x;
    double sx = 0, sy = 0, sxx = 0, sxy = 0, lo = 1e300, hi = 0;
    for (double rtol : rtols) {
        const Run r = run<M, Method>(p, rtol, switching, &reference, t_end);
        const double x = std::log(r.work), y = -std::log(r.error);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
        lo = std::min(lo, r.error / rtol);
        hi = std::max(hi, r.error / rtol);
    }
    const double n = double(rtols.size());
    return {(n * sxy - sx * sy) / (n * sxx - sx * sx), hi / lo};
}

}  // namespace

TEST_CASE("nonsmooth: the quadratic-drag pendulum loses exactly the work of the drag", "[physics][nonsmooth]") {
    // x = (theta, theta', W) with W' = F theta', F = -k l^3 theta'|theta'| written here by hand: h(t) - h(0) = W(t).
    using State3 = Eigen::Matrix<double, 3, 1>;
    const Drag::Params p{};
    const auto f = [&p](const double& t, const State3& x, State3& xdot) {
        Drag::State y = x.head<2>(), ydot;
        Drag::rhs(t, y, p, ydot);
        const double F = -p.k * p.l * p.l * p.l * x(1) * std::abs(x(1));
        xdot << ydot, F * x(1);
    };
    const auto h = [&p](const State3& x) {
        return Drag::energy(0.0, x.head<1>(), x.segment<1>(1), p);
    };
    std::vector<eomgen::Event<State3>> events = {
        {"abs(theta')", [](const double&, const State3& x) { return x(1); }, eomgen::EventDirection::Both,
         eomgen::EventAction::Switch}};
    std::vector<double> times;
    for (int i = 0; i <= 400; ++i) times.push_back(20.0 * i / 400);
    const State3 x0(Drag::default_state()(0), Drag::default_state()(1), 0.0);
    eomgen::Dopri5Options<double> o;
    o.rtol = 1e-12;
    o.atol = 1e-14;
    const auto r = eomgen::integrate(f, 0.0, x0, 20.0, o, events, times);
    double worst = 0;
    for (const auto& s : r.samples) worst = std::max(worst, std::abs(h(s.x) - h(x0) - s.x(2)));
    INFO("h lost " << h(x0) - h(r.x) << ", work of drag " << -r.x(2) << ", " << r.switches.size()
                   << " switches; largest |h - h0 - W| " << worst);
    CHECK(r.switches.size() >= 10);
    CHECK(h(x0) - h(r.x) > 1.0);  // the drag takes a good part of the energy
    CHECK(worst <= 1e-9);
}

TEST_CASE("nonsmooth: dopri5 and dop853 keep their order across the switches of abs(theta')", "[physics][nonsmooth]") {
    // Over rtol 1e-5 … 1e-10 on 20 s (19 switches): the slope of log(1/error) against log(work), beside the same
    // pendulum with linear drag (smooth), and how far error/rtol strays (tolerance proportionality). Measured on
    // the commit that added this test (docs/integrators.md, "Switching surfaces"): the slopes and spreads are in
    // the test's output with -s.
    const Drag::Params drag{};
    const Smooth::Params smooth{};
    const std::vector<double> rtols = {1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
    const auto check = [&](auto smooth_order, auto switching_order, auto straddling_order, const char* method) {
        const Order s = smooth_order(), on = switching_order(), off = straddling_order();
        INFO(method << ": order smooth " << s.slope << ", switching " << on.slope << ", straddling " << off.slope
                    << "; error/rtol spread " << s.spread << ", " << on.spread << ", " << off.spread);
        CHECK(on.slope >= s.slope - 0.75);  // (higher is no loss: the switches' fixed cost weighs on loose rtol)
        CHECK(on.spread <= 3.0);
    };
    check([&] { return observed_order<Smooth, eomgen::Dopri5>(smooth, false, 20.0, rtols); },
          [&] { return observed_order<Drag, eomgen::Dopri5>(drag, true, 20.0, rtols); },
          [&] { return observed_order<Drag, eomgen::Dopri5>(drag, false, 20.0, rtols); }, "dopri5");
    check([&] { return observed_order<Smooth, eomgen::Dop853>(smooth, false, 20.0, rtols); },
          [&] { return observed_order<Drag, eomgen::Dop853>(drag, true, 20.0, rtols); },
          [&] { return observed_order<Drag, eomgen::Dop853>(drag, false, 20.0, rtols); }, "dop853");
}

TEST_CASE("nonsmooth: the block on a belt sticks and slips at the closed form's times", "[physics][nonsmooth]") {
    // m x'' = -k x + mu m g sign(v - x'), from rest at x = 0: it slips forward, x = x_e (1 - cos w t) with
    // x_e = mu m g / k, until x' = v at t1 = asin(v / (x_e w)) / w; it rides the belt (x' = v: both sides of the
    // surface push into it while |k x| < mu m g) until x = x_e at t2 = t1 + x_e cos(w t1) / v; then it slips back,
    // x = x_e + (v / w) sin w (t - t2), touching the belt's speed again only tangentially.
    using M = eomgen::models::block_on_belt::Model<double>;
    using State = M::State;
    const M::Params p{};
    const double xe = p.mu * p.m * p.g / p.k, w = std::sqrt(p.k / p.m);
    const double t1 = std::asin(p.v / (xe * w)) / w;
    const double t2 = t1 + xe * std::cos(w * t1) / p.v;
    const auto f = [&p](const double& t, const State& x, State& xdot) { M::rhs(t, x, p, xdot); };
    eomgen::Dop853Options<double> o;
    o.rtol = 1e-12;
    o.atol = 1e-14;
    std::vector<double> times;
    for (int i = 0; i <= 200; ++i) times.push_back(2.0 * i / 200);
    const auto r = eomgen::integrate_sliding<eomgen::Dop853>(f, 0.0, M::default_state(), 2.0, o, switches<M>(p, true),
                                                             times);
    REQUIRE(r.events.size() == 2);
    INFO("slides at " << r.events[0].t << " (closed form " << t1 << "), leaves at " << r.events[1].t << " (" << t2
                      << ")");
    CHECK(r.events[0].name == "sign(v - x'): slides");
    CHECK(r.events[1].name == "sign(v - x'): leaves to s > 0");
    CHECK(std::abs(r.events[0].t - t1) <= 1e-9);
    CHECK(std::abs(r.events[1].t - t2) <= 1e-9);
    double worst = 0;
    for (const auto& s : r.samples) {
        double x;
        if (s.t <= t1)
            x = xe * (1 - std::cos(w * s.t));
        else if (s.t <= t2)
            x = xe * (1 - std::cos(w * t1)) + p.v * (s.t - t1);
        else
            x = xe + p.v / w * std::sin(w * (s.t - t2));
        worst = std::max(worst, std::abs(s.x(0) - x));
    }
    INFO("largest |x - closed form| at the samples: " << worst);
    CHECK(r.samples.size() == times.size());
    CHECK(worst <= 1e-9);
}

TEST_CASE("nonsmooth: a kink is no place to slide, and a switch event restarts every adaptive method", "[physics][nonsmooth]") {
    // abs(theta') is continuous: both sides carry the motion across (no sliding), whatever the method.
    const Drag::Params p{};
    const auto f = [&p](const double& t, const Drag::State& x, Drag::State& xdot) { Drag::rhs(t, x, p, xdot); };
    eomgen::AdamsOptions<double> a;
    a.rtol = 1e-10;
    a.atol = 1e-12;
    const auto adams = eomgen::integrate_sliding<eomgen::Adams>(f, 0.0, Drag::default_state(), 20.0, a,
                                                                switches<Drag>(p, true));
    eomgen::Dopri5Options<double> d;
    d.rtol = 1e-10;
    d.atol = 1e-12;
    const auto dopri = eomgen::integrate_sliding<eomgen::Dopri5>(f, 0.0, Drag::default_state(), 20.0, d,
                                                                 switches<Drag>(p, true));
    CHECK(adams.events.empty());
    CHECK(dopri.events.empty());
    CHECK(adams.switches.size() == dopri.switches.size());
    REQUIRE(!adams.switches.empty());
    for (std::size_t i = 0; i < adams.switches.size() && i < dopri.switches.size(); ++i)
        CHECK(std::abs(adams.switches[i].t - dopri.switches[i].t) <= 1e-7);
    CHECK((adams.x - dopri.x).norm() <= 1e-7);
}

TEST_CASE("nonsmooth: the generated code of abs and sign in long double and under forward differentiation",
          "[physics][nonsmooth]") {
    // long double: the same rhs as double at a state on either side of each surface.
    using DragL = eomgen::models::quadratic_drag_pendulum::Model<long double>;
    using Belt = eomgen::models::block_on_belt::Model<double>;
    using BeltL = eomgen::models::block_on_belt::Model<long double>;
    for (double v : {-0.7, 0.4}) {
        Drag::State x(0.3, v), xdot;
        DragL::State xl(0.3L, static_cast<long double>(v)), xdotl;
        Drag::rhs(0.0, x, Drag::Params{}, xdot);
        DragL::rhs(0.0L, xl, DragL::Params{}, xdotl);
        CHECK(std::abs(double(xdotl(1)) - xdot(1)) <= 1e-15 * (1 + std::abs(xdot(1))));
        Belt::State y(0.1, v), ydot;
        BeltL::State yl(0.1L, static_cast<long double>(v)), ydotl;
        Belt::rhs(0.0, y, Belt::Params{}, ydot);
        BeltL::rhs(0.0L, yl, BeltL::Params{}, ydotl);
        CHECK(std::abs(double(ydotl(1)) - ydot(1)) <= 1e-15 * (1 + std::abs(ydot(1))));
        // power() = dh/dt = Q theta' = -k l^3 theta'^2 |theta'| by hand.
        const Drag::Params pp{};
        CHECK(std::abs(Drag::power(0.0, x.head<1>(), x.tail<1>(), pp) + pp.k * std::pow(pp.l, 3) * v * v * std::abs(v)) <=
              1e-15);
        // x'' = -g/l sin(theta) - k l/m theta'|theta'|: d/dtheta' = -2 k l/m |theta'| by hand, against AD.
        Eigen::Matrix<double, 2, 2> A;
        Eigen::Matrix<double, 2, Drag::n_params> B;
        const Drag::Params p{};
        Drag::linearization(0.0, x, p, A, B);
        CHECK(std::abs(A(1, 1) - (-2 * p.k * p.l / p.m * std::abs(v))) <= 1e-14);
        // The belt's friction is flat away from x' = v: its derivative there is 0, and the spring's -k/m remains.
        Eigen::Matrix<double, 2, 2> Ab;
        Eigen::Matrix<double, 2, Belt::n_params> Bb;
        Belt::linearization(0.0, y, Belt::Params{}, Ab, Bb);
        CHECK(Ab(1, 1) == 0.0);
        CHECK(Ab(1, 0) == Approx(-Belt::Params{}.k / Belt::Params{}.m));
    }
}
