// The member integrators of CUDA ensembles (device_ensemble.hpp), compiled here by the C++ compiler: the same
// steps, solve and event location as the runtime's integrate_rk4 and Dopri5, so their results must be the
// runtime's (to round-off for RK4, whose rhs differs; bit for bit for the adaptive pair on the same rhs); the
// door's closing times against the closed form; failures as statuses.
#include "eomgen/device_ensemble.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/models/door.hpp"
#include "eomgen/models/heavy_symmetric_top.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace {

using Door = eomgen::models::door::Model<double>;
using Top = eomgen::models::heavy_symmetric_top::Model<double>;
using eomgen::device::Status;

const double kPi = std::acos(-1.0);

template <class M>
eomgen::IntegrationResult<typename M::State> runtime_rk4(const typename M::Params& p, const typename M::State& x0,
                                                         double t_end, double dt, int index, double value) {
    auto f = [&p](const double& t, const typename M::State& x, typename M::State& xdot) { M::rhs(t, x, p, xdot); };
    std::vector<eomgen::Event<typename M::State>> events;
    if (index >= 0)
        events.push_back({"e", [index, value](const double&, const typename M::State& x) { return x(index) - value; },
                          eomgen::EventDirection::Both, eomgen::EventAction::Stop});
    return eomgen::integrate_rk4(f, 0.0, x0, t_end, dt, events);
}

}  // namespace

TEST_CASE("device ensemble: the door's closing times are the runtime's RK4 and the closed form's", "[device]") {
    for (int k = 1; k <= 12; ++k) {
        Door::Params p;
        p.theta = 0.02 + (kPi / 2 - 0.02) * k / 12;
        const Door::State x0 = Door::default_state();
        const auto member = eomgen::device::integrate_member_rk4<Door>(p, x0, 20.0, 1e-3, {0, -kPi / 2});
        const auto cpu = runtime_rk4<Door>(p, x0, 20.0, 1e-3, 0, -kPi / 2);
        INFO("theta = " << p.theta);
        REQUIRE(member.status == Status::Event);
        REQUIRE(cpu.stop_reason == eomgen::StopReason::TerminalEvent);
        CHECK(std::abs(member.t - cpu.t) <= 1e-13 * cpu.t);
        CHECK((member.x - cpu.x).cwiseAbs().maxCoeff() <= 1e-12);
        const double closed = 1.5138456348 * std::sqrt(p.w / (p.g * std::sin(p.theta)));
        CHECK(std::abs(member.t - closed) <= 1e-9 * closed);
    }
}

TEST_CASE("device ensemble: the heavy top to t_end is the runtime's RK4 to round-off", "[device]") {
    Top::Params p;
    Top::State x0 = Top::default_state();
    const auto member = eomgen::device::integrate_member_rk4<Top>(p, x0, 3.0, 1e-3, {});
    const auto cpu = runtime_rk4<Top>(p, x0, 3.0, 1e-3, -1, 0);
    REQUIRE(member.status == Status::Ok);
    CHECK(member.t == cpu.t);
    CHECK((member.x - cpu.x).cwiseAbs().maxCoeff() <= 1e-11 * (1 + cpu.x.cwiseAbs().maxCoeff()));
}

TEST_CASE("device ensemble: a solve that fails and a state that blows up are statuses, not NaN", "[device]") {
    Door::Params massless;
    massless.m = 0;
    const auto singular = eomgen::device::integrate_member_rk4<Door>(massless, Door::default_state(), 1.0, 1e-2, {});
    CHECK(singular.status == Status::Singular);
    CHECK(singular.t == 0.0);

    Door::Params p;
    Door::State x0 = Door::default_state();
    x0(1) = 1e308;  // k1 + 2 (k2 + k3) + k4 overflows in the first step
    const auto blown = eomgen::device::integrate_member_rk4<Door>(p, x0, 1.0, 1e-2, {});
    CHECK(blown.status == Status::NonFinite);
    CHECK(blown.x.allFinite());  // the last finite state, at the t it was reached
}

namespace {

/// The host's Dopri5 through integrate(), on the member integrator's own right-hand side (dynamics() and the
/// L D Lᵀ in registers), with its options: the same arithmetic, so the same steps bit for bit.
template <class M>
eomgen::IntegrationResult<typename M::State> runtime_dopri5(const typename M::Params& p, const typename M::State& x0,
                                                            double t_end, const eomgen::Dopri5Options<double>& o,
                                                            int index, double value) {
    bool ok = true;
    const eomgen::device::Rhs<M> rhs{&p, &ok};
    auto f = [&](const double& t, const typename M::State& x, typename M::State& xdot) {
        rhs(t, x, xdot);
        if (!ok) throw std::runtime_error("singular M");
    };
    std::vector<eomgen::Event<typename M::State>> events;
    if (index >= 0)
        events.push_back({"e", [index, value](const double&, const typename M::State& x) { return x(index) - value; },
                          eomgen::EventDirection::Both, eomgen::EventAction::Stop});
    return eomgen::integrate(f, 0.0, x0, t_end, o, events);
}

eomgen::Dopri5Options<double> tolerances(double rtol, double atol) {
    eomgen::Dopri5Options<double> o;
    o.rtol = rtol;
    o.atol = atol;
    return o;
}

}  // namespace

TEST_CASE("device ensemble: the adaptive pair closes the door where the runtime's Dopri5 does, bit for bit",
          "[device]") {
    for (int k = 1; k <= 12; ++k) {
        Door::Params p;
        p.theta = 0.02 + (kPi / 2 - 0.02) * k / 12;
        const Door::State x0 = Door::default_state();
        const auto o = tolerances(1e-12, 1e-14);
        const auto member = eomgen::device::integrate_member_dopri5<Door>(p, x0, 20.0, o, {0, -kPi / 2});
        const auto cpu = runtime_dopri5<Door>(p, x0, 20.0, o, 0, -kPi / 2);
        INFO("theta = " << p.theta);
        REQUIRE(member.status == Status::Event);
        REQUIRE(cpu.stop_reason == eomgen::StopReason::TerminalEvent);
        CHECK(member.t == cpu.t);
        CHECK(member.x == cpu.x);
        // and against the runtime's own rhs (solve_mass_matrix) and the closed form
        const double closed = 1.5138456348 * std::sqrt(p.w / (p.g * std::sin(p.theta)));
        CHECK(std::abs(member.t - closed) <= 1e-9 * closed);
    }
}

TEST_CASE("device ensemble: the adaptive pair integrates the heavy top to t_end as the runtime's Dopri5 does",
          "[device]") {
    Top::Params p;
    const Top::State x0 = Top::default_state();
    for (double rtol : {1e-6, 1e-10}) {
        const auto o = tolerances(rtol, 1e-3 * rtol);
        const auto member = eomgen::device::integrate_member_dopri5<Top>(p, x0, 3.0, o, {});
        const auto cpu = runtime_dopri5<Top>(p, x0, 3.0, o, -1, 0);
        INFO("rtol = " << rtol);
        REQUIRE(member.status == Status::Ok);
        CHECK(member.t == 3.0);
        CHECK(member.x == cpu.x);
        // The energy is conserved to the tolerance's order.
        const auto energy = [&p](const Top::State& x) {
            Top::Config q = x.head<Top::nq>(), qd = x.tail<Top::nq>();
            return Top::energy(0.0, q, qd, p);
        };
        CHECK(std::abs(energy(member.x) - energy(x0)) <= 100 * rtol * (1 + std::abs(energy(x0))));
    }
}

TEST_CASE("device ensemble: the adaptive pair's failures are statuses at the last accepted point", "[device]") {
    Door::Params massless;
    massless.m = 0;
    const auto singular = eomgen::device::integrate_member_dopri5<Door>(massless, Door::default_state(), 1.0,
                                                                        tolerances(1e-8, 1e-10), {});
    CHECK(singular.status == Status::Singular);
    CHECK(singular.t == 0.0);

    Door::Params p;
    auto few = tolerances(1e-12, 1e-14);
    few.max_steps = 5;
    const auto stopped = eomgen::device::integrate_member_dopri5<Door>(p, Door::default_state(), 20.0, few, {});
    CHECK(stopped.status == Status::TooManySteps);
    CHECK(stopped.t > 0.0);
    CHECK(stopped.t < 20.0);
    CHECK(stopped.x.allFinite());

    Door::State x0 = Door::default_state();
    x0(1) = std::numeric_limits<double>::infinity();
    CHECK(eomgen::device::integrate_member_dopri5<Door>(p, x0, 1.0, tolerances(1e-8, 1e-10), {}).status ==
          Status::NonFinite);
}
