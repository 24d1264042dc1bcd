/** @file time_derive_prototype.cpp  Measures where derive_equations' time goes and what a faster derivation
 * gives. */
// Usage: time_derive_prototype FAMILY:n=N...   (e.g. pendulum:n=16). Not part of run.sh's tables: the
// experiment behind the "derive" notes in docs/benchmarks.md. Each line: derive_equations' time, then a
// prototype that builds M and f of the same model (unconstrained, no forces) with two changes, and the
// largest relative difference of its M and f from derive_equations' at random points.
//  1. sin(q_i) and cos(q_i) are plain symbols s_i, c_i while differentiating (∂/∂q_i e = ∂e/∂q_i|explicit
//     + ∂e/∂s_i c_i − ∂e/∂c_i s_i), because GiNaC's function::derivative throws and catches an exception for
//     every sin/cos it differentiates (no explicit derivative registered: it falls back to the chain rule in
//     a catch block);
//  2. f_i = 2 ∂L/∂q_i − ∂D/∂q̇_i − ∂p_i/∂t with D = Σ_j (∂L/∂q_j) q̇_j, since ∂D/∂q̇_i = Σ_j ∂²L/∂q̇_i∂q_j q̇_j +
//  ∂L/∂q_i:
//     n derivatives of one sum instead of the n² derivatives ∂p_i/∂q_j.
#include "mechanics/lagrangian.hpp"
#include "model/families.hpp"
#include "model/model_file.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

double value(const GiNaC::ex& e, const GiNaC::exmap& at) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
}

}  // namespace

int main(int argc, char** argv) {
    for (int a = 1; a < argc; ++a) {
        const eomgen::Model model =
            eomgen::parse_model(eomgen::family_model_text(eomgen::parse_family_spec(argv[a])), argv[a]);
        const std::size_t n = model.dof();
        auto start = std::chrono::steady_clock::now();
        const eomgen::Equations ref = eomgen::derive_equations(model);
        const double t_ref = seconds_since(start);

        start = std::chrono::steady_clock::now();
        std::vector<GiNaC::symbol> s(n), c(n);
        GiNaC::exmap to_symbols, to_functions;
        for (std::size_t i = 0; i < n; ++i) {
            const GiNaC::ex q = model.coordinates[i].q;
            to_symbols[GiNaC::sin(q)] = s[i];
            to_symbols[GiNaC::cos(q)] = c[i];
            to_functions[s[i]] = GiNaC::sin(q);
            to_functions[c[i]] = GiNaC::cos(q);
        }
        const GiNaC::ex L = (model.T.expr - model.V.expr).subs(to_symbols);
        auto d_dq = [&](const GiNaC::ex& e, std::size_t i) {
            return GiNaC::diff(e, model.coordinates[i].q) + GiNaC::diff(e, s[i]) * c[i] -
                   GiNaC::diff(e, c[i]) * s[i];
        };
        std::vector<GiNaC::ex> p(n), dLdq(n), f(n);
        for (std::size_t i = 0; i < n; ++i) {
            p[i] = GiNaC::diff(L, model.coordinates[i].qd);
            dLdq[i] = d_dq(L, i);
        }
        GiNaC::matrix M{static_cast<unsigned>(n), static_cast<unsigned>(n)};
        for (unsigned i = 0; i < n; ++i)
            for (unsigned j = i; j < n; ++j) M(i, j) = M(j, i) = GiNaC::diff(p[i], model.coordinates[j].qd);
        GiNaC::ex D = 0;
        for (std::size_t j = 0; j < n; ++j) D += dLdq[j] * model.coordinates[j].qd;
        for (std::size_t i = 0; i < n; ++i)
            f[i] = (2 * dLdq[i] - GiNaC::diff(D, model.coordinates[i].qd) - GiNaC::diff(p[i], model.t))
                       .subs(to_functions);
        for (unsigned i = 0; i < n; ++i)
            for (unsigned j = i; j < n; ++j) M(i, j) = M(j, i) = M(i, j).subs(to_functions);
        const double t_proto = seconds_since(start);

        double worst = 0;
        for (unsigned seed = 21; seed <= 22; ++seed) {
            const GiNaC::exmap at = eomgen::random_point(model, seed);
            for (unsigned i = 0; i < n; ++i) {
                const double fr = value(ref.f[i], at), fp = value(f[i], at);
                worst = std::max(worst, std::abs(fr - fp) / std::max(1.0, std::abs(fr)));
                for (unsigned j = 0; j < n; ++j) {
                    const double mr = value(ref.M(i, j), at), mp = value(M(i, j), at);
                    worst = std::max(worst, std::abs(mr - mp) / std::max(1.0, std::abs(mr)));
                }
            }
        }
        std::printf(
            "%s: derive_equations %.3f s; prototype M and f %.3f s (%.1fx); max relative difference %.1e\n",
            argv[a], t_ref, t_proto, t_ref / t_proto, worst);
        std::fflush(stdout);
    }
    return 0;
}
