/**
 * @file cuda_ensemble.cuh  Ensembles on a CUDA device (nvcc only): one member per thread, each integrated by
 * device::integrate_member_rk4 (fixed-step RK4) or device::integrate_member_dopri5 (adaptive Dormand–Prince
 * 5(4)) of device_ensemble.hpp (an L D Lᵀ solve in registers, one terminal event), from per-member parameters and
 * initial states.
 *
 *     std::vector<eomgen::device::Member<M>> r = eomgen::device::ensemble_rk4<M>(params, x0, t_end, dt, event);
 *     std::vector<eomgen::device::Member<M>> s = eomgen::device::ensemble_dopri5<M>(params, x0, t_end, options, event);
 *
 * M is a generated Model<double> (its expression functions are EOMGEN_HD). Throws std::runtime_error with
 * CUDA's message when the device cannot run it. Results are in member order; member i's are those of the same
 * member integrator on the host up to the device's last-bit differences in sin, cos and sqrt (which an adaptive
 * method's step choices can amplify to the order of its tolerance).
 */
#pragma once

#include "eomgen/device_ensemble.hpp"

#include <cuda_runtime.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen::device {

template <class M>
__global__ void rk4_members(const typename M::Params* params, const typename M::State* x0, int n, double t_end,
                            double dt, StateEvent event, Member<M>* out) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) out[i] = integrate_member_rk4<M>(params[i], x0[i], t_end, dt, event);
}

template <class M>
__global__ void dopri5_members(const typename M::Params* params, const typename M::State* x0, int n, double t_end,
                               Dopri5Options<double> options, StateEvent event, Member<M>* out) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) out[i] = integrate_member_dopri5<M>(params[i], x0[i], t_end, options, event);
}

namespace detail {

inline void cuda_check(cudaError_t e, const char* what) {
    if (e != cudaSuccess) throw std::runtime_error(std::string("CUDA ensemble: ") + what + ": " + cudaGetErrorString(e));
}

/// Device memory for n values of T, freed on every path.
template <class T>
struct DeviceArray {
    T* data = nullptr;
    explicit DeviceArray(std::size_t n) { cuda_check(cudaMalloc(&data, n * sizeof(T)), "cudaMalloc"); }
    ~DeviceArray() { cudaFree(data); }
    DeviceArray(const DeviceArray&) = delete;
    DeviceArray& operator=(const DeviceArray&) = delete;
};


/// Copies the members' parameters and initial states to the device, runs launch(blocks, threads, params, x0,
/// n, out) and copies the results back.
template <class M, class Launch>
std::vector<Member<M>> run_members(const char* name, const std::vector<typename M::Params>& params,
                                   const std::vector<typename M::State>& x0, int threads_per_block, Launch launch) {
    if (params.size() != x0.size()) throw std::invalid_argument(std::string(name) + ": params and x0 differ in size");
    if (threads_per_block < 1) throw std::invalid_argument(std::string(name) + ": threads_per_block must be positive");
    const std::size_t n = params.size();
    std::vector<Member<M>> out(n);
    if (n == 0) return out;
    DeviceArray<typename M::Params> d_params(n);
    DeviceArray<typename M::State> d_x0(n);
    DeviceArray<Member<M>> d_out(n);
    cuda_check(cudaMemcpy(d_params.data, params.data(), n * sizeof(typename M::Params), cudaMemcpyHostToDevice),
               "cudaMemcpy");
    cuda_check(cudaMemcpy(d_x0.data, x0.data(), n * sizeof(typename M::State), cudaMemcpyHostToDevice), "cudaMemcpy");
    const int blocks = int((n + std::size_t(threads_per_block) - 1) / std::size_t(threads_per_block));
    launch(blocks, threads_per_block, d_params.data, d_x0.data, int(n), d_out.data);
    cuda_check(cudaGetLastError(), "launch");
    cuda_check(cudaDeviceSynchronize(), "kernel");
    cuda_check(cudaMemcpy(out.data(), d_out.data, n * sizeof(Member<M>), cudaMemcpyDeviceToHost), "cudaMemcpy");
    return out;
}

}  // namespace detail

/// Members i = 0 … n-1 with params[i] and x0[i] (equal sizes), RK4 steps dt to t_end or the event.
template <class M>
std::vector<Member<M>> ensemble_rk4(const std::vector<typename M::Params>& params,
                                    const std::vector<typename M::State>& x0, double t_end, double dt,
                                    StateEvent event = {}, int threads_per_block = 128) {
    if (!(dt > 0) || !(t_end >= 0)) throw std::invalid_argument("ensemble_rk4: dt must be positive, t_end not negative");
    return detail::run_members<M>("ensemble_rk4", params, x0, threads_per_block,
                                  [&](int blocks, int threads, const typename M::Params* p, const typename M::State* x,
                                      int n, Member<M>* out) {
                                      rk4_members<M><<<blocks, threads>>>(p, x, n, t_end, dt, event, out);
                                  });
}

/// Members i = 0 … n-1 with params[i] and x0[i] (equal sizes), adaptive Dormand–Prince 5(4) with `options` (as
/// Dopri5 takes them: rtol ≥ 0, atol > 0) to t_end or the event. Members stop when they are done, so a warp
/// takes as long as its slowest member.
template <class M>
std::vector<Member<M>> ensemble_dopri5(const std::vector<typename M::Params>& params,
                                       const std::vector<typename M::State>& x0, double t_end,
                                       const Dopri5Options<double>& options, StateEvent event = {},
                                       int threads_per_block = 128) {
    if (!(t_end >= 0)) throw std::invalid_argument("ensemble_dopri5: t_end must not be negative");
    if (!(options.rtol >= 0) || !(options.atol > 0))
        throw std::invalid_argument("ensemble_dopri5: need rtol >= 0 and atol > 0");
    return detail::run_members<M>("ensemble_dopri5", params, x0, threads_per_block,
                                  [&](int blocks, int threads, const typename M::Params* p, const typename M::State* x,
                                      int n, Member<M>* out) {
                                      dopri5_members<M><<<blocks, threads>>>(p, x, n, t_end, options, event, out);
                                  });
}

}  // namespace eomgen::device
