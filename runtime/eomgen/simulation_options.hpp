/**
 * @file simulation_options.hpp  What a simulation of `eomgen-sim` and `eomgen run` is asked for: the options
 * (Options), their values read from NAME=VALUE strings, checked before anything runs, and applied to a model's
 * parameters and initial state; the --until and switching events. simulation.hpp runs them, sensitivity_run.hpp
 * runs them with sensitivities.
 */
#pragma once

#include "eomgen/column_units.hpp"
#include "eomgen/dop853.hpp"
#include "eomgen/dopri5.hpp"
#include "eomgen/adams.hpp"
#include "eomgen/events.hpp"
#include "eomgen/model_traits.hpp"
#include "eomgen/progress.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>


namespace eomgen::sim {

/// What run() returns: the caller maps these to its own exit codes.
constexpr int kExitOk = 0, kExitUsage = 1, kExitSimulation = 2, kExitOutput = 3;

/// A bad option value (unknown parameter or state, unreadable number, method without --dt, ...).
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The CSV cannot be written (its directory does not exist, no permission, a full disk).
struct OutputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// "; did you mean 'x'?" for the candidate closest to `name` in edit distance (at most a third of its
/// length, at least 1), or "" when none is that close.
template <class Names>
std::string did_you_mean(const std::string& name, const Names& candidates) {
    std::string best;
    std::size_t best_distance = std::max<std::size_t>(1, name.size() / 3) + 1;
    for (const auto& c : candidates) {
        const std::string cand(c);
        std::vector<std::size_t> row(cand.size() + 1);
        for (std::size_t j = 0; j <= cand.size(); ++j) row[j] = j;
        for (std::size_t i = 1; i <= name.size(); ++i) {
            std::size_t diagonal = row[0];
            row[0] = i;
            for (std::size_t j = 1; j <= cand.size(); ++j) {
                const std::size_t up = row[j];
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (name[i - 1] == cand[j - 1] ? 0 : 1)});
                diagonal = up;
            }
        }
        if (row[cand.size()] < best_distance) {
            best_distance = row[cand.size()];
            best = cand;
        }
    }
    return best.empty() ? "" : "; did you mean '" + best + "'?";
}

/// Models with constraints have n_constraints, multipliers() and constraint_residuals() (model_traits.hpp).
using eomgen::is_constrained;
using eomgen::declares_power;
using eomgen::power_available;

/// The simulation options of `eomgen-sim` and `eomgen run` (the same meaning in both).
struct Options {
    std::string model;
    double t_end = 10;
    std::string method = "dopri5";
    double rtol = 1e-10, atol = 1e-12, dt = 0;
    std::vector<std::string> set, init;
    std::string csv, until;
    /// --sensitivities: the columns of S = dx/d(...), a parameter NAME or an initial value x0:STATE
    /// (sensitivity_run.hpp); empty: none.
    std::vector<std::string> sensitivities;
    /// --state-error-only: with sensitivities, the state alone in the error norm (S left out of the step-size control).
    bool state_error_only = false;
    int samples = 200;
    std::size_t max_steps = 10000000;
    bool project_initial = false;
    /// Stop the adaptive methods' steps at the model's switching surfaces (kinks and jumps of rhs()).
    bool switch_events = true;
    /// How far a long integration has come, on stderr (progress.hpp): set by `eomgen run`, not an option here.
    eomgen::ProgressStyle progress = eomgen::ProgressStyle::None;
    /// Say where the CSV went ("csv: path (N rows)"); off for `eomgen run`'s private one, made for its plot.
    bool report_csv = true;
};

/// An adaptive method of --method: the stepper template (integrate_with, integrate_constrained) and its
/// options from --rtol, --atol and --max-steps (the method's own defaults for the rest).
template <template <class> class Stepper>
struct AdaptiveMethod {
    template <class State>
    using type = Stepper<State>;

    template <class State>
    static typename Stepper<State>::Options options(const Options& o) {
        typename Stepper<State>::Options opt;
        opt.rtol = o.rtol;
        opt.atol = o.atol;
        opt.max_steps = o.max_steps;
        return opt;
    }
};

/// Calls use(AdaptiveMethod<...>{}) for the adaptive method `name` and returns true, or returns false when
/// `name` is none of them. A new adaptive method joins with one line here.
template <class Use>
bool with_adaptive_method(const std::string& name, Use&& use) {
    if (name == "dopri5") return use(AdaptiveMethod<eomgen::Dopri5>{}), true;
    if (name == "dop853") return use(AdaptiveMethod<eomgen::Dop853>{}), true;
    if (name == "adams") return use(AdaptiveMethod<eomgen::Adams>{}), true;
    return false;
}

/// Whether --method `name` is an explicit adaptive method (with_adaptive_method: constrained models too).
inline bool is_adaptive_method(const std::string& name) {
    return with_adaptive_method(name, [](auto) {});
}

/// Whether --method `name` chooses its own steps by --rtol and --atol (no --dt): the explicit adaptive
/// methods and radau5 (implicit, unconstrained models only).
inline bool takes_tolerances(const std::string& name) {
    return is_adaptive_method(name) || name == "radau5";
}

/// A number as written on the command line: "0.5", "-pi/2", "2*pi", "pi/4", "1e-3".
inline double parse_value(const std::string& text) {
    std::string s = text;
    double sign = 1;
    if (!s.empty() && (s[0] == '-' || s[0] == '+')) {
        sign = s[0] == '-' ? -1 : 1;
        s = s.substr(1);
    }
    double value = 1, divisor = 1;
    const auto slash = s.find('/');
    if (slash != std::string::npos) {
        try {
            std::size_t used = 0;
            divisor = std::stod(s.substr(slash + 1), &used);
            if (used != s.size() - slash - 1) throw std::invalid_argument("");
        } catch (const std::exception&) {
            throw UsageError("cannot read the number '" + text + "'");
        }
        s = s.substr(0, slash);
    }
    const auto pi = s.find("pi");
    if (pi != std::string::npos) {
        if (pi + 2 != s.size()) throw UsageError("cannot read the number '" + text + "'");
        value = 3.141592653589793238462643383279502884;
        s = s.substr(0, pi);
        if (!s.empty() && s.back() == '*') s.pop_back();
        if (s.empty()) s = "1";
    }
    double result = 0;
    try {
        std::size_t used = 0;
        const double k = std::stod(s, &used);
        if (used != s.size()) throw std::invalid_argument("");
        result = sign * k * value / divisor;
    } catch (const std::exception&) {
        throw UsageError("cannot read the number '" + text + "'");
    }
    if (!std::isfinite(result)) throw UsageError("'" + text + "' is not a finite number");
    return result;
}

inline std::pair<std::string, double> parse_assignment(const std::string& text, const char* option) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw UsageError(std::string(option) + " " + text + ": expected NAME=VALUE");
    try {
        return {text.substr(0, eq), parse_value(text.substr(eq + 1))};
    } catch (const UsageError& e) {
        throw UsageError(std::string(option) + " " + text + ": " + e.what());
    }
}

template <class Array>
int index_of(const Array& names, const std::string& name) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (name == names[i]) return int(i);
    return -1;
}

template <class Array>
std::string list(const Array& names) {
    std::string s;
    for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + std::string(names[i]);
    return s;
}

/// Why the file `path` that `option` names cannot be written (its directory is missing, it is a directory),
/// or "" when nothing says it cannot.
inline std::string output_path_problem(const std::string& option, const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(path).parent_path();
    std::error_code ec;
    if (!dir.empty() && !fs::is_directory(dir, ec))
        return option + " " + path + ": the directory '" + dir.string() + "' does not exist";
    if (fs::is_directory(path, ec)) return option + " " + path + ": is a directory";
    return "";
}

/// The options' values that no model accepts, refused before anything runs (UsageError, OutputError).
inline void check_options(const Options& o) {
    auto finite = [](double v) { return std::isfinite(v); };
    if (!finite(o.t_end) || !(o.t_end > 0)) throw UsageError("--t-end must be a positive number");
    if (!finite(o.rtol) || !finite(o.atol) || o.rtol < 0 || o.atol < 0 || (o.rtol == 0 && o.atol == 0))
        throw UsageError("--rtol and --atol must be at least 0 and not both 0");
    if (o.samples < 1) throw UsageError("--samples must be at least 1 (sample intervals on [0, t_end])");
    if (o.max_steps < 1) throw UsageError("--max-steps must be at least 1");
    if (o.method == "rk4" || o.method == "symplectic") {
        if (!finite(o.dt) || !(o.dt > 0)) throw UsageError("--method " + o.method + " needs --dt, a positive step");
        const double steps = std::ceil(o.t_end / o.dt);
        if (steps > double(o.max_steps)) {
            std::ostringstream os;
            os << "--dt " << o.dt << " would take " << steps << " steps to reach --t-end " << o.t_end
               << ", more than --max-steps " << o.max_steps;
            throw UsageError(os.str());
        }
    }
    if (!o.csv.empty())
        if (const std::string problem = output_path_problem("--csv", o.csv); !problem.empty()) throw OutputError(problem);
}

/// UsageError when model M cannot take --method (radau5 and constraints), before anything is printed.
template <class M>
void check_method_for(const Options& o) {
    if (o.method == "radau5" && constraint_count<M>() > 0)
        throw UsageError("--method radau5 integrates unconstrained models; use dopri5, dop853 or adams for " +
                         std::string(M::name) + "'s constraints");
}

/// The parameters after `--set` and the initial state after `--init` (UsageError for an unknown name or value).
template <class M>
void apply_settings(const Options& o, typename M::Params& params, typename M::State& x0) {
    for (const std::string& s : o.set) {
        const auto [name, v] = parse_assignment(s, "--set");
        if (!M::set_param(params, name, v))
            throw UsageError("--set " + s + ": " + M::name + " has no parameter '" + name + "'" +
                             did_you_mean(name, M::param_names) + " (it has " + list(M::param_names) + ")");
    }
    for (const std::string& s : o.init) {
        const auto [name, v] = parse_assignment(s, "--init");
        const int i = index_of(M::state_names, name);
        if (i < 0)
            throw UsageError("--init " + s + ": no state '" + name + "'" + did_you_mean(name, M::state_names) +
                             " (states: " + list(M::state_names) + ")");
        x0(i) = v;
    }
}

/// `--until NAME=VALUE` as a terminal event where state NAME crosses VALUE (none when o.until is empty).
template <class M>
std::vector<eomgen::Event<typename M::State>> until_events(const Options& o) {
    using State = typename M::State;
    std::vector<eomgen::Event<State>> events;
    if (o.until.empty()) return events;
    if (o.method == "symplectic")
        throw UsageError("--until needs --method dopri5, dop853, adams, radau5 or rk4 (events use dense output)");
    const auto [name, value] = parse_assignment(o.until, "--until");
    const int i = index_of(M::state_names, name);
    if (i < 0)
        throw UsageError("--until " + o.until + ": no state '" + name + "'" + did_you_mean(name, M::state_names) +
                         " (states: " + list(M::state_names) + ")");
    const double target = value;
    events.push_back({o.until, [i, target](const double&, const State& x) { return x(i) - target; },
                      eomgen::EventDirection::Both, eomgen::EventAction::Stop});
    return events;
}

/// The model's switching surfaces (abs, sign, … in its file) as EventAction::Switch events of the adaptive
/// methods, unless o.switch_events is off (--no-switch-events). `params` must outlive the events.
template <class M>
std::vector<eomgen::Event<typename M::State>> switch_events(const Options& o, const typename M::Params& params) {
    using State = typename M::State;
    std::vector<eomgen::Event<State>> events;
    if constexpr (eomgen::has_switching<M>::value) {
        if (!o.switch_events) return events;
        for (int k = 0; k < M::n_switches; ++k)
            events.push_back({M::switch_names[std::size_t(k)],
                              [k, &params](const double& t, const State& x) {
                                  typename M::Switches s;
                                  M::switching(t, positions<M::nq>(x), velocities<M::nq>(x), params, s);
                                  return s(k);
                              },
                              eomgen::EventDirection::Both, eomgen::EventAction::Switch});
    }
    return events;
}

/// The first lines of a run's report: "model:   door (Closing tilted door; Goldstein ch. 5, Ex. 30)" and the
/// parameters, "params:  m = 30 kg, w = 0.9 m" (or "params:  m=30 w=0.9" for a model without units).
template <class M>
void print_heading(const typename M::Params& params, std::ostream& os) {
    os.precision(15);
    // "model:   door (Closing tilted door; Goldstein ch. 5, Ex. 30)", with no empty parentheses when untitled.
    const std::string title = M::title, source = M::source;
    const std::string about = title + (!title.empty() && !source.empty() ? "; " : "") + source;
    os << "model:   " << M::name << (about.empty() ? "" : " (" + about + ")") << "\n";
    // "params:  m=30 w=0.9", with units "params:  m = 30 kg, w = 0.9 m".
    os << "params: ";
    const auto values = M::param_values(params);
    bool units = false;
    for (std::size_t i = 0; i < values.size(); ++i) units = units || !param_unit<M>(i).empty();
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (units)
            os << (i ? ", " : " ") << M::param_names[i] << " = " << values[i]
            << (param_unit<M>(i).empty() ? "" : " " + param_unit<M>(i));
        else
            os << " " << M::param_names[i] << "=" << values[i];
    }
    os << "\n";
}

}  // namespace eomgen::sim
