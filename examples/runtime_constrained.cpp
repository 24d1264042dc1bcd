// docs/runtime.md, "Constraints": the pendulum of models/pendulum_cartesian.toml in x and y with its rod.
#include "eomgen/constraints.hpp"
#include "eomgen/models/pendulum_cartesian.hpp"

#include <cmath>
#include <iostream>

using Pendulum = eomgen::models::pendulum_cartesian::Model<double>;

int main() {
    Pendulum::Params p;
    Pendulum::State x0 = Pendulum::default_state();  // on the rod: x = sin 0.5, y = -cos 0.5, at rest
    std::vector<double> times;                        // projected back onto the constraints at each
    for (int k = 1; k <= 100; ++k) times.push_back(0.1 * k);
    eomgen::Dopri5Options<double> options;
    options.rtol = 1e-10;
    options.atol = 1e-12;
    const auto r = eomgen::integrate_constrained<Pendulum>(p, 0.0, x0, times, options);
    Pendulum::ConstraintVector lambda;
    Pendulum::multipliers(r.run.t, r.run.x, p, lambda);
    std::cout << "t = " << r.run.t << ": x = " << r.run.x(0) << ", y = " << r.run.x(1) << "\n";
    std::cout << "rod length " << std::hypot(r.run.x(0), r.run.x(1)) << ", multiplier " << lambda(0) << " "
              << Pendulum::multiplier_units[0] << "\n";
    std::cout << "largest drift before a projection: " << r.max_position_residual << " (position), "
              << r.max_velocity_residual << " (velocity)\n";
}
