/** @file exam_ensemble.cpp  eomgen::ensemble on generated models linked in: the door's closing time over a θ grid
 * against the closed form, the same results for any number of threads, failed members as results. */
#include "eomgen/ensemble.hpp"
#include "eomgen/models/door.hpp"
#include "eomgen/models/pendulum.hpp"

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>
#include <vector>

namespace {

using Door = eomgen::models::door::Model<double>;
using Pendulum = eomgen::models::pendulum::Model<double>;
const double kPi = std::acos(-1.0);

/// Δt = √(w/(3 g sin θ)) ∫₀^{π/2} dψ/√(sin ψ), the integral (√π/2) Γ(1/4)/Γ(3/4) (README: 1.5138456348·√(w/(g sin θ))).
double closing_time(double w, double g, double theta) {
    return std::sqrt(kPi) / 2 * std::tgamma(0.25) / std::tgamma(0.75) * std::sqrt(w / (3 * g * std::sin(theta)));
}

double theta_of(std::size_t i) { return 0.02 + 0.05 * double(i); }  // 0.02 … 1.57 for i < 32

eomgen::EnsembleOptions closing_options(unsigned threads) {
    eomgen::EnsembleOptions o;
    o.simulation.until = "psi=-pi/2";
    o.simulation.t_end = 100;
    o.simulation.rtol = 1e-12;
    o.simulation.atol = 1e-15;
    o.threads = threads;
    return o;
}

std::vector<eomgen::MemberResult<Door>> door_closings(std::size_t n, unsigned threads, std::size_t chunk = 0) {
    std::vector<eomgen::MemberResult<Door>> rows;
    eomgen::EnsembleOptions o = closing_options(threads);
    o.chunk = chunk;
    eomgen::ensemble<Door>(
        n,
        [](std::size_t i) {
            eomgen::Member<Door> m;
            m.params.theta = theta_of(i);
            return m;
        },
        o, [&rows](const eomgen::MemberResult<Door>& r) { rows.push_back(r); });
    return rows;
}

/// Every double of a result, as bytes: "identical" means bit for bit.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("ensemble: the door's closing time over a theta grid matches the closed form to 1e-9",
          "[runtime][ensemble][door]") {
    const auto rows = door_closings(32, 2);
    REQUIRE(rows.size() == 32);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const auto& r = rows[i];
        INFO("member " << i << ", theta " << theta_of(i) << ": " << r.error);
        REQUIRE(r.index == i);
        REQUIRE(r.ok);
        REQUIRE(r.stopped_by == "psi=-pi/2");
        const Door::Params p;  // w and g at their defaults
        REQUIRE(std::abs(r.t / closing_time(p.w, p.g, theta_of(i)) - 1) <= 1e-9);
        REQUIRE(r.x(0) == Approx(-kPi / 2).epsilon(1e-12));
        // The declared output v_edge = w ψ̇ and h at the end, from energy conservation: ψ̇ = −√(3 g sin θ / w).
        REQUIRE(r.outputs(1) == Approx(-p.w * std::sqrt(3 * p.g * std::sin(theta_of(i)) / p.w)).epsilon(1e-9));
        REQUIRE(r.energy == Approx(p.m * p.g / 2 * p.h * std::cos(theta_of(i))).epsilon(1e-9));
    }
}

TEST_CASE("ensemble: 1, 2 and 4 threads and any chunk give the same results bit for bit, in member order",
          "[runtime][ensemble]") {
    const auto one = door_closings(40, 1);
    for (const auto& [threads, chunk] : {std::pair<unsigned, std::size_t>{2, 0}, {4, 0}, {4, 1}, {3, 7}}) {
        INFO(threads << " threads, chunk " << chunk);
        const auto other = door_closings(40, threads, chunk);
        REQUIRE(other.size() == one.size());
        for (std::size_t i = 0; i < one.size(); ++i) {
            REQUIRE(other[i].index == i);
            REQUIRE(same_bits(other[i].t, one[i].t));
            REQUIRE(same_bits(other[i].x(0), one[i].x(0)));
            REQUIRE(same_bits(other[i].x(1), one[i].x(1)));
            REQUIRE(same_bits(other[i].energy, one[i].energy));
        }
    }
}

TEST_CASE("ensemble: a member with a singular mass matrix is a failed result, the others run", "[runtime][ensemble]") {
    // Members 3 and 5 have m = 0: M = m l² is singular at t = 0.
    std::vector<eomgen::MemberResult<Pendulum>> rows;
    eomgen::EnsembleOptions o;
    o.simulation.t_end = 1;
    o.threads = 2;
    o.chunk = 1;
    eomgen::ensemble<Pendulum>(
        8,
        [](std::size_t i) {
            eomgen::Member<Pendulum> m;
            if (i == 3 || i == 5) m.params.m = 0;
            return m;
        },
        o, [&rows](const eomgen::MemberResult<Pendulum>& r) { rows.push_back(r); });
    REQUIRE(rows.size() == 8);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        INFO("member " << i);
        REQUIRE(rows[i].index == i);
        if (i == 3 || i == 5) {
            REQUIRE_FALSE(rows[i].ok);
            REQUIRE(rows[i].t == 0);
            REQUIRE(rows[i].error.find("singular") != std::string::npos);
        } else {
            REQUIRE(rows[i].ok);
            REQUIRE(rows[i].t == 1);
            REQUIRE(rows[i].stopped_by.empty());
            REQUIRE(rows[i].error.empty());
        }
    }
}

TEST_CASE("ensemble: a member too stiff for the step budget is a failed result with its time", "[runtime][ensemble]") {
    // g = 1e12 makes the pendulum swing at ω ≈ 1e6 rad/s: 1000 steps end long before t_end = 1.
    std::vector<eomgen::MemberResult<Pendulum>> rows;
    eomgen::EnsembleOptions o;
    o.simulation.t_end = 1;
    o.simulation.max_steps = 1000;
    eomgen::ensemble<Pendulum>(
        2,
        [](std::size_t i) {
            eomgen::Member<Pendulum> m;
            if (i == 1) m.params.g = 1e12;
            return m;
        },
        o, [&rows](const eomgen::MemberResult<Pendulum>& r) { rows.push_back(r); });
    REQUIRE(rows.size() == 2);
    REQUIRE(rows[0].ok);
    REQUIRE_FALSE(rows[1].ok);
    REQUIRE(rows[1].t > 0);
    REQUIRE(rows[1].t < 1e-3);
    REQUIRE(rows[1].error.find("max_steps = 1000") != std::string::npos);
}

TEST_CASE("ensemble: options no member can take are refused before any member runs", "[runtime][ensemble]") {
    int made = 0;
    auto count = [&made](std::size_t) {
        ++made;
        return eomgen::Member<Door>{};
    };
    auto ignore = [](const eomgen::MemberResult<Door>&) {};
    eomgen::EnsembleOptions o;
    o.simulation.until = "psy=0";
    REQUIRE_THROWS_WITH(eomgen::ensemble<Door>(4, count, o, ignore),
                        Catch::Contains("no state 'psy'; did you mean 'psi'"));
    o.simulation.until = "";
    o.simulation.t_end = -1;
    REQUIRE_THROWS_AS(eomgen::ensemble<Door>(4, count, o, ignore), eomgen::sim::UsageError);
    REQUIRE(made == 0);
}

TEST_CASE("ensemble: what member() throws ends the ensemble and is rethrown", "[runtime][ensemble]") {
    eomgen::EnsembleOptions o;
    o.threads = 2;
    o.chunk = 1;
    o.simulation.t_end = 0.1;
    std::size_t delivered = 0;
    REQUIRE_THROWS_WITH(eomgen::ensemble<Door>(
                            100,
                            [](std::size_t i) {
                                if (i == 7) throw std::runtime_error("no member 7");
                                return eomgen::Member<Door>{};
                            },
                            o, [&delivered](const eomgen::MemberResult<Door>&) { ++delivered; }),
                        "no member 7");
    REQUIRE(delivered <= 7);  // nothing after the missing member reaches the sink
}

TEST_CASE("ensemble: results delivered in order while the sink runs outside the lock, with a bounded buffer",
          "[runtime][ensemble]") {
    // Four threads file indices 0 … 3999 in chunks of 5 (so out of order) into a buffer of at most 8; the
    // sink sleeps now and then, so threads arrive while it runs. Every index reaches the sink once, in order,
    // never two sink calls at a time, and nothing deadlocks on the bound.
    std::vector<std::size_t> seen;
    std::atomic<int> inside{0};
    bool overlapped = false;
    auto sink = [&](const std::size_t& i) {
        if (inside.fetch_add(1) != 0) overlapped = true;
        if (i % 97 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
        seen.push_back(i);
        inside.fetch_sub(1);
    };
    eomgen::InOrder<std::size_t, decltype(sink)> in_order(0, sink, 8);
    eomgen::for_each_index(0, 4000, 4, 5, [&](std::size_t i) { in_order.put(i, i); });
    REQUIRE_FALSE(overlapped);
    REQUIRE(seen.size() == 4000);
    for (std::size_t i = 0; i < seen.size(); ++i) REQUIRE(seen[i] == i);
    REQUIRE(in_order.next() == 4000);
}

TEST_CASE("ensemble: a sink that throws ends the ensemble without leaving a thread waiting for room",
          "[runtime][ensemble]") {
    std::size_t delivered = 0;
    auto sink = [&](const std::size_t& i) {
        if (i == 50) throw std::runtime_error("disk full at row 50");
        ++delivered;
    };
    eomgen::InOrder<std::size_t, decltype(sink)> in_order(0, sink, 4);
    REQUIRE_THROWS_WITH(eomgen::for_each_index(0, 10000, 3, 2, [&](std::size_t i) { in_order.put(i, i); }),
                        "disk full at row 50");
    REQUIRE(delivered == 50);
}
