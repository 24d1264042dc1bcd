/** @file exam_adams_models.cpp  The Adams stepper on a generated model: evaluations to a given accuracy on
 * the 5-20 pendulum against DOP853 (the door's closing time is in tests/physics/exam_door.cpp). */
#include "eomgen/integrate.hpp"
#include "eomgen/models/pendulum_5_20.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace {

template <class Scalar>
using Pendulum = eomgen::models::pendulum_5_20::Model<Scalar>;

/// One run of the 5-20 pendulum from its default state to t_end: the error at the end against `reference`
/// and the evaluations of f it took.
struct Cost {
    double rtol, error;
    std::size_t rhs_evaluations;
};

template <template <class> class Method>
Cost pendulum_run(double rtol, double t_end, const Pendulum<double>::State& reference) {
    using P = Pendulum<double>;
    const P::Params p;
    auto f = [&p](const double& t, const P::State& x, P::State& xdot) { P::rhs(t, x, p, xdot); };
    typename Method<P::State>::Options opt;
    opt.rtol = rtol;
    opt.atol = rtol * 1e-2;
    const auto r = eomgen::integrate_with<Method>(f, 0.0, P::default_state(), t_end, opt);
    return {rtol, (r.x - reference).template lpNorm<Eigen::Infinity>(), r.rhs_evaluations};
}

/// The fewest evaluations among `runs` whose error is at most `target` (0 when none reaches it).
std::size_t cheapest_to(const std::vector<Cost>& runs, double target) {
    std::size_t best = 0;
    for (const Cost& c : runs)
        if (c.error <= target && (best == 0 || c.rhs_evaluations < best)) best = c.rhs_evaluations;
    return best;
}

}  // namespace

TEST_CASE("Adams reaches 1e-8 and 1e-10 on the 5-20 pendulum with fewer evaluations than DOP853",
          "[runtime][adams][pendulum_5_20]") {
    // The reference: the same generated model in long double, DOP853 at rtol 1e-18 (an independent method
    // at a precision neither double run can reach). Each method runs over a grid of tolerances (atol =
    // rtol/100); the cheapest run whose error at t = 10 is within the target counts, as in a
    // work-precision diagram.
    const double t_end = 10;
    using PL = Pendulum<long double>;
    const PL::Params pl;
    auto fl = [&pl](const long double& t, const PL::State& x, PL::State& xdot) { PL::rhs(t, x, pl, xdot); };
    eomgen::Dop853Options<long double> ref_opt;
    ref_opt.rtol = 1e-18L;
    ref_opt.atol = 1e-20L;
    const auto ref =
        eomgen::integrate_dop853(fl, 0.0L, PL::default_state(), static_cast<long double>(t_end), ref_opt);
    const Pendulum<double>::State reference = ref.x.cast<double>();

    std::vector<Cost> adams, dop853;
    for (int i = 10; i <= 28; ++i) {
        const double rtol = std::pow(10.0, -0.5 * i);  // 1e-5 … 1e-14
        adams.push_back(pendulum_run<eomgen::Adams>(rtol, t_end, reference));
        dop853.push_back(pendulum_run<eomgen::Dop853>(rtol, t_end, reference));
        INFO("rtol " << rtol << ": adams error " << adams.back().error << " in "
                     << adams.back().rhs_evaluations << " f, dop853 " << dop853.back().error << " in "
                     << dop853.back().rhs_evaluations << " f");
        CHECK(adams.back().error < 1e4 * rtol);  // both converge with the tolerance
        CHECK(dop853.back().error < 1e4 * rtol);
    }
    for (const double target : {1e-8, 1e-10}) {
        const std::size_t a = cheapest_to(adams, target), d = cheapest_to(dop853, target);
        INFO("to " << target << ": adams " << a << " f, dop853 " << d << " f");
        REQUIRE(a > 0);
        REQUIRE(d > 0);
        CHECK(a < d);
    }
}
