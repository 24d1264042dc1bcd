/**
 * @file gpu_ensemble_host.hpp  The host side of gpu_ensemble.cu that needs eomgen::ensemble (the whole simulation
 * driver) or its thread pool, compiled by the C++ compiler in gpu_ensemble_host.cpp: nvcc spent about 3 minutes of
 * the benchmark's build on the driver alone (docs/benchmarks.md, "Build time").
 */
#pragma once

#include "eomgen/models/door.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace gpu_bench {

using Door = eomgen::models::door::Model<double>;

/// eomgen::thread_count(0), eomgen::chunk_size and eomgen::for_each_index (ensemble.hpp): the host's threads, and
/// work(i) for i in [0, n) on `threads` of them.
unsigned thread_count();
std::size_t chunk_size(std::size_t n, unsigned threads);
void for_each_index(std::size_t n, unsigned threads, std::size_t chunk, const std::function<void(std::size_t)>& work);

/// The door's closing times (psi reaches -pi/2 before t_end) by eomgen::ensemble, the engine of `eomgen run --sweep`,
/// with the runtime's integrate() at rtol and atol on `threads` threads; NaN where a member fails.
std::vector<double> door_closing_times(const std::vector<Door::Params>& params, double t_end, double rtol, double atol,
                                       unsigned threads);

}  // namespace gpu_bench
