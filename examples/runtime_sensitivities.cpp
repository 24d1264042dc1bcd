// docs/sensitivities.md, "In a program": how the door's closing time depends on its hinge's tilt and on where it starts.
#include "eomgen/models/door.hpp"
#include "eomgen/sensitivities.hpp"

#include <cmath>
#include <iostream>

using Door = eomgen::models::door::Model<double>;

int main() {
    const std::vector<eomgen::SensitivityColumn> columns{eomgen::parameter_column(Door::param_names, "theta"),
                                                         eomgen::initial_column(Door::state_names, "psi")};
    eomgen::Dop853Options<double> options;
    options.rtol = 1e-12;
    options.atol = 1e-14;
    const double pi = std::acos(-1.0);
    const auto r = eomgen::integrate_sensitivities<Door, eomgen::Dop853>(
        Door::Params{}, 0.0, Door::default_state(), 10.0, columns, options,
        {eomgen::state_crossing("shut", 0, -pi / 2)}, /*sample_times=*/{0.0, 1.0, 2.0});
    // r.S: dx/d(theta, psi0) where the run ended; r.samples[k].S at the sample times; r.events[0].dt: dt*/d(theta,
    // psi0); r.events[0].dx = S + x' dt, the state's total derivative at the event.
    const auto& shut = r.events.at(0);
    const double theta = Door::Params{}.theta;
    std::cout.precision(12);
    std::cout << "shut at t = " << shut.t << " s; dt/dtheta = " << shut.dt(0) << " s/rad (closed form "
              << -shut.t / (2 * std::tan(theta)) << "), dt/dpsi0 = " << shut.dt(1) << " s/rad\n";
    std::cout << "at t = 1 s: dpsi/dtheta = " << r.samples.at(1).S(0, 0) << "\n";
}
