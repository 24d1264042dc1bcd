/**
 * @file time_ensemble.cpp  Ensembles (issue 16): N door closings (--until psi=-pi/2, rtol 1e-10) over a θ grid,
 * timed in one run as ratios:
 *   - eomgen::ensemble on 1 thread against a hand-written loop over the generated header (the same
 *     integrate() call, event and tolerances): the per-member overhead of the ensemble;
 *   - eomgen::ensemble on 2 threads against 1 thread: the speed-up.
 * Each variant runs `repeats` times, interleaved, and the median is kept (the machine may be shared); beside
 * the wall time, the process's CPU time, which a busy machine disturbs less: the overhead is also given as
 * a ratio of CPU times, and 2 threads' CPU time against 1 thread's says what the threads cost in work. The
 * results of every variant are checked equal bit for bit, so the loops cannot be optimized away or differ.
 *
 * Usage: time_ensemble [N=10000] [repeats=5]. Prints one JSON object.
 */
#include "eomgen/ensemble.hpp"
#include "eomgen/models/door.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <vector>

namespace {

using Door = eomgen::models::door::Model<double>;
const double kPi = std::acos(-1.0);

double theta_of(std::size_t i, std::size_t n) { return 0.02 + (kPi / 2 - 0.02) * double(i) / double(n - 1); }

/// The hand-written loop: what an app would write over the generated header without the ensemble.
std::vector<double> hand_loop(std::size_t n) {
    std::vector<double> t(n);
    const int psi = 0;
    const double target = -kPi / 2;
    const std::vector<eomgen::Event<Door::State>> events{
        {"psi=-pi/2", [psi, target](const double&, const Door::State& x) { return x(psi) - target; },
         eomgen::EventDirection::Both, eomgen::EventAction::Stop}};
    eomgen::Dopri5Options<double> opt;
    opt.rtol = 1e-10;
    opt.atol = 1e-12;
    for (std::size_t i = 0; i < n; ++i) {
        Door::Params p;
        p.theta = theta_of(i, n);
        auto f = [&p](const double& tt, const Door::State& x, Door::State& xdot) { Door::rhs(tt, x, p, xdot); };
        t[i] = eomgen::integrate(f, 0.0, Door::default_state(), 100.0, opt, events).t;
    }
    return t;
}

std::vector<double> with_ensemble(std::size_t n, unsigned threads) {
    std::vector<double> t(n);
    eomgen::EnsembleOptions o;
    o.simulation.until = "psi=-pi/2";
    o.simulation.t_end = 100;
    o.simulation.rtol = 1e-10;
    o.simulation.atol = 1e-12;
    o.threads = threads;
    eomgen::ensemble<Door>(
        n,
        [n](std::size_t i) {
            eomgen::Member<Door> m;
            m.params.theta = theta_of(i, n);
            return m;
        },
        o, [&t](const eomgen::MemberResult<Door>& r) { t[r.index] = r.ok ? r.t : NAN; });
    return t;
}

struct Timing {
    double wall = 0, cpu = 0;
};

Timing timed(const std::function<std::vector<double>()>& f, std::vector<double>& out) {
    auto cpu_now = [] {
        timespec ts{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
        return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
    };
    const double cpu0 = cpu_now();
    const auto start = std::chrono::steady_clock::now();
    out = f();
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), cpu_now() - cpu0};
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 10000;
    const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
    if (n < 2 || repeats < 1) {
        std::fprintf(stderr, "usage: time_ensemble [N >= 2] [repeats >= 1]\n");
        return 2;
    }
    std::vector<double> reference;
    std::vector<Timing> t_hand, t_one, t_two;
    for (int r = 0; r < repeats; ++r) {
        std::vector<double> out;
        t_hand.push_back(timed([n] { return hand_loop(n); }, out));
        reference = out;
        t_one.push_back(timed([n] { return with_ensemble(n, 1); }, out));
        if (std::memcmp(out.data(), reference.data(), n * sizeof(double)) != 0) {
            std::fprintf(stderr, "time_ensemble: the ensemble on 1 thread differs from the hand-written loop\n");
            return 1;
        }
        t_two.push_back(timed([n] { return with_ensemble(n, 2); }, out));
        if (std::memcmp(out.data(), reference.data(), n * sizeof(double)) != 0) {
            std::fprintf(stderr, "time_ensemble: the ensemble on 2 threads differs from 1 thread\n");
            return 1;
        }
    }
    auto wall = [](const std::vector<Timing>& v) {
        std::vector<double> w;
        for (const Timing& t : v) w.push_back(t.wall);
        return median(w);
    };
    auto cpu = [](const std::vector<Timing>& v) {
        std::vector<double> c;
        for (const Timing& t : v) c.push_back(t.cpu);
        return median(c);
    };
    const double hand_s = wall(t_hand), one_s = wall(t_one), two_s = wall(t_two);
    std::printf("{\"members\": %zu, \"repeats\": %d, \"hand_loop_s\": %.6f, \"ensemble_1_thread_s\": %.6f, "
                "\"ensemble_2_threads_s\": %.6f, \"hand_loop_cpu_s\": %.6f, \"ensemble_1_thread_cpu_s\": %.6f, "
                "\"ensemble_2_threads_cpu_s\": %.6f, \"overhead_1_thread\": %.4f, \"overhead_1_thread_cpu\": %.4f, "
                "\"speedup_2_threads\": %.3f, \"cpu_2_threads_over_1\": %.3f, \"members_per_cpu_s\": %.0f, "
                "\"cores\": %u}\n",
                n, repeats, hand_s, one_s, two_s, cpu(t_hand), cpu(t_one), cpu(t_two), one_s / hand_s - 1,
                cpu(t_one) / cpu(t_hand) - 1, one_s / two_s, cpu(t_two) / cpu(t_one), double(n) / cpu(t_one),
                eomgen::thread_count(0));
    return 0;
}
