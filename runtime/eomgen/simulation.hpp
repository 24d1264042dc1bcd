/**
 * @file simulation.hpp  The simulation driver of `eomgen-sim` (compiled-in models) and `eomgen run` (any
 * model file, compiled on demand): options, initial state and parameters from NAME=VALUE strings,
 * integration by the chosen method, the report on stdout and the CSV. One implementation for both.
 */
#pragma once

#include "eomgen/sample_csv.hpp"
#include "eomgen/sensitivity_run.hpp"
#include "eomgen/simulation_options.hpp"
#include "eomgen/column_units.hpp"
#include "eomgen/constraints.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/sliding.hpp"
#include "eomgen/model_jacobian.hpp"
#include "eomgen/model_traits.hpp"
#include "eomgen/output.hpp"
#include "eomgen/progress.hpp"
#include "eomgen/radau5.hpp"
#include "eomgen/symplectic.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace eomgen::sim {

/// What one integration gave: where and how it ended, the samples when asked for, the energy's drift.
template <class M>
struct Trajectory {
    using State = typename M::State;
    double t = 0;            ///< where it ended: t_end, or the terminal event's time
    State x;                 ///< the state there
    std::string stopped_by;  ///< the terminal event's name, "" when t_end was reached
    double h0 = 0;           ///< the energy at the start (after a projection onto the constraints)
    double max_drift = 0;    ///< the largest change of h from h0 at the samples (and steps), relative unless h0 = 0
    std::vector<eomgen::Sample<State>> samples;  ///< at o.samples + 1 times when keep_samples
    /// Where h is not conserved (M::power, unconstrained, an explicit method): the work W(t) = ∫ P dt at each
    /// sample, integrated with the state, and the balance's largest |h(t) − h(0) − W(t)|; empty and 0 otherwise.
    std::vector<double> work;
    double max_imbalance = 0;
};

/**
 * Integrates M from (0, x0) to o.t_end with o's method, tolerances and steps, stopping at a terminal event
 * of `events` (until_events()). With keep_samples the state is sampled at o.samples + 1 times on [0, t_end]
 * and the energy's drift measured there; without, only the end is computed (a constrained model is still
 * projected at those times, which is its drift control). What the method did is written to `log` when not
 * null (what eomgen-sim prints). Throws UsageError for a method the model cannot take and the runtime's
 * SimulationError when the integration fails.
 */
template <class M>
Trajectory<M> simulate(const Options& o, const typename M::Params& params, const typename M::State& x0,
                       const std::vector<eomgen::Event<typename M::State>>& terminal_events, bool keep_samples,
                       std::ostream* log) {
    using State = typename M::State;
    using Config = typename M::Config;
    check_method_for<M>(o);
    std::vector<eomgen::Event<State>> events = terminal_events;
    for (auto& e : switch_events<M>(o, params)) events.push_back(std::move(e));
    auto h = [&params](double t, const State& x) {
        const Config q = positions<M::nq>(x), qd = velocities<M::nq>(x);
        return M::energy(t, q, qd, params);
    };
    eomgen::ProgressMeter meter(&std::cerr, o.progress, o.t_end);
    unsigned long rhs_calls = 0;
    auto f = [&params, &meter, &rhs_calls](const double& t, const State& x, State& xdot) {
        M::rhs(t, x, params, xdot);
        if (meter.active() && (++rhs_calls & 63u) == 0) meter.at(t);
    };

    // Sticking (Filippov sliding along a jump of f, as friction holding a block to a belt) is followed by the
    // explicit adaptive methods (integrate_sliding; integrate_constrained for constrained models). rk4 and radau5
    // stop where the motion would stick and say so, rather than chatter across the jump or give a wrong answer.
    const bool follows_sticking = o.method != "rk4" && o.method != "radau5";
    const std::vector<std::string> sticking_names =
        follows_sticking ? std::vector<std::string>{}
                         : eomgen::stop_where_sliding(events, [&params](const double& t, const State& x, State& xdot) {
                               M::rhs(t, x, params, xdot);
                           });
    const auto refuse = [&](const std::string& surface, double t) {
        std::ostringstream os;
        os.precision(15);
        os << "the motion sticks on " << surface << " at t = " << t
           << " (both sides of its jump push into it, as static friction holds a block): "
           << "--method " << o.method << " does not follow sticking; dopri5, dop853 and adams do"
           << " (docs/model_files.md, Sticking)";
        throw eomgen::SimulationError(os.str(), t);
    };
    const auto refuse_sticking = [&](const auto& r) {
        if (r.stop_reason == eomgen::StopReason::TerminalEvent &&
            std::find(sticking_names.begin(), sticking_names.end(), r.stopped_by) != sticking_names.end())
            refuse(r.stopped_by, r.t);
    };
    // A start on a surface that holds the motion (a door released at rest against its hinges' friction).
    for (const eomgen::Event<State>& e : events)
        if (std::find(sticking_names.begin(), sticking_names.end(), e.name) != sticking_names.end() &&
            e.g(0.0, x0) == 0.0 && e.stop_at_switch(0.0, x0))
            refuse(e.name, 0.0);

    Trajectory<M> out;
    out.x = x0;
    out.h0 = h(0, x0);
    // Relative to h(0), or absolute where h(0) is 0 (or nearly: a relative error would be meaningless).
    auto drift = [&out](double value) {
        return std::abs(value - out.h0) / (std::abs(out.h0) < 1e-12 ? 1.0 : std::abs(out.h0));
    };
    auto track = [&](double t, const State& x) { out.max_drift = std::max(out.max_drift, drift(h(t, x))); };

    std::vector<double> sample_times;
    const bool constrained = constraint_count<M>() > 0 && is_adaptive_method(o.method);
    if (keep_samples || constrained)
        for (int k = 0; k <= o.samples; ++k) sample_times.push_back(o.t_end * k / std::max(o.samples, 1));

    // What every method reports about how the run ended.
    auto report_run = [log](const auto& r) {
        if (!log) return;
        *log << "steps:   " << r.accepted_steps << " accepted, " << r.rejected_steps << " rejected, "
             << r.rhs_evaluations << " right-hand sides\n";
        for (const auto& e : r.events) *log << "event:   " << e.name << " at t = " << e.t << "\n";
        if (!r.switches.empty())
            *log << "switches: " << r.switches.size() << " (steps ended where " << r.switches.front().name
                 << (r.switches.size() > 1 ? " and the others" : "") << " switched; first at t = "
                 << r.switches.front().t << ")\n";
        *log << "stopped: "
             << (r.stop_reason == eomgen::StopReason::TerminalEvent ? "at event " + r.stopped_by : "at t_end") << "\n";
    };
    auto finish = [&out](const auto& r) {
        out.t = r.t;
        out.x = r.x;
        if (r.stop_reason == eomgen::StopReason::TerminalEvent) out.stopped_by = r.stopped_by;
    };

    bool done = false;
    if constexpr (is_constrained<M>::value) {
        if (constrained)
            done = with_adaptive_method(o.method, [&](auto method) {
                using Method = decltype(method);
                const auto r = eomgen::integrate_constrained<M, Method::template type>(
                    params, 0.0, x0, sample_times, Method::template options<State>(o), o.project_initial, events,
                    [&meter](const double& t, const State&) { meter.at(t); });
                meter.finish();
                refuse_sticking(r.run);
                // Energy drift from the (possibly projected) start, not from the state given.
                out.h0 = h(r.run.samples.front().t, r.run.samples.front().x);
                for (const auto& s : r.run.samples) out.max_drift = std::max(out.max_drift, drift(h(s.t, s.x)));
                if (keep_samples) out.samples = r.run.samples;
                if (log) {
                    typename M::ConstraintVector lambda;
                    M::multipliers(r.run.t, r.run.x, params, lambda);
                    *log << "method:  " << o.method << " with projection onto the constraints after each of "
                         << o.samples << " segments, rtol " << o.rtol << ", atol " << o.atol << "\n";
                    report_run(r.run);
                    *log << "constraint residuals before projection: position " << r.max_position_residual
                         << ", velocity " << r.max_velocity_residual << "\n";
                    for (int k = 0; k < M::n_constraints; ++k)
                        *log << "multiplier " << M::constraint_names[std::size_t(k)] << " = " << lambda(k)
                             << " at the end\n";
                }
                finish(r.run);
            });
    }
    if (!done && o.method == "symplectic") {
        if (constraint_count<M>() > 0 || M::has_generalized_forces)
            throw UsageError(
                "--method symplectic integrates unconstrained models without forces; use dopri5, dop853 or adams");
        eomgen::VariationalIntegrator<M> vi(params, o.dt);
        vi.set_state(0.0, positions<M::nq>(x0), velocities<M::nq>(x0));
        const auto steps = static_cast<std::size_t>(std::llround(o.t_end / o.dt));
        const std::size_t every = std::max<std::size_t>(1, steps / std::size_t(std::max(o.samples, 1)));
        if (keep_samples) out.samples.push_back({0.0, x0});
        for (std::size_t k = 1; k <= steps; ++k) {
            vi.step();
            State x = x0;
            positions<M::nq>(x) = vi.q();  // not `x << q, qd`: g++ 12 warns falsely for 1×1 blocks
            velocities<M::nq>(x) = vi.velocity();
            track(vi.t(), x);
            if (keep_samples && (k % every == 0 || k == steps)) out.samples.push_back({vi.t(), x});
            if (meter.active() && k % 64 == 0) meter.at(vi.t());
            out.x = x;
        }
        out.t = vi.t();
        meter.finish();
        if (log) *log << "method:  variational midpoint, dt " << std::to_string(o.dt) << ", " << steps << " steps\n";
    } else if (!done && keep_samples && power_available<M>() && o.method != "radau5") {
        if constexpr (declares_power<M>::value) {
            // The energy balance: W' = P beside the state (one more component, under the same error control), so
            // that h(t) − h(0) − W(t) checks the integration where h itself is not conserved.
            constexpr int na = M::nx == Eigen::Dynamic ? Eigen::Dynamic : M::nx + 1;
            using Aug = Eigen::Matrix<double, na, 1>;
            const Eigen::Index nx = x0.size();
            const auto split = [nx](const Aug& xa) { return State(xa.head(nx)); };
            auto fa = [&](const double& t, const Aug& xa, Aug& xdota) {
                const State x = split(xa);
                State xdot = x;
                f(t, x, xdot);
                xdota.resize(nx + 1);
                xdota.head(nx) = xdot;
                xdota(nx) = M::power(t, positions<M::nq>(x), velocities<M::nq>(x), params);
            };
            std::vector<eomgen::Event<Aug>> ea;
            for (const auto& e : events) {
                eomgen::Event<Aug> a{e.name, [g = e.g, split](const double& t, const Aug& xa) { return g(t, split(xa)); },
                                     e.direction, e.action};
                if (e.stop_at_switch)
                    a.stop_at_switch = [h = e.stop_at_switch, split](const double& t, const Aug& xa) { return h(t, split(xa)); };
                ea.push_back(std::move(a));
            }
            Aug xa0(nx + 1);
            xa0.head(nx) = x0;
            xa0(nx) = 0;
            const eomgen::Observer<Aug> watch = [&](const double& t, const Aug& xa) {
                const State x = split(xa);
                track(t, x);
                out.samples.push_back({t, x});
                out.work.push_back(xa(nx));
                out.max_imbalance = std::max(out.max_imbalance, std::abs(h(t, x) - out.h0 - xa(nx)));
            };
            eomgen::IntegrationResult<Aug> r;
            if (o.method == "rk4") {
                r = eomgen::integrate_rk4(fa, 0.0, xa0, o.t_end, o.dt, ea, sample_times, watch);
                if (log) *log << "method:  rk4, dt " << o.dt << "\n";
            } else if (!with_adaptive_method(o.method, [&](auto method) {
                           using Method = decltype(method);
                           r = eomgen::integrate_sliding<Method::template type>(fa, 0.0, xa0, o.t_end,
                                                                               Method::template options<Aug>(o), ea,
                                                                               sample_times, watch);
                           if (log) *log << "method:  " << o.method << ", rtol " << o.rtol << ", atol " << o.atol << "\n";
                       })) {
                throw UsageError("--method " + o.method + ": expected dopri5, dop853, adams, radau5, rk4 or symplectic");
            }
            refuse_sticking(r);
            out.t = r.t;
            out.x = split(r.x);
            if (r.stop_reason == eomgen::StopReason::TerminalEvent) out.stopped_by = r.stopped_by;
            track(r.t, out.x);
            meter.finish();
            report_run(r);
        }
    } else if (!done) {
        eomgen::Observer<State> observer;
        if (keep_samples)
            observer = [&](const double& t, const State& x) {
                track(t, x);
                out.samples.push_back({t, x});
            };
        eomgen::IntegrationResult<State> r;
        if (o.method == "rk4") {
            r = eomgen::integrate_rk4(f, 0.0, x0, o.t_end, o.dt, events, sample_times, observer);
            if (log) *log << "method:  rk4, dt " << o.dt << "\n";
        } else if (o.method == "radau5") {
            eomgen::Radau5Options<double> opt;
            opt.rtol = o.rtol;
            opt.atol = o.atol;
            opt.max_steps = o.max_steps;
            const auto jac = [&params](const double& t, const State& x, auto& J) {
                eomgen::model_jacobian<M>(t, x, params, J);
            };
            const auto rr = eomgen::integrate_radau5(f, jac, 0.0, x0, o.t_end, opt, events, sample_times, observer);
            r = rr;
            if (log)
                *log << "method:  radau5 (implicit, exact Jacobian), rtol " << o.rtol << ", atol " << o.atol << "; "
                     << rr.jacobian_evaluations << " Jacobians, " << rr.lu_decompositions << " LU decompositions\n";
        } else if (!with_adaptive_method(o.method, [&](auto method) {
                       using Method = decltype(method);
                       // Sliding along a switching surface (sticking friction) where the model has them.
                       r = eomgen::integrate_sliding<Method::template type>(f, 0.0, x0, o.t_end,
                                                                           Method::template options<State>(o),
                                                                           events, sample_times, observer);
                       if (log) *log << "method:  " << o.method << ", rtol " << o.rtol << ", atol " << o.atol << "\n";
                   })) {
            throw UsageError("--method " + o.method + ": expected dopri5, dop853, adams, radau5, rk4 or symplectic");
        }
        refuse_sticking(r);
        finish(r);
        track(r.t, r.x);
        meter.finish();
        report_run(r);
    }
    return out;
}

/// Each conserved quantity other than h (a cyclic momentum, a Noether symmetry's L_z) at the first and last
/// sample, and its largest change between, relative to its start unless that is 0.
template <class M>
void report_conserved(const typename M::Params& params, const std::vector<eomgen::Sample<typename M::State>>& samples,
                      std::ostream& os) {
    if (samples.empty()) return;
    std::vector<std::vector<double>> values;  // [sample][quantity]
    for (const auto& s : samples) {
        typename M::Conserved c;
        M::conserved(s.t, positions<M::nq>(s.x), velocities<M::nq>(s.x), params, c);
        values.emplace_back(c.data(), c.data() + c.size());
    }
    for (int k = 0; k < M::n_conserved; ++k) {
        const std::string name = M::conserved_names[std::size_t(k)];
        if (name == "h") continue;
        const double first = values.front()[std::size_t(k)], last = values.back()[std::size_t(k)];
        const bool absolute = std::abs(first) < 1e-12;
        double drift = 0;
        for (const auto& v : values) drift = std::max(drift, std::abs(v[std::size_t(k)] - first));
        if (!absolute) drift /= std::abs(first);
        const std::string unit = conserved_unit<M>(std::size_t(k)).empty() ? "" : " " + conserved_unit<M>(std::size_t(k));
        os << "conserved " << name << ": " << first << unit << " at t = " << samples.front().t << ", " << last << unit
           << " at the end; " << (absolute ? "max |d" + name + "| = " : "max |d" + name + "|/|" + name + "0| = ")
           << drift << (absolute ? unit + "  (absolute: it starts at 0)" : "") << "\n";
    }
}

/// One run as eomgen-sim and `eomgen run` make it: the settings, the integration, its report on stdout
/// and the CSV of its samples.
template <class M>
int run(const Options& o) {
    using State = typename M::State;
    if (!o.sensitivities.empty()) return run_sensitivities<M>(o);
    check_options(o);
    check_method_for<M>(o);
    typename M::Params params;
    State x0 = M::default_state();
    apply_settings<M>(o, params, x0);
    const auto events = until_events<M>(o);

    print_heading<M>(params, std::cout);

    const Trajectory<M> r = simulate<M>(o, params, x0, events, true, &std::cout);
    const double h_end = M::energy(r.t, positions<M::nq>(r.x), velocities<M::nq>(r.x), params);
    std::cout.precision(15);
    const std::string s = time_unit<M>().empty() ? "" : " s", J = energy_unit<M>().empty() ? "" : " " + energy_unit<M>();
    std::cout << "t:       " << r.t << s << "\n";
    for (Eigen::Index i = 0; i < r.x.size(); ++i)
        std::cout << "  " << M::state_names[std::size_t(i)] << " = " << r.x(i)
                  << (state_unit<M>(std::size_t(i)).empty() ? "" : " " + state_unit<M>(std::size_t(i))) << "\n";
    std::cout << "energy h: " << r.h0 << J << " at t = 0, " << h_end << J << " at the end; "
              << (std::abs(r.h0) < 1e-12 ? "max |dh| = " : "max |dh|/|h0| = ") << r.max_drift
              << (std::abs(r.h0) < 1e-12 ? J + "  (absolute: h0 is 0)" : "")
              << (M::explicit_time ? "  (L depends on t: h need not be conserved)" : "") << "\n";
    if (!r.work.empty())
        std::cout << "balance: W = " << r.work.back() << J << " (the work of the forces, int power dt); max |h - h0 - W| = "
                  << r.max_imbalance << J << " over the samples\n";
    report_conserved<M>(params, r.samples, std::cout);
    try {
        write_samples<M>(o, params, r.samples, r.work);
    } catch (const std::runtime_error& e) {
        throw OutputError(std::string("cannot write the CSV: ") + e.what());
    }
    return kExitOk;
}


/// run() with its errors reported on stderr as `<program>: message`; returns kExitOk, kExitUsage,
/// kExitSimulation or kExitOutput.
template <class M>
int run_reporting(const Options& o, const char* program) {
    try {
        return run<M>(o);
    } catch (const UsageError& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return kExitUsage;
    } catch (const OutputError& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return kExitOutput;
    } catch (const eomgen::InconsistentInitialConditions& e) {
        std::cerr << program << ": simulation failed: " << e.what()
                  << "\n  (give a state on the constraints with --init, or --project-initial to project this one onto them)\n";
        return kExitSimulation;
    } catch (const eomgen::SimulationError& e) {
        std::cerr << program << ": simulation failed: " << e.what() << "\n";
        return kExitSimulation;
    } catch (const std::exception& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return kExitSimulation;
    }
}

}  // namespace eomgen::sim
