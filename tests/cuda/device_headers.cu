// The generated headers' expression functions (EOMGEN_HD, runtime/eomgen/device.hpp) compiled as CUDA device
// code unchanged (the friction door's sign() included), and, where a GPU is present, evaluated there at random
// states and compared with the same functions on the host: M, f, T, V, the energy, the conserved quantities, the
// outputs, the rest linearization and the analytic Jacobians' terms of unconstrained models, and, for constrained
// models, the constraint Jacobian and residuals; then a door sweep through cuda_ensemble.cuh against the same member
// integrator on the host.
#include "eomgen/models/door.hpp"
#include "eomgen/models/friction_door.hpp"
#include "eomgen/models/heavy_symmetric_top.hpp"
#include "eomgen/models/pendulum_cartesian.hpp"
#include "eomgen/models/rolling_sphere.hpp"
#include "eomgen/cuda_ensemble.cuh"
#include "eomgen/model_traits.hpp"

#include <cuda_runtime.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

/// Every EOMGEN_HD function of M at state x (2 nq values), written to out in a fixed order; returns the count.
template <class M>
__host__ __device__ int evaluate(const double* x, double* out) {
    typename M::Params p;
    typename M::Config q, qd;
    for (int i = 0; i < M::nq; ++i) {
        q(i) = x[i];
        qd(i) = x[M::nq + i];
    }
    int k = 0;
    typename M::MassMatrix mass, K, C, G;
    typename M::Config f, momenta;
    M::dynamics(0.25, q, qd, p, mass, f);
    M::momenta(0.25, q, qd, p, momenta);
    M::stiffness(0.25, q, p, K);
    M::damping(0.25, q, p, C);
    M::gyroscopic(0.25, q, p, G);
    for (int i = 0; i < M::nq; ++i) {
        out[k++] = f(i);
        out[k++] = momenta(i);
        for (int j = 0; j < M::nq; ++j) {
            out[k++] = mass(i, j);
            out[k++] = K(i, j);
            out[k++] = C(i, j);
            out[k++] = G(i, j);
        }
    }
    out[k++] = M::kinetic_energy(0.25, q, qd, p);
    out[k++] = M::potential_energy(0.25, q, qd, p);
    out[k++] = M::energy(0.25, q, qd, p);
    typename M::Conserved c;
    M::conserved(0.25, q, qd, p, c);
    for (int i = 0; i < M::n_conserved; ++i) out[k++] = c(i);
    typename M::Outputs o;
    M::outputs(0.25, q, qd, p, o);
    for (int i = 0; i < M::n_outputs; ++i) out[k++] = o(i);
    if constexpr (!eomgen::is_constrained<M>::value) {
        // The analytic Jacobians' terms (member templates), at f standing in for q'': they hold for any q''.
        Eigen::Matrix<double, M::nq, M::nx> R;
        Eigen::Matrix<double, M::nq, M::n_params> Rp;
        M::jacobian_terms(0.25, q, qd, f, p, R);
        M::parameter_jacobian_terms(0.25, q, qd, f, p, Rp);
        for (int i = 0; i < M::nq; ++i) {
            for (int j = 0; j < M::nx; ++j) out[k++] = R(i, j);
            for (int j = 0; j < M::n_params; ++j) out[k++] = Rp(i, j);
        }
    }
    if constexpr (eomgen::is_constrained<M>::value) {
        typename M::ConstraintJacobian A;
        typename M::ConstraintVector gamma, position, velocity;
        M::constraints(0.25, q, qd, p, A, gamma);
        M::constraint_residuals(0.25, q, qd, p, position, velocity);
        for (int i = 0; i < M::n_constraints; ++i) {
            out[k++] = gamma(i);
            out[k++] = position(i);
            out[k++] = velocity(i);
            for (int j = 0; j < M::nq; ++j) out[k++] = A(i, j);
        }
    }
    return k;
}

template <class M>
__global__ void evaluate_all(const double* x, double* out, int members, int stride) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < members) evaluate<M>(x + 2 * M::nq * i, out + stride * i);
}

bool check(cudaError_t e, const char* what) {
    if (e == cudaSuccess) return true;
    std::printf("%s: %s\n", what, cudaGetErrorString(e));
    return false;
}

/// Host and device values at `members` random states; the largest relative difference, or -1 on a CUDA error.
template <class M>
double compare(int members) {
    std::mt19937_64 rng(20261124);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    std::vector<double> x(std::size_t(2 * M::nq * members));
    for (double& v : x) v = u(rng);
    std::vector<double> scratch(4096);
    const int stride = evaluate<M>(x.data(), scratch.data());
    std::vector<double> host(std::size_t(stride * members)), device(host.size());
    for (int i = 0; i < members; ++i) evaluate<M>(x.data() + 2 * M::nq * i, host.data() + stride * i);
    double *dx = nullptr, *dout = nullptr;
    if (!check(cudaMalloc(&dx, x.size() * sizeof(double)), "cudaMalloc") ||
        !check(cudaMalloc(&dout, device.size() * sizeof(double)), "cudaMalloc") ||
        !check(cudaMemcpy(dx, x.data(), x.size() * sizeof(double), cudaMemcpyHostToDevice), "cudaMemcpy"))
        return -1;
    evaluate_all<M><<<(members + 127) / 128, 128>>>(dx, dout, members, stride);
    if (!check(cudaGetLastError(), "launch") || !check(cudaDeviceSynchronize(), "kernel") ||
        !check(cudaMemcpy(device.data(), dout, device.size() * sizeof(double), cudaMemcpyDeviceToHost), "cudaMemcpy"))
        return -1;
    cudaFree(dx);
    cudaFree(dout);
    double worst = 0;
    for (std::size_t i = 0; i < host.size(); ++i) {
        // A NaN is a value too (the damping about rest of dry friction): on both sides, or a difference.
        if (std::isnan(host[i]) || std::isnan(device[i])) {
            if (std::isnan(host[i]) != std::isnan(device[i])) worst = HUGE_VAL;
            continue;
        }
        worst = std::max(worst, std::abs(host[i] - device[i]) / std::max(1.0, std::abs(host[i])));
    }
    std::printf("%s: %d states, %d values each, largest relative difference %.2e\n", M::name, members, stride, worst);
    return worst;
}

/// The door's closing time over a θ grid on the device (cuda_ensemble.cuh, by on_device(params, x0, event)) against
/// the same member integrator on the host (on_host(params, x0, event)): the largest relative difference of t, or
/// -1 when a member did not stop at its event.
template <class OnDevice, class OnHost>
double door_sweep(const char* what, int members, OnDevice on_device, OnHost on_host) {
    using Door = eomgen::models::door::Model<double>;
    const double pi = std::acos(-1.0);
    std::vector<Door::Params> params(static_cast<std::size_t>(members));
    std::vector<Door::State> x0(params.size(), Door::default_state());
    for (int i = 0; i < members; ++i) params[std::size_t(i)].theta = 0.02 + (pi / 2 - 0.02) * i / (members - 1);
    const eomgen::device::StateEvent shut{0, -pi / 2};
    // Wall times, printed and not asserted: the device's includes the copies to and from it; the host's is the
    // same member integrator on one thread, member after member.
    const auto t0 = std::chrono::steady_clock::now();
    const auto device = on_device(params, x0, shut);
    const auto t1 = std::chrono::steady_clock::now();
    std::vector<decltype(on_host(params[0], x0[0], shut))> hosts;
    for (int i = 0; i < members; ++i) hosts.push_back(on_host(params[std::size_t(i)], x0[std::size_t(i)], shut));
    const auto t2 = std::chrono::steady_clock::now();
    std::printf("door sweep (%s): %d members, device %.3f s (copies included), host one thread %.3f s\n", what,
                members, std::chrono::duration<double>(t1 - t0).count(), std::chrono::duration<double>(t2 - t1).count());
    double worst = 0;
    for (int i = 0; i < members; ++i) {
        const auto& host = hosts[std::size_t(i)];
        const auto& d = device[std::size_t(i)];
        if (d.status != eomgen::device::Status::Event || host.status != eomgen::device::Status::Event) return -1;
        worst = std::max(worst, std::abs(d.t - host.t) / host.t);
    }
    std::printf("door sweep (%s): %d members on the device, closing times within %.2e of the host's\n", what,
                members, worst);
    return worst;
}

}  // namespace

int main() {
    int devices = 0;
    if (cudaGetDeviceCount(&devices) != cudaSuccess || devices == 0) {
        std::printf("skipped: no CUDA device (the generated headers compiled as device code)\n");
        return 0;
    }
    // Device and host libm may differ in the last bits of sin, cos and sqrt.
    const double tolerance = 1e-12;
    bool ok = true;
    for (double d : {compare<eomgen::models::door::Model<double>>(1000),
                     compare<eomgen::models::heavy_symmetric_top::Model<double>>(1000),
                     compare<eomgen::models::pendulum_cartesian::Model<double>>(1000),
                     compare<eomgen::models::rolling_sphere::Model<double>>(1000),
                     compare<eomgen::models::friction_door::Model<double>>(1000)})
        ok = ok && d >= 0 && d <= tolerance;
    using Door = eomgen::models::door::Model<double>;
    const double sweep = door_sweep(
        "RK4", 4096,
        [](const auto& params, const auto& x0, auto event) {
            return eomgen::device::ensemble_rk4<Door>(params, x0, 20.0, 1e-3, event);
        },
        [](const auto& p, const auto& x0, auto event) {
            return eomgen::device::integrate_member_rk4<Door>(p, x0, 20.0, 1e-3, event);
        });
    ok = ok && sweep >= 0 && sweep <= tolerance;
    // Last-bit differences can change an adaptive step's size; the closing time stays within the tolerance.
    eomgen::Dopri5Options<double> o;
    o.rtol = 1e-10;
    o.atol = 1e-12;
    const double adaptive = door_sweep(
        "Dormand-Prince 5(4), rtol 1e-10", 4096,
        [&o](const auto& params, const auto& x0, auto event) {
            return eomgen::device::ensemble_dopri5<Door>(params, x0, 20.0, o, event);
        },
        [&o](const auto& p, const auto& x0, auto event) {
            return eomgen::device::integrate_member_dopri5<Door>(p, x0, 20.0, o, event);
        });
    ok = ok && adaptive >= 0 && adaptive <= 1e-9;
    return ok ? 0 : 1;
}
