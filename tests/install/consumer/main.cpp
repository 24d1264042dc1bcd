// Half a period of the oscillator from x = 1 at rest: x must come back as -1 (the period is 2 pi sqrt(m/k)).
// Prints the parameters' defaults so the test can see an edited model file take effect.
#include "eomgen/integrate.hpp"
#include "eomgen/models/oscillator.hpp"

#include <cmath>
#include <cstdio>

int main() {
    using Model = eomgen::models::oscillator::Model<double>;
    const Model::Params p;
    auto f = [&p](const double& t, const Model::State& x, Model::State& xdot) { Model::rhs(t, x, p, xdot); };
    eomgen::Dopri5Options<double> opt;
    opt.rtol = 1e-12;
    opt.atol = 1e-14;
    const double half = std::acos(-1.0) * std::sqrt(p.m / p.k);
    const auto r = eomgen::integrate(f, 0.0, Model::default_state(), half, opt);
    std::printf("k = %g: x(T/2) = %.12f\n", p.k, r.x(0));
    return std::abs(r.x(0) + 1.0) < 1e-8 ? 0 : 1;
}
