// The loop that the Python module's Model.rhs runs, written in C++ (bench/python_api.py, docs/benchmarks.md
// section 13): a compiled model's shared object from the cache loaded with dlopen, its table's rhs called on each
// row of N states read from a file of raw doubles (N × 2n, row-major), with the model's default parameters; the
// best of R passes in nanoseconds per state on stdout; the results written to RESULTS_FILE (raw doubles), to be
// compared with the module's.
//
// Usage: time_table_rhs SHARED_OBJECT STATES_FILE N REPEATS RESULTS_FILE
#include "eomgen/model_table.hpp"

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <vector>

#include <dlfcn.h>

int main(int argc, char** argv) {
    if (argc != 6) {
        std::fprintf(stderr, "usage: time_table_rhs SHARED_OBJECT STATES_FILE N REPEATS RESULTS_FILE\n");
        return 2;
    }
    void* handle = ::dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        std::fprintf(stderr, "time_table_rhs: %s\n", ::dlerror());
        return 1;
    }
    using Entry = const eomgen::ModelTable* (*)();
    auto entry = reinterpret_cast<Entry>(::dlsym(handle, "eomgen_model_table"));
    if (!entry) {
        std::fprintf(stderr, "time_table_rhs: no eomgen_model_table in %s\n", argv[1]);
        return 1;
    }
    const eomgen::ModelTable& table = *entry();
    const std::size_t n = std::strtoull(argv[3], nullptr, 10), nx = 2 * std::size_t(table.nq);
    const int repeats = std::atoi(argv[4]);
    std::vector<double> x(n * nx), xdot(n * nx);
    std::ifstream in(argv[2], std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(x.data()), std::streamsize(x.size() * sizeof(double)))) {
        std::fprintf(stderr, "time_table_rhs: %s does not hold %zu states of %zu values\n", argv[2], n, nx);
        return 1;
    }
    std::vector<std::max_align_t> params(table.params_size / sizeof(std::max_align_t) + 2);
    table.init_params(params.data());
    double best = 1e300;
    for (int r = 0; r < repeats; ++r) {
        const auto start = std::chrono::steady_clock::now();
        for (std::size_t k = 0; k < n; ++k)
            if (table.rhs(0.0, x.data() + k * nx, params.data(), xdot.data() + k * nx) != 0) return 1;
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (s < best) best = s;
    }
    std::ofstream out(argv[5], std::ios::binary);
    if (!out.write(reinterpret_cast<const char*>(xdot.data()), std::streamsize(xdot.size() * sizeof(double)))) {
        std::fprintf(stderr, "time_table_rhs: cannot write %s\n", argv[5]);
        return 1;
    }
    std::printf("%.6f\n", best * 1e9 / double(n));
    return 0;
}
