/** @file options.hpp  The command-line options of a simulation, shared by `eomgen-sim` and `eomgen run`. */
#pragma once

#include "eomgen/simulation.hpp"

#include <CLI/CLI.hpp>

namespace eomgen::sim {

/// Adds --t-end, --method, --rtol, --atol, --dt, --set, --init, --until, --sensitivities, --state-error-only, --csv,
/// --samples, --max-steps and --project-initial to `app`, writing into `o`.
inline void add_options(CLI::App& app, Options& o) {
    app.add_option("--t-end", o.t_end, "End time")->capture_default_str();
    app.add_option("--method", o.method,
                   "dopri5 (adaptive, 5th order), dop853 (adaptive, 8th order: cheaper at tight tolerances), "
                   "adams (Adams-Bashforth-Moulton of variable order 1-12: fewest evaluations of f on smooth models at "
                   "tight tolerances), "
                   "radau5 (implicit, for stiff models), rk4 (fixed step), symplectic (variational midpoint)")
        ->capture_default_str();
    app.add_option("--rtol", o.rtol, "Relative tolerance (dopri5, dop853, adams, radau5)")->capture_default_str();
    app.add_option("--atol", o.atol, "Absolute tolerance (dopri5, dop853, adams, radau5)")->capture_default_str();
    app.add_option("--dt", o.dt, "Step size (rk4, symplectic)");
    app.add_option("--set", o.set, "Parameter value, NAME=VALUE (repeatable; VALUE may use pi: -pi/2)");
    app.add_option("--init", o.init, "Initial state, NAME=VALUE with NAME a coordinate or NAME_dot (repeatable)");
    app.add_option("--until", o.until, "Stop when a state crosses a value, NAME=VALUE (e.g. psi=-pi/2)");
    app.add_option("--sensitivities", o.sensitivities,
                   "Integrate dx/d(...) with the state: parameters NAME and initial values x0:STATE, comma-separated "
                   "(e.g. theta,x0:psi); S at the end on stdout, its columns in the CSV")
        ->delimiter(',');
    app.add_flag("--state-error-only", o.state_error_only,
                 "With --sensitivities: the state alone sets the steps (S left out of the error norm: fewer steps, "
                 "S as accurate as those steps make it)");
    app.add_option("--csv", o.csv, "Write samples (state, energy, conserved quantities) to this CSV file");
    app.add_option("--samples", o.samples, "Number of sample intervals on [0, t_end] for the CSV")->capture_default_str();
    app.add_option("--max-steps", o.max_steps, "Largest number of steps (dopri5, dop853, adams, radau5)")->capture_default_str();
    app.add_flag("--project-initial", o.project_initial,
                 "Project inconsistent initial conditions onto the constraints instead of refusing them");
    app.add_flag("--no-switch-events{false}", o.switch_events,
                 "Step across the switching surfaces of abs, sign, heaviside, max and min instead of ending the "
                 "steps of the adaptive methods there");
}

}  // namespace eomgen::sim
