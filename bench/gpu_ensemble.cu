/**
 * @file gpu_ensemble.cu  Ensembles on a CUDA device against every core of the host (issue 16's throughput row;
 * docs/benchmarks.md, "Ensembles on a GPU"). Built only where CMake finds nvcc (bench/CMakeLists.txt), run by hand
 * on a machine with a GPU (bench/run.sh does not: CI has none).
 *
 * Two problems, each at several ensemble sizes N:
 *   - the door's closing time (psi crosses -pi/2) over a theta grid, t_end 100, the event ending each member;
 *   - the heavy symmetric top (3 coordinates, spinning at 100 rad/s) from theta0 in [0.2, 1.2] to t = 2.
 * Each with fixed-step RK4 (dt 1e-3) and adaptive Dormand–Prince 5(4) (rtol 1e-10, atol 1e-12), run
 *   - on the device by cuda_ensemble.cuh (one member per thread), wall time with the copies both ways;
 *   - the same kernel alone on members already resident on the device (CUDA events around the launch), which
 *     splits the device's wall time into the kernel and the allocations and copies around it;
 *   - on the host by the same member integrator (device_ensemble.hpp) on every core (eomgen::for_each_index);
 *   - for the door with Dormand–Prince also by eomgen::ensemble, the engine of `eomgen run --sweep`, on every core.
 * Each time is the fastest of `repeats` runs after one unmeasured run (the device's first launch loads the module).
 * The largest relative difference of the results (closing times; the top's final states) between device and host
 * is printed beside the times, and the door's closing times are compared with the closed form
 * 1.5138456348 sqrt(w / (g sin theta)).
 *
 * Usage: gpu_ensemble [max N = 1048576] [repeats = 3]. Prints one JSON object per row, and a summary line.
 */
#include "eomgen/cuda_ensemble.cuh"
#include "gpu_ensemble_host.hpp"
#include "eomgen/models/door.hpp"
#include "eomgen/models/heavy_symmetric_top.hpp"

#include <cuda_runtime.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

namespace {

using Door = eomgen::models::door::Model<double>;
using Top = eomgen::models::heavy_symmetric_top::Model<double>;
const double kPi = std::acos(-1.0);

template <class F>
double fastest(int repeats, F&& f) {
    f();  // unmeasured
    double best = HUGE_VAL;
    for (int r = 0; r < repeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
}

/// One problem's members: parameters, initial states, t_end and the terminal event.
template <class M>
struct Problem {
    const char* name;
    std::vector<typename M::Params> params;
    std::vector<typename M::State> x0;
    double t_end;
    eomgen::device::StateEvent event;
};

Problem<Door> door(std::size_t n) {
    Problem<Door> p{"door", std::vector<Door::Params>(n), std::vector<Door::State>(n, Door::default_state()), 100.0,
                    {0, -kPi / 2}};
    for (std::size_t i = 0; i < n; ++i) p.params[i].theta = 0.02 + (kPi / 2 - 0.02) * double(i) / double(n - 1);
    return p;
}

Problem<Top> top(std::size_t n) {
    Problem<Top> p{"heavy_symmetric_top", std::vector<Top::Params>(n), std::vector<Top::State>(n, Top::default_state()),
                   2.0, {}};
    for (std::size_t i = 0; i < n; ++i) p.x0[i](1) = 0.2 + 1.0 * double(i) / double(n - 1);
    return p;
}

/// The fastest of `repeats` launches of kernel(blocks, threads, params, x0, n, out) on members already on the
/// device (one unmeasured launch first), timed by CUDA events: the kernel alone, without allocations or copies.
template <class M, class Kernel>
double kernel_seconds(const Problem<M>& p, int repeats, Kernel kernel) {
    using eomgen::device::detail::cuda_check;
    const std::size_t n = p.params.size();
    eomgen::device::detail::DeviceArray<typename M::Params> d_params(n);
    eomgen::device::detail::DeviceArray<typename M::State> d_x0(n);
    eomgen::device::detail::DeviceArray<eomgen::device::Member<M>> d_out(n);
    cuda_check(cudaMemcpy(d_params.data, p.params.data(), n * sizeof(typename M::Params), cudaMemcpyHostToDevice),
               "cudaMemcpy");
    cuda_check(cudaMemcpy(d_x0.data, p.x0.data(), n * sizeof(typename M::State), cudaMemcpyHostToDevice), "cudaMemcpy");
    const int threads = 128, blocks = int((n + 127) / 128);
    cudaEvent_t start, stop;
    cuda_check(cudaEventCreate(&start), "cudaEventCreate");
    cuda_check(cudaEventCreate(&stop), "cudaEventCreate");
    double best = HUGE_VAL;
    for (int r = 0; r <= repeats; ++r) {
        cuda_check(cudaEventRecord(start), "cudaEventRecord");
        kernel(blocks, threads, d_params.data, d_x0.data, int(n), d_out.data);
        cuda_check(cudaGetLastError(), "launch");
        cuda_check(cudaEventRecord(stop), "cudaEventRecord");
        cuda_check(cudaEventSynchronize(stop), "kernel");
        float ms = 0;
        cuda_check(cudaEventElapsedTime(&ms, start, stop), "cudaEventElapsedTime");
        if (r > 0) best = std::min(best, double(ms) * 1e-3);
    }
    cudaEventDestroy(start);
    cudaEventDestroy(stop);
    return best;
}

/// The largest relative difference between two members' results (t and x), or +inf when a status differs.
template <class M>
double difference(const eomgen::device::Member<M>& a, const eomgen::device::Member<M>& b) {
    if (a.status != b.status) return HUGE_VAL;
    double worst = std::abs(a.t - b.t) / std::max(1.0, std::abs(b.t));
    for (int k = 0; k < M::nx; ++k) worst = std::max(worst, std::abs(a.x(k) - b.x(k)) / std::max(1.0, std::abs(b.x(k))));
    return worst;
}

struct Row {
    std::string problem, method;
    std::size_t members = 0;
    double device_s = 0, kernel_s = 0, host_s = 0, ensemble_s = -1, worst = 0, closed_form = -1;
    int failed = 0;
};

void print(const Row& r, unsigned threads) {
    std::printf("{\"problem\": \"%s\", \"method\": \"%s\", \"members\": %zu, \"device_s\": %.6f, \"kernel_s\": %.6f, \"host_s\": %.6f, "
                "\"host_threads\": %u, \"speedup\": %.2f, \"ensemble_s\": %.6f, \"device_vs_host\": %.3e, "
                "\"closed_form\": %.3e, \"failed\": %d}\n",
                r.problem.c_str(), r.method.c_str(), r.members, r.device_s, r.kernel_s, r.host_s, threads, r.host_s / r.device_s,
                r.ensemble_s, r.worst, r.closed_form, r.failed);
    std::fflush(stdout);
}

/// Runs problem p by `method` (on_device(params, x0), the kernel alone on resident members, and on_host(params, x0)
/// of one member) and returns the row.
template <class M, class OnDevice, class Kernel, class OnHost>
Row compare(const Problem<M>& p, const char* method, int repeats, unsigned threads, OnDevice on_device,
            Kernel kernel, OnHost on_host) {
    const std::size_t n = p.params.size();
    Row row{p.name, method, n};
    std::vector<eomgen::device::Member<M>> dev, host(n);
    row.device_s = fastest(repeats, [&] { dev = on_device(p.params, p.x0); });
    row.kernel_s = kernel_seconds(p, repeats, kernel);
    const std::size_t chunk = gpu_bench::chunk_size(n, threads);
    row.host_s = fastest(repeats, [&] {
        gpu_bench::for_each_index(n, threads, chunk, [&](std::size_t i) { host[i] = on_host(p.params[i], p.x0[i]); });
    });
    for (std::size_t i = 0; i < n; ++i) {
        const bool done = host[i].status == eomgen::device::Status::Ok || host[i].status == eomgen::device::Status::Event;
        row.failed += done ? 0 : 1;
        row.worst = std::max(row.worst, difference(dev[i], host[i]));
    }
    if constexpr (std::is_same_v<M, Door>) {
        row.closed_form = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const auto& q = p.params[i];
            const double exact = 1.5138456348 * std::sqrt(q.w / (q.g * std::sin(q.theta)));
            row.closed_form = std::max(row.closed_form, std::abs(dev[i].t - exact) / exact);
        }
    }
    return row;
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t max_n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1048576;
    const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
    int devices = 0;
    if (cudaGetDeviceCount(&devices) != cudaSuccess || devices == 0) {
        std::printf("gpu_ensemble: no CUDA device\n");
        return 77;
    }
    cudaDeviceProp prop{};
    cudaGetDeviceProperties(&prop, 0);
    const unsigned threads = gpu_bench::thread_count();
    std::printf("# device: %s (%d multiprocessors); host: %u threads\n", prop.name, prop.multiProcessorCount, threads);
    eomgen::Dopri5Options<double> o;
    o.rtol = 1e-10;
    o.atol = 1e-12;
    const double dt = 1e-3;
    for (std::size_t n = 4096; n <= max_n; n *= 16) {
        const Problem<Door> d = door(n);
        Row rk4 = compare(
            d, "rk4", repeats, threads,
            [&](const auto& params, const auto& x0) { return eomgen::device::ensemble_rk4<Door>(params, x0, d.t_end, dt, d.event); },
            [&](int b, int th, const auto* p, const auto* x, int n, auto* out) { eomgen::device::rk4_members<Door><<<b, th>>>(p, x, n, d.t_end, dt, d.event, out); },
            [&](const auto& params, const auto& x0) { return eomgen::device::integrate_member_rk4<Door>(params, x0, d.t_end, dt, d.event); });
        print(rk4, threads);
        Row dp = compare(
            d, "dopri5", repeats, threads,
            [&](const auto& params, const auto& x0) { return eomgen::device::ensemble_dopri5<Door>(params, x0, d.t_end, o, d.event); },
            [&](int b, int th, const auto* p, const auto* x, int n, auto* out) { eomgen::device::dopri5_members<Door><<<b, th>>>(p, x, n, d.t_end, o, d.event, out); },
            [&](const auto& params, const auto& x0) { return eomgen::device::integrate_member_dopri5<Door>(params, x0, d.t_end, o, d.event); });
        // The CLI's engine: eomgen::ensemble with the runtime's integrate(), dense output and the event by name
        // (gpu_ensemble_host.cpp, compiled by the C++ compiler).
        dp.ensemble_s = fastest(repeats, [&] { gpu_bench::door_closing_times(d.params, d.t_end, o.rtol, o.atol, threads); });
        print(dp, threads);
        if (n > max_n / 4) continue;  // the top costs about 40 times the door per member
        const Problem<Top> s = top(n);
        print(compare(
                  s, "rk4", repeats, threads,
                  [&](const auto& params, const auto& x0) { return eomgen::device::ensemble_rk4<Top>(params, x0, s.t_end, dt, s.event); },
                  [&](int b, int th, const auto* p, const auto* x, int n, auto* out) { eomgen::device::rk4_members<Top><<<b, th>>>(p, x, n, s.t_end, dt, s.event, out); },
                  [&](const auto& params, const auto& x0) { return eomgen::device::integrate_member_rk4<Top>(params, x0, s.t_end, dt, s.event); }),
              threads);
        print(compare(
                  s, "dopri5", repeats, threads,
                  [&](const auto& params, const auto& x0) { return eomgen::device::ensemble_dopri5<Top>(params, x0, s.t_end, o, s.event); },
                  [&](int b, int th, const auto* p, const auto* x, int n, auto* out) { eomgen::device::dopri5_members<Top><<<b, th>>>(p, x, n, s.t_end, o, s.event, out); },
                  [&](const auto& params, const auto& x0) { return eomgen::device::integrate_member_dopri5<Top>(params, x0, s.t_end, o, s.event); }),
              threads);
    }
    return 0;
}
