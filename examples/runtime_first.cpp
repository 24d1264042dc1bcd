// docs/runtime.md, "A first program": the door of models/door.toml, integrated until it shuts.
#include "eomgen/column_units.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/models/door.hpp"

#include <cmath>
#include <iostream>

using Door = eomgen::models::door::Model<double>;

int main() {
    Door::Params p;        // the model file's values, in SI
    p.theta = 0.1;         // a steeper hinge than the file's 0.0234 rad
    Door::State x0 = Door::default_state();  // the file's initial values: psi = 0, psi' = 0
    auto f = [&p](const double& t, const Door::State& x, Door::State& xdot) { Door::rhs(t, x, p, xdot); };

    // Stop where psi falls through -pi/2 (shut).
    const double pi = std::acos(-1.0);
    eomgen::Event<Door::State> shut{"shut", [pi](const double&, const Door::State& x) { return x(0) + pi / 2; },
                                    eomgen::EventDirection::Falling, eomgen::EventAction::Stop};
    eomgen::Dopri5Options<double> options;
    options.rtol = 1e-10;  // eomgen run's defaults; the library's own are 1e-6 and 1e-9
    options.atol = 1e-12;
    const std::vector<double> samples{0.0, 0.5, 1.0};  // the state at these times, from the dense output
    try {
        const auto r = eomgen::integrate(f, 0.0, x0, 100.0, options, {shut}, samples);
        std::cout << "stopped by " << r.stopped_by << " at t = " << r.t << " " << eomgen::time_unit<Door>() << "\n";
        for (const auto& s : r.samples)
            std::cout << "t = " << s.t << ": " << Door::state_names[0] << " = " << s.x(0) << " "
                      << eomgen::state_unit<Door>(0) << "\n";
        std::cout << r.accepted_steps << " steps, " << r.rhs_evaluations << " right-hand sides\n";
        const double h0 = Door::energy(0.0, x0.head<Door::nq>(), x0.tail<Door::nq>(), p);
        const double h1 = Door::energy(r.t, r.x.head<Door::nq>(), r.x.tail<Door::nq>(), p);
        std::cout << "energy drift " << std::abs(h1 - h0) / std::abs(h0) << "\n";
    } catch (const eomgen::SimulationError& e) {  // a singular M, a state that is not finite, too many steps
        std::cerr << "failed at t = " << e.t() << ": " << e.what() << "\n";
        return 1;
    }
}
