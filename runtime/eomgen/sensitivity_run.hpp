/**
 * @file sensitivity_run.hpp  `eomgen run MODEL --sensitivities theta,x0:psi` (and eomgen-sim's): the trajectory
 * with S = ∂x/∂(θ, ψ(0)) integrated beside it (sensitivities.hpp), S at the end on stdout, a terminal event's
 * ∂t⁎/∂(…), and S's columns in the CSV after the usual ones: `dpsi/dtheta [1]`, `dpsi_dot/dpsi(0) [1/s]`, then the
 * declared outputs' (`dz_c/dtheta [m/rad]`) and a constrained model's multipliers' (`dlambda_rod/dg`).
 */
#pragma once

#include "eomgen/column_units.hpp"
#include "eomgen/constraints.hpp"
#include "eomgen/sample_csv.hpp"
#include "eomgen/sensitivities.hpp"
#include "eomgen/simulation_options.hpp"
#include "eomgen/variational_sensitivities.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>
#include <string>
#include <vector>

namespace eomgen::sim {

/// One requested column: what it differentiates by, its name in headers ("theta", "psi(0)") and that name's unit.
struct SensitivityLabel {
    SensitivityColumn column;
    std::string name, unit;
};

/// "a/b" of two units, "" where either is unknown: "1" where they are the same, "1/s" for rad/s over rad, b in
/// parentheses when compound.
inline std::string unit_ratio(const std::string& a, const std::string& b) {
    if (a.empty() || b.empty()) return "";
    if (a == b) return "1";
    if (a.rfind(b + "/", 0) == 0 && a.find_first_of("/* ", b.size() + 1) == std::string::npos)
        return "1/" + a.substr(b.size() + 1);
    const bool compound = b.find_first_of("/* ") != std::string::npos;
    return a + "/" + (compound ? "(" + b + ")" : b);
}

/// The columns of --sensitivities: NAME a parameter, x0:NAME an initial value (a coordinate or NAME_dot).
/// UsageError for an unknown name or one given twice.
template <class M>
std::vector<SensitivityLabel> sensitivity_labels(const Options& o) {
    std::vector<SensitivityLabel> labels;
    std::set<std::string> seen;
    for (const std::string& given : o.sensitivities) {
        std::string spec = given;
        spec.erase(0, spec.find_first_not_of(' '));
        spec.erase(spec.find_last_not_of(' ') + 1);
        if (spec.empty()) throw UsageError("--sensitivities: an empty name (expected NAME or x0:NAME, comma-separated)");
        if (!seen.insert(spec).second) throw UsageError("--sensitivities " + spec + ": given twice");
        if (spec.rfind("x0:", 0) == 0) {
            const std::string name = spec.substr(3);
            const int i = index_of(M::state_names, name);
            if (i < 0)
                throw UsageError("--sensitivities " + spec + ": no state '" + name + "'" +
                                 did_you_mean(name, M::state_names) + " (states: " + list(M::state_names) + ")");
            labels.push_back({{SensitivityColumn::Kind::InitialValue, i}, name + "(0)", state_unit<M>(std::size_t(i))});
        } else {
            const int k = index_of(M::param_names, spec);
            if (k < 0)
                throw UsageError("--sensitivities " + spec + ": " + std::string(M::name) + " has no parameter '" + spec +
                                 "'" + did_you_mean(spec, M::param_names) + " (it has " + list(M::param_names) +
                                 "; an initial value is x0:NAME)");
            labels.push_back({{SensitivityColumn::Kind::Parameter, k}, spec, param_unit<M>(std::size_t(k))});
        }
    }
    return labels;
}

/// integrate_sensitivities (or its radau5, rk4 or variational form) by o's method, tolerances and steps (o.dt for rk4
/// and symplectic); dopri5, dop853, adams, radau5, rk4 or symplectic (UsageError otherwise).
template <class M>
SensitivityResult integrate_sensitivities_by(const Options& o, const typename M::Params& params,
                                             const typename M::State& x0, double t_end,
                                             const std::vector<SensitivityColumn>& columns,
                                             const std::vector<SensitivityEvent>& events,
                                             const std::vector<double>& sample_times) {
    // --state-error-only: the error norm counts the state's components only, not S's.
    const std::size_t counted = o.state_error_only ? std::size_t(x0.size()) : 0;
    if (o.method == "radau5") {
        Radau5Options<double> opt;
        opt.rtol = o.rtol;
        opt.atol = o.atol;
        opt.max_steps = o.max_steps;
        opt.error_components = counted;
        return integrate_sensitivities_radau5<M>(params, 0.0, x0, t_end, columns, opt, events, sample_times);
    }
    if (o.method == "rk4") return integrate_sensitivities_rk4<M>(params, 0.0, x0, t_end, o.dt, columns, events, sample_times);
    if (o.method == "symplectic") {
        if (!events.empty()) throw UsageError("--until needs --method dopri5, dop853, adams, radau5 or rk4 (events use dense output)");
        return integrate_sensitivities_symplectic<M>(params, 0.0, x0, t_end, o.dt, columns, sample_times);
    }
    SensitivityResult r;
    if (!with_adaptive_method(o.method, [&](auto method) {
            using Method = decltype(method);
            auto opt = Method::template options<Eigen::VectorXd>(o);
            opt.error_components = counted;
            r = integrate_sensitivities<M, Method::template type>(params, 0.0, x0, t_end, columns, opt, events,
                                                                  sample_times);
        }))
        throw UsageError("sensitivities need dopri5, dop853, adams, radau5, rk4 or symplectic, not " + o.method);
    return r;
}

/// A run with sensitivities, as integrated: the parameters it used, its columns, and S beside the state at every
/// sample and event.
template <class M>
struct SensitivityRun {
    typename M::Params params;
    std::vector<SensitivityLabel> labels;
    SensitivityResult result;
};

/**
 * The state and S of Model M from x0 with `params` (o's settings already applied), o.sensitivities' columns
 * checked, to o.t_end or the --until event; sampled at o.samples + 1 times when `with_samples` (an ensemble's
 * member needs only the end). A constrained model's x0 is projected onto its constraints with --project-initial.
 * Throws UsageError for a bad option or column, SimulationError when the integration fails; writes nothing.
 */
/// UsageError where o's method cannot integrate Model M's sensitivities: one whose steps do not end at switching
/// surfaces (radau5, rk4, symplectic) for a model that has them; --state-error-only with a fixed step.
template <class M>
void check_sensitivity_method(const Options& o) {
    const bool fixed_steps = o.method == "rk4" || o.method == "symplectic";
    if (!is_adaptive_method(o.method) && o.method != "radau5" && !fixed_steps)
        throw UsageError("--sensitivities needs dopri5, dop853, adams, radau5, rk4 or symplectic, not " + o.method);
    if (o.state_error_only && fixed_steps)
        throw UsageError("--state-error-only: " + o.method + " takes fixed steps (--dt) and has no error control");
    if (o.method == "symplectic" && (constraint_count<M>() > 0 || M::has_generalized_forces))
        throw UsageError("--method symplectic integrates unconstrained models without forces; use dopri5, dop853 or adams");
    if constexpr (has_switching<M>::value)
        if (M::n_switches > 0 && (o.method == "radau5" || fixed_steps))
            throw UsageError("--sensitivities: " + std::string(M::name) +
                             " has switching surfaces, where the sensitivities jump: " + o.method +
                             " does not end its steps there; use dopri5, dop853 or adams");
}

template <class M>
SensitivityResult sensitivities_from(const Options& o, const typename M::Params& params, typename M::State x0,
                                     bool with_samples = true) {
    check_sensitivity_method<M>(o);
    if constexpr (is_constrained<M>::value)
        if (o.project_initial && constraint_count<M>() > 0) project_onto_constraints<M>(0.0, x0, params);
    std::vector<SensitivityColumn> columns;
    for (const auto& l : sensitivity_labels<M>(o)) columns.push_back(l.column);

    std::vector<SensitivityEvent> events;
    if (!o.until.empty()) {
        const auto [name, value] = parse_assignment(o.until, "--until");
        const int i = index_of(M::state_names, name);
        if (i < 0)
            throw UsageError("--until " + o.until + ": no state '" + name + "'" + did_you_mean(name, M::state_names) +
                             " (states: " + list(M::state_names) + ")");
        events.push_back(state_crossing(o.until, i, value));
    }
    std::vector<double> sample_times;
    for (int k = 0; with_samples && k <= o.samples; ++k) sample_times.push_back(o.t_end * double(k) / double(o.samples));
    try {
        check_sensitivity_columns<M>(0.0, x0, params, columns);
        return integrate_sensitivities_by<M>(o, params, x0, o.t_end, columns, events, sample_times);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--sensitivities: ") + e.what());
    }
}

/// The integration of run_sensitivities() without its report: o's settings applied, then sensitivities_from().
/// What `eomgen run --sensitivities` prints and the Python module's simulate(sensitivities=...) returns.
template <class M>
SensitivityRun<M> sensitivity_run(const Options& o) {
    check_options(o);
    check_method_for<M>(o);
    typename M::Params params;
    typename M::State x0 = M::default_state();
    apply_settings<M>(o, params, x0);
    SensitivityRun<M> run{params, sensitivity_labels<M>(o), {}};
    run.result = sensitivities_from<M>(o, params, x0);
    return run;
}

/// One run with sensitivities: what run() does, with S beside the state. Returns kExitOk; throws as run() does.
template <class M>
int run_sensitivities(const Options& o) {
    using State = typename M::State;
    const SensitivityRun<M> run = sensitivity_run<M>(o);
    const typename M::Params& params = run.params;
    const std::vector<SensitivityLabel>& labels = run.labels;
    const SensitivityResult& r = run.result;
    print_heading<M>(params, std::cout);

    std::cout << "method:  " << o.method << " with the sensitivities of " << labels.size() << " column"
              << (labels.size() == 1 ? "" : "s");
    if (o.method == "rk4")
        std::cout << ", fixed steps of " << o.dt << " (S is the derivative of RK4's own motion)";
    else if (o.method == "symplectic")
        std::cout << " (variational midpoint), fixed steps of " << o.dt
                  << " (S is the derivative of the integrator's own motion)";
    else
        std::cout << (o.state_error_only ? ", the state alone in the error control" : " under the same error control")
                  << ", rtol " << o.rtol << ", atol " << o.atol;
    std::cout << (constraint_count<M>() > 0 ? "; no projection onto the constraints" : "") << "\n";
    if (o.method == "symplectic")
        std::cout << "steps:   " << r.accepted_steps << ", " << r.rhs_evaluations << " Newton iterations, "
                  << r.jacobian_evaluations << " evaluations of the Lagrangian's derivatives\n";
    else
        std::cout << "steps:   " << r.accepted_steps << " accepted, " << r.rejected_steps << " rejected, "
                  << r.rhs_evaluations << " right-hand sides (each with J and Jp)\n";
    const std::string s = time_unit<M>().empty() ? "" : " s";
    std::cout << "t:       " << r.t << s << "\n";
    for (Eigen::Index i = 0; i < r.x.size(); ++i)
        std::cout << "  " << M::state_names[std::size_t(i)] << " = " << r.x(i)
                  << (state_unit<M>(std::size_t(i)).empty() ? "" : " " + state_unit<M>(std::size_t(i))) << "\n";
    if constexpr (is_constrained<M>::value) {
        if (M::n_constraints > 0) {
            const auto c = constraint_residual<M>(r.t, State(r.x), params);
            std::cout << "constraint residuals at the end: position " << c.position << ", velocity " << c.velocity
                      << "\n";
        }
    }
    std::cout << "sensitivities at t = " << r.t << s << ":\n";
    // A line per state, then per declared output (the last sample is the end: its y and Y).
    const auto row = [&](const std::string& name, const std::string& unit_of_name, const auto& values) {
        std::cout << "  ";
        for (std::size_t c = 0; c < labels.size(); ++c) {
            const std::string unit = unit_ratio(unit_of_name, labels[c].unit);
            std::cout << (c ? ", " : "") << "d" << name << "/d" << labels[c].name << " = " << values(Eigen::Index(c))
                      << (unit.empty() || unit == "1" ? "" : " " + unit);
        }
        std::cout << "\n";
    };
    for (Eigen::Index i = 0; i < r.x.size(); ++i)
        row(M::state_names[std::size_t(i)], state_unit<M>(std::size_t(i)), r.S.row(i));
    if (!r.samples.empty() && r.samples.back().t == r.t) {
        for (Eigen::Index k = 0; k < r.samples.back().Y.rows(); ++k)
            row(M::output_names[std::size_t(k)], output_unit<M>(std::size_t(k)), r.samples.back().Y.row(k));
        if constexpr (is_constrained<M>::value)
            for (Eigen::Index k = 0; k < r.samples.back().L.rows(); ++k)
                row("lambda_" + std::string(M::constraint_names[std::size_t(k)]), multiplier_unit<M>(std::size_t(k)),
                    r.samples.back().L.row(k));
    }
    for (const auto& e : r.events) {
        std::cout << "event:   " << e.name << " at t = " << e.t << s << ";";
        for (std::size_t c = 0; c < labels.size(); ++c) {
            const std::string unit = unit_ratio(time_unit<M>(), labels[c].unit);
            std::cout << (c ? "," : "") << " dt/d" << labels[c].name << " = " << e.dt(Eigen::Index(c))
                      << (unit.empty() || unit == "1" ? "" : " " + unit);
        }
        std::cout << "\n";
    }
    std::cout << "stopped: " << (r.stop_reason == StopReason::TerminalEvent ? "at event " + r.stopped_by : "at t_end")
              << "\n";
    const std::string grazes = ": grazes";
    for (const auto& [name, at] : r.switches)
        if (name.size() > grazes.size() && name.compare(name.size() - grazes.size(), grazes.size(), grazes) == 0)
            std::cerr << "warning: the motion grazes " << name.substr(0, name.size() - grazes.size()) << " = 0 at t = "
                      << at << s << " without crossing it: a motion with other values of the columns may cross it "
                      << "there, where S has no derivative, and S after it is that of motions that do not cross "
                      << "(docs/sensitivities.md, Grazing)\n";

    if (o.csv.empty()) return kExitOk;
    // S's columns (each column's states), then the outputs' (each column's outputs), then the multipliers'.
    std::vector<std::string> names;
    for (std::size_t c = 0; c < labels.size(); ++c)
        for (std::size_t i = 0; i < M::state_names.size(); ++i)
            names.push_back(with_unit("d" + std::string(M::state_names[i]) + "/d" + labels[c].name,
                                      unit_ratio(state_unit<M>(i), labels[c].unit)));
    for (std::size_t c = 0; c < labels.size(); ++c)
        for (std::size_t k = 0; k < M::output_names.size(); ++k)
            names.push_back(with_unit("d" + std::string(M::output_names[k]) + "/d" + labels[c].name,
                                      unit_ratio(output_unit<M>(k), labels[c].unit)));
    if constexpr (is_constrained<M>::value)
        for (std::size_t c = 0; c < labels.size(); ++c)
            for (std::size_t k = 0; k < M::constraint_names.size(); ++k)
                names.push_back(with_unit("dlambda_" + std::string(M::constraint_names[k]) + "/d" + labels[c].name,
                                          unit_ratio(multiplier_unit<M>(k), labels[c].unit)));
    std::vector<Sample<State>> samples;
    std::vector<std::vector<double>> rows;
    for (const auto& sample : r.samples) {
        samples.push_back({sample.t, State(sample.x)});
        rows.emplace_back(sample.S.data(), sample.S.data() + sample.S.size());  // column-major: by column, then state
        rows.back().insert(rows.back().end(), sample.Y.data(), sample.Y.data() + sample.Y.size());
        rows.back().insert(rows.back().end(), sample.L.data(), sample.L.data() + sample.L.size());
    }
    try {
        write_samples<M>(o, params, samples, {}, names, rows);
    } catch (const std::runtime_error& e) {
        throw OutputError(std::string("cannot write the CSV: ") + e.what());
    }
    return kExitOk;
}

}  // namespace eomgen::sim
