/** @file door_sweep.cpp  An app sweeping its linked model with eomgen::ensemble: the door's closing time over the hinge
 * tilt θ on every core, each member against the closed form Δt = 1.5138456348·√(w/(g sin θ)). */
#include "eomgen/ensemble.hpp"
#include "eomgen/models/door.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

using Door = eomgen::models::door::Model<double>;
const double kPi = std::acos(-1.0);

}  // namespace

int main(int argc, char** argv) {
    const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 12;
    if (n < 2) {
        std::fprintf(stderr, "usage: door_sweep [members >= 2]\n");
        return 2;
    }
    auto theta = [n](std::size_t i) { return 0.02 + (kPi / 2 - 0.02) * double(i) / double(n - 1); };
    eomgen::EnsembleOptions opt;
    opt.simulation.until = "psi=-pi/2";  // the door is shut
    opt.simulation.t_end = 100;
    opt.simulation.rtol = 1e-12;
    opt.simulation.atol = 1e-15;
    opt.threads = 0;  // every core
    // Closed form: √(w/(3 g sin θ)) ∫₀^{π/2} dψ/√(sin ψ), the integral (√π/2) Γ(1/4)/Γ(3/4).
    const double c = std::sqrt(kPi / 3) / 2 * std::tgamma(0.25) / std::tgamma(0.75);
    double worst = 0;
    std::printf("%8s %16s %16s %9s\n", "theta", "dt simulated", "dt closed form", "rel.err");
    eomgen::ensemble<Door>(
        n,
        [&theta](std::size_t i) {
            eomgen::Member<Door> m;  // the model's default parameters (w = 0.9 m, g = 9.8) and state (rest at 0)
            m.params.theta = theta(i);
            return m;
        },
        opt,
        [&](const eomgen::MemberResult<Door>& r) {  // in member order, whatever the threads
            const Door::Params p;
            const double exact = c * std::sqrt(p.w / (p.g * std::sin(theta(r.index))));
            if (!r.ok) {
                std::printf("%8.5f failed: %s\n", theta(r.index), r.error.c_str());
                worst = INFINITY;
                return;
            }
            const double err = std::abs(r.t - exact) / exact;
            worst = std::max(worst, err);
            std::printf("%8.5f %16.12f %16.12f %9.1e\n", theta(r.index), r.t, exact, err);
        });
    std::printf("largest relative error: %.1e\n", worst);
    return worst <= 1e-9 ? 0 : 1;
}
