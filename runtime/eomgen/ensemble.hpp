/**
 * @file ensemble.hpp  Many independent integrations of one model (a parameter sweep, a Monte Carlo study)
 * on a pool of threads, one result per member, delivered in member order whatever the number of threads.
 *
 * A member is a parameter set and an initial state, made from its index by a function the caller gives,
 * so that the same index always means the same member (on any thread, in any process of an MPI run).
 * Each member is integrated by simulation.hpp's driver (simulate(): the method, tolerances and --until
 * event of sim::Options), for a generated Model<double> compiled in or for the TableModel `eomgen run`
 * loads. A member whose integration fails (a singular mass matrix, a non-finite state, too many steps, ...)
 * is a result with its message and time, not the end of the ensemble.
 *
 * Threads take chunks of consecutive indices from an atomic counter (dynamic assignment: a slow member
 * holds up only its own thread); results wait in a buffer until every earlier one is there and then go to
 * the sink in order, so the sink sees the same sequence for 1 or 64 threads.
 *
 *     using Door = eomgen::models::door::Model<double>;
 *     eomgen::EnsembleOptions opt;
 *     opt.simulation.until = "psi=-pi/2";
 *     eomgen::ensemble<Door>(1000, [](std::size_t i) {
 *         eomgen::Member<Door> m;   // default parameters and initial state
 *         m.params.theta = 0.01 + 0.001 * double(i);
 *         return m;
 *     }, opt, [](const eomgen::MemberResult<Door>& r) { std::printf("%zu %.10g\n", r.index, r.t); });
 */
#pragma once

#include "eomgen/simulation.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <limits>
#include <mutex>
#include <map>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace eomgen {

/// One member of an ensemble: parameters (the model's defaults unless changed) and the initial state.
template <class M>
struct Member {
    typename M::Params params{};
    typename M::State x0 = M::default_state();
};

/// What one member gave.
template <class M>
struct MemberResult {
    std::size_t index = 0;
    bool ok = false;         ///< false: the integration failed, `error` says why
    double t = std::numeric_limits<double>::quiet_NaN();  ///< ok: where it ended (t_end or the event); failed:
                                                          ///< the failure's time (NaN when it has none)
    typename M::State x;     ///< ok: the state at t
    std::string stopped_by;  ///< ok: the terminal event's name, "" when t_end was reached
    double energy = std::numeric_limits<double>::quiet_NaN();  ///< ok: h at (t, x)
    typename M::Outputs outputs;  ///< ok: the model's declared outputs at (t, x)
    /// With sim::Options::sensitivities (ok): S = ∂x/∂(columns) at (t, x), the outputs' Y = ∂y/∂(columns), and for a
    /// member stopped by the --until event its time's dt/d(columns) (sensitivities.hpp); empty otherwise.
    Eigen::MatrixXd S, Y;
    Eigen::RowVectorXd dt;
    std::string error;            ///< failed: the message (with the time and state where the runtime gives them)
};

/// How an ensemble runs: every member with the same simulation options, on `threads` threads.
struct EnsembleOptions {
    sim::Options simulation;  ///< method, tolerances, t_end, until; set, init and csv are not used
    unsigned threads = 0;     ///< 0: every core (std::thread::hardware_concurrency)
    std::size_t chunk = 0;    ///< indices a thread takes at a time; 0: chosen from the count and the threads
};

/// The number of threads `requested` means: itself, or every core for 0 (at least 1).
inline unsigned thread_count(unsigned requested) {
    if (requested > 0) return requested;
    return std::max(1u, std::thread::hardware_concurrency());
}

/// Chunks small enough to balance (about 16 per thread) and large enough that the counter is not contended.
inline std::size_t chunk_size(std::size_t members, unsigned threads, std::size_t requested = 0) {
    if (requested > 0) return requested;
    return std::clamp<std::size_t>(members / (16 * std::size_t(std::max(1u, threads))), 1, 256);
}

/**
 * Runs work(i) for every i in [begin, end) on `threads` threads (the calling thread alone for 1), each
 * taking `chunk` consecutive indices at a time from a shared counter. The first exception work() throws
 * stops the handing out of further chunks and is rethrown here after every thread has finished.
 */
template <class Work>
void for_each_index(std::size_t begin, std::size_t end, unsigned threads, std::size_t chunk, Work&& work) {
    if (begin >= end) return;
    chunk = std::max<std::size_t>(1, chunk);
    std::atomic<std::size_t> next{begin};
    std::atomic<bool> stop{false};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    auto worker = [&] {
        try {
            while (!stop.load(std::memory_order_relaxed)) {
                const std::size_t first = next.fetch_add(chunk, std::memory_order_relaxed);
                if (first >= end) break;
                const std::size_t last = std::min(end, first + chunk);
                for (std::size_t i = first; i < last; ++i) work(i);
            }
        } catch (...) {
            std::lock_guard<std::mutex> lock(failure_mutex);
            if (!failure) failure = std::current_exception();
            stop = true;
        }
    };
    const unsigned n = std::max(1u, std::min<unsigned>(threads, unsigned(std::min<std::size_t>(end - begin, 1u << 16))));
    if (n == 1) {
        worker();
    } else {
        std::vector<std::thread> pool;
        pool.reserve(n);
        for (unsigned k = 0; k < n; ++k) pool.emplace_back(worker);
        for (std::thread& th : pool) th.join();
    }
    if (failure) std::rethrow_exception(failure);
}

/**
 * Takes results in any order from any thread and hands them to `sink` in index order, from `first` on.
 * One thread at a time delivers: the put() that finds no delivery under way hands every result that has
 * become next in line to the sink, outside the lock, and goes on while others keep arriving; the other
 * threads only file their result and return to work, so a sink that formats and writes a row (the CLI's
 * table) runs beside the integrations instead of holding every thread up. Results that arrived ahead of an
 * earlier one wait; past `max_waiting` of them a put() waits until the sink has caught up, so a sink slower
 * than the integrations bounds the memory instead of buffering the whole ensemble.
 */
template <class Result, class Sink>
class InOrder {
  public:
    /// `max_waiting`: no bound by default. Bound it only where the result that is next in line is always
    /// being computed by a thread that is not itself waiting in put() (ensemble() below); a single thread
    /// that files results received from elsewhere (the MPI coordinator) must not bound it.
    InOrder(std::size_t first, Sink& sink, std::size_t max_waiting = std::numeric_limits<std::size_t>::max())
        : next_(first), sink_(sink), max_waiting_(std::max<std::size_t>(1, max_waiting)) {}

    void put(std::size_t index, Result result) {
        std::unique_lock<std::mutex> lock(mutex_);
        // Only a result other than the next one waits for room: the next one always gets in, so the
        // deliverer is never waited for by the result it needs.
        caught_up_.wait(lock, [&] { return index == next_ || waiting_.size() < max_waiting_ || failed_; });
        if (failed_) return;  // the sink threw: the ensemble is ending, and nothing more is delivered
        waiting_.emplace(index, std::move(result));
        if (delivering_) return;
        delivering_ = true;
        std::vector<Result> ready;
        try {
            for (;;) {
                for (auto it = waiting_.begin(); it != waiting_.end() && it->first == next_ + ready.size();
                     it = waiting_.erase(it))
                    ready.push_back(std::move(it->second));
                if (ready.empty()) break;
                lock.unlock();
                for (const Result& r : ready) sink_(r);
                lock.lock();
                next_ += ready.size();
                ready.clear();
                caught_up_.notify_all();
            }
        } catch (...) {
            if (!lock.owns_lock()) lock.lock();
            failed_ = true;  // nothing more is delivered: let every waiting put() return
            delivering_ = false;
            caught_up_.notify_all();
            throw;
        }
        delivering_ = false;
    }

    /// The index of the next result the sink is waiting for (once every put() has returned).
    std::size_t next() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return next_;
    }

  private:
    mutable std::mutex mutex_;
    std::condition_variable caught_up_;
    std::size_t next_;
    std::map<std::size_t, Result> waiting_;
    Sink& sink_;
    std::size_t max_waiting_;
    bool delivering_ = false;
    bool failed_ = false;
};

/**
 * Integrates one member by simulate() (no samples kept) and returns its result. A SimulationError, or any
 * other error of the model's code, is a failed result; sim::UsageError (options no member can take) is
 * thrown, since it would fail every member alike.
 */
template <class M>
MemberResult<M> simulate_member(const sim::Options& o, const std::vector<Event<typename M::State>>& events,
                                std::size_t index, const Member<M>& member) {
    MemberResult<M> r;
    r.index = index;
    try {
        if (!o.sensitivities.empty()) {
            const SensitivityResult run = sim::sensitivities_from<M>(o, member.params, member.x0, false);
            const typename M::State x(run.x);
            typename M::Config q = positions<M::nq>(x), qd = velocities<M::nq>(x);
            r.energy = M::energy(run.t, q, qd, member.params);
            M::outputs(run.t, q, qd, member.params, r.outputs);
            r.t = run.t;
            r.x = x;
            r.S = run.S;
            r.Y = run.end.Y;
            if (run.stop_reason == StopReason::TerminalEvent && !run.events.empty()) {
                r.stopped_by = run.stopped_by;
                r.dt = run.events.back().dt;
            }
            r.ok = true;
            return r;
        }
        const sim::Trajectory<M> run = sim::simulate<M>(o, member.params, member.x0, events, false, nullptr);
        typename M::Config q = positions<M::nq>(run.x), qd = velocities<M::nq>(run.x);
        r.energy = M::energy(run.t, q, qd, member.params);
        M::outputs(run.t, q, qd, member.params, r.outputs);
        r.t = run.t;
        r.x = run.x;
        r.stopped_by = run.stopped_by;
        r.ok = true;
    } catch (const sim::UsageError&) {
        throw;
    } catch (const SimulationError& e) {
        r.t = e.t();
        r.error = e.what();
    } catch (const std::exception& e) {
        r.error = e.what();
    }
    return r;
}

/**
 * Integrates members 0 … count − 1, member(i) giving member i (called on the worker threads: it must be
 * safe to call concurrently, as a function of i alone is), each with options.simulation, and calls
 * sink(const MemberResult<M>&) once per member in index order (one call at a time, from the worker
 * threads). Throws sim::UsageError for options no member can take (before any member runs), and rethrows
 * what member() or sink() throw (no further members are started then).
 */
template <class M, class MakeMember, class Sink>
void ensemble(std::size_t count, MakeMember&& member, const EnsembleOptions& options, Sink&& sink) {
    sim::check_options(options.simulation);
    const auto events = sim::until_events<M>(options.simulation);
    const unsigned threads = thread_count(options.threads);
    const std::size_t chunk = chunk_size(count, threads, options.chunk);
    // Each thread computes its chunk in order, so the next result in line is always on its way from a
    // thread that is not waiting: bounding the buffer cannot deadlock here.
    InOrder<MemberResult<M>, std::remove_reference_t<Sink>> in_order(
        0, sink, std::max<std::size_t>(4096, 4 * threads * chunk));
    for_each_index(0, count, threads, chunk, [&](std::size_t i) {
        const Member<M> m = member(i);
        in_order.put(i, simulate_member<M>(options.simulation, events, i, m));
    });
}

}  // namespace eomgen
