/** @file gpu_ensemble_host.cpp  gpu_ensemble.cu's host side that needs eomgen::ensemble (gpu_ensemble_host.hpp). */
#include "gpu_ensemble_host.hpp"

#include "eomgen/ensemble.hpp"

#include <cmath>

namespace gpu_bench {

unsigned thread_count() { return eomgen::thread_count(0); }

std::size_t chunk_size(std::size_t n, unsigned threads) { return eomgen::chunk_size(n, threads); }

void for_each_index(std::size_t n, unsigned threads, std::size_t chunk, const std::function<void(std::size_t)>& work) {
    eomgen::for_each_index(0, n, threads, chunk, work);
}

std::vector<double> door_closing_times(const std::vector<Door::Params>& params, double t_end, double rtol, double atol,
                                       unsigned threads) {
    eomgen::EnsembleOptions eo;
    eo.simulation.until = "psi=-pi/2";
    eo.simulation.t_end = t_end;
    eo.simulation.rtol = rtol;
    eo.simulation.atol = atol;
    eo.threads = threads;
    std::vector<double> t(params.size(), NAN);
    eomgen::ensemble<Door>(
        params.size(),
        [&params](std::size_t i) {
            eomgen::Member<Door> m;
            m.params = params[i];
            return m;
        },
        eo, [&t](const eomgen::MemberResult<Door>& r) { t[r.index] = r.ok ? r.t : NAN; });
    return t;
}

}  // namespace gpu_bench
