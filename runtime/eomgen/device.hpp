/**
 * @file device.hpp  EOMGEN_HD: `__host__ __device__` under nvcc, empty elsewhere. The generated headers mark
 * their expression functions (dynamics, mass_matrix, forcing, the energies, momenta, conserved quantities,
 * outputs, the rest linearization and the constraint Jacobians) with it, so a generated header compiles as CUDA
 * device code unchanged (nvcc -std=c++17 --expt-relaxed-constexpr, for Eigen's fixed-size types). The functions
 * that can throw (rhs, accelerations, multipliers, the solve) stay host-only. Define EOMGEN_HD yourself before
 * the first include to override it.
 */
#pragma once

#ifndef EOMGEN_HD
#if defined(__CUDACC__)
#define EOMGEN_HD __host__ __device__
#else
#define EOMGEN_HD
#endif
#endif
