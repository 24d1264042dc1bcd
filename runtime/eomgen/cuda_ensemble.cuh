/**
 * @file cuda_ensemble.cuh  Ensembles on a CUDA device (nvcc only): one member per thread, each integrated by
 * device::integrate_member_rk4 (device_ensemble.hpp: fixed-step RK4, an L D Lᵀ solve in registers, one terminal
 * event), from per-member parameters and initial states.
 *
 *     std::vector<eomgen::device::Member<M>> r = eomgen::device::ensemble_rk4<M>(params, x0, t_end, dt, event);
 *
 * M is a generated Model<double> (its expression functions are EOMGEN_HD). Throws std::runtime_error with
 * CUDA's message when the device cannot run it. Results are in member order; member i's are those of
 * integrate_member_rk4 on the host up to the device's last-bit differences in sin, cos and sqrt.
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

}  // namespace detail

/// Members i = 0 … n-1 with params[i] and x0[i] (equal sizes), RK4 steps dt to t_end or the event.
template <class M>
std::vector<Member<M>> ensemble_rk4(const std::vector<typename M::Params>& params,
                                    const std::vector<typename M::State>& x0, double t_end, double dt,
                                    StateEvent event = {}, int threads_per_block = 128) {
    if (params.size() != x0.size()) throw std::invalid_argument("ensemble_rk4: params and x0 differ in size");
    if (!(dt > 0) || !(t_end >= 0)) throw std::invalid_argument("ensemble_rk4: dt must be positive, t_end not negative");
    const std::size_t n = params.size();
    std::vector<Member<M>> out(n);
    if (n == 0) return out;
    detail::DeviceArray<typename M::Params> d_params(n);
    detail::DeviceArray<typename M::State> d_x0(n);
    detail::DeviceArray<Member<M>> d_out(n);
    detail::cuda_check(cudaMemcpy(d_params.data, params.data(), n * sizeof(typename M::Params), cudaMemcpyHostToDevice),
                       "cudaMemcpy");
    detail::cuda_check(cudaMemcpy(d_x0.data, x0.data(), n * sizeof(typename M::State), cudaMemcpyHostToDevice),
                       "cudaMemcpy");
    const int blocks = int((n + std::size_t(threads_per_block) - 1) / std::size_t(threads_per_block));
    rk4_members<M><<<blocks, threads_per_block>>>(d_params.data, d_x0.data, int(n), t_end, dt, event, d_out.data);
    detail::cuda_check(cudaGetLastError(), "launch");
    detail::cuda_check(cudaDeviceSynchronize(), "kernel");
    detail::cuda_check(cudaMemcpy(out.data(), d_out.data, n * sizeof(Member<M>), cudaMemcpyDeviceToHost), "cudaMemcpy");
    return out;
}

}  // namespace eomgen::device
