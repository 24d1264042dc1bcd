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

/// integrate_sensitivities (or its radau5 form) by o's method, tolerances and steps; the method must be one with
/// error control (dopri5, dop853, adams, radau5: UsageError otherwise).
template <class M>
SensitivityResult integrate_sensitivities_by(const Options& o, const typename M::Params& params,
                                             const typename M::State& x0, double t_end,
                                             const std::vector<SensitivityColumn>& columns,
                                             const std::vector<SensitivityEvent>& events,
                                             const std::vector<double>& sample_times) {
    if (o.method == "radau5") {
        Radau5Options<double> opt;
        opt.rtol = o.rtol;
        opt.atol = o.atol;
        opt.max_steps = o.max_steps;
        return integrate_sensitivities_radau5<M>(params, 0.0, x0, t_end, columns, opt, events, sample_times);
    }
    SensitivityResult r;
    if (!with_adaptive_method(o.method, [&](auto method) {
            using Method = decltype(method);
            r = integrate_sensitivities<M, Method::template type>(params, 0.0, x0, t_end, columns,
                                                                  Method::template options<Eigen::VectorXd>(o), events,
                                                                  sample_times);
        }))
        throw UsageError("sensitivities need a method with error control (dopri5, dop853, adams or radau5), not " +
                         o.method);
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

/// The integration of run_sensitivities() without its report: o's settings applied, o.sensitivities' columns
/// checked, the state and S integrated to o.t_end (or the --until event), sampled at o.samples + 1 times. Throws
/// UsageError for a bad option or column, SimulationError when the integration fails; writes nothing. What
/// `eomgen run --sensitivities` prints and the Python module's simulate(sensitivities=...) returns.
template <class M>
SensitivityRun<M> sensitivity_run(const Options& o) {
    using State = typename M::State;
    check_options(o);
    if (!is_adaptive_method(o.method) && o.method != "radau5")
        throw UsageError("--sensitivities needs a method with error control (dopri5, dop853, adams or radau5), not " +
                         o.method);
    check_method_for<M>(o);
    typename M::Params params;
    State x0 = M::default_state();
    apply_settings<M>(o, params, x0);
    const std::vector<SensitivityLabel> labels = sensitivity_labels<M>(o);
    std::vector<SensitivityColumn> columns;
    for (const auto& l : labels) columns.push_back(l.column);

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
    for (int k = 0; k <= o.samples; ++k) sample_times.push_back(o.t_end * double(k) / double(o.samples));

    try {
        check_sensitivity_columns<M>(0.0, x0, params, columns);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--sensitivities: ") + e.what());
    }
    SensitivityRun<M> run{params, labels, {}};
    try {
        run.result = integrate_sensitivities_by<M>(o, params, x0, o.t_end, columns, events, sample_times);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--sensitivities: ") + e.what());
    }
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
              << (labels.size() == 1 ? "" : "s") << " under the same error control, rtol " << o.rtol << ", atol "
              << o.atol << (constraint_count<M>() > 0 ? "; no projection onto the constraints" : "") << "\n";
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
