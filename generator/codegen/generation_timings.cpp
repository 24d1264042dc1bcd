/** @file generation_timings.cpp  Phase times and peak memory of generating a header (generation_timings.hpp). */
#include "codegen/generation_timings.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <chrono>
#include <utility>

namespace eomgen::codegen {

namespace {

double now_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double peak_resident_mb() {
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

}  // namespace

void GenerationTimings::add(std::string name, double seconds) {
    phases.push_back({std::move(name), seconds, peak_resident_mb()});
}

std::string GenerationTimings::table(const std::string& what) const {
    std::string out = fmt::format("{}: generation phases\n  {:<34} {:>9} {:>12}\n", what, "phase", "seconds", "peak MB");
    double total = 0;
    for (const Phase& p : phases) {
        out += fmt::format("  {:<34} {:>9.3f} {:>12.1f}\n", p.name, p.seconds, p.peak_mb);
        total += p.seconds;
    }
    out += fmt::format("  {:<34} {:>9.3f} {:>12.1f}\n", "total", total, peak_resident_mb());
    return out;
}

PhaseClock::PhaseClock(GenerationTimings* out) : out_(out), start_(out ? now_seconds() : 0) {}

void PhaseClock::lap(const std::string& name) {
    if (!out_) return;
    const double t = now_seconds();
    out_->add(name, t - start_);
    start_ = t;
}

}  // namespace eomgen::codegen
