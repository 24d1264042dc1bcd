/** @file steady_sweep.cpp  A steady motion's linear equations against a parameter (steady_sweep.hpp). */
#include "mechanics/steady_sweep.hpp"

#include "mechanics/small_oscillations.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace eomgen {

namespace {
std::string num(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}
}  // namespace

/// C = v C1 and K = g K0 + v² K2, from the linearizations at v, 0 and 2v (and 0 with 2g), each checked.
std::optional<SpeedSplit> split_by_speed(const Model& model, SteadyMotionSolver& solver, const SteadyMotionOptions& options,
                                    const SteadyMotion& base, const std::string& speed) {
    if (speed.empty() || !base.decoupled) return std::nullopt;
    SpeedSplit out;
    out.speed = speed;
    std::size_t index = 0;
    while (index < model.parameters.size() && model.parameters[index].name != speed) ++index;
    if (index == model.parameters.size()) throw ModesError("--speed " + speed + ": no parameter of that name");
    out.v = base.parameters[index];
    if (out.v == 0) {
        out.notes.push_back("no split by " + speed + ": it is 0 here");
        return out;
    }
    auto at = [&](double v, std::optional<double> g) {
        SteadyMotionOptions o = options;
        o.set[speed] = v;
        if (g) o.set["g"] = *g;
        const SteadyMotion s = solver.solve(o, &base);
        if (s.second_order != base.second_order || !s.decoupled)
            throw ModesError("the steady motion at " + speed + " = " + num(v) + " has another structure");
        return s;
    };
    const SteadyMotion rest = at(0, std::nullopt), twice = at(2 * out.v, std::nullopt);
    const double scale = 1 + base.C.norm() + base.K.norm();
    out.C1 = base.C / out.v;
    out.K2 = (base.K - rest.K) / (out.v * out.v);
    out.K_rest = rest.K;
    const bool linear_C = rest.C.norm() <= 1e-9 * scale && (twice.C - 2 * base.C).norm() <= 1e-9 * scale;
    const bool quadratic_K = (twice.K - rest.K - 4 * (base.K - rest.K)).norm() <= 1e-9 * scale;
    if (!linear_C) out.notes.push_back("C is not proportional to " + speed + ": C1 = C/" + speed + " holds at this speed only");
    if (!quadratic_K) out.notes.push_back("K is not K(0) + " + speed + "^2 K2: K2 holds at this speed only");
    for (std::size_t i = 0; i < model.parameters.size(); ++i)
        if (model.parameters[i].name == "g" && base.parameters[i] != 0) {
            out.gravity = "g";
            out.g = base.parameters[i];
            const SteadyMotion heavy = at(0, 2 * out.g);
            if ((heavy.K - 2 * rest.K).norm() <= 1e-9 * scale) out.K0 = rest.K / out.g;
            else out.notes.push_back("K at " + speed + " = 0 is not proportional to g");
        }
    return out;
}

SteadySweep sweep_steady_motion(const Model& model, SteadyMotionSolver& solver, const SteadyMotionOptions& options,
                                const SteadyMotion& base, const std::string& name, double a, double b, long count) {
    SteadySweep out;
    out.name = name;
    if (std::none_of(model.parameters.begin(), model.parameters.end(), [&](const Parameter& p) { return p.name == name; }))
        throw ModesError("--sweep: no parameter '" + name + "'");
    if (count < 2 || count > 100000) throw ModesError("--sweep: COUNT is between 2 and 100000");
    SteadyMotion previous = base;
    std::vector<double> growth;
    auto solve_at = [&](double v, const SteadyMotion& from) {
        SteadyMotionOptions o = options;
        o.set[out.name] = v;
        return solver.solve(o, &from);
    };
    for (long k = 0; k < count; ++k) {
        const double v = a + (b - a) * double(k) / double(count - 1);
        previous = solve_at(v, previous);
        out.values.push_back(v);
        out.eigenvalues.push_back(previous.eigenvalues);
        out.stability.push_back(previous.stability);
        growth.push_back(previous.growth_rate);
    }
    // Where the stability changes. Between stable and unstable the largest real part changes sign: the Illinois
    // variant of regula falsi on it (bracketing, superlinear). Where one side is marginally stable (purely
    // imaginary eigenvalues: the largest real part is 0 up to round-off there), bisection on the verdict.
    for (std::size_t k = 0; k + 1 < growth.size(); ++k) {
        if (out.stability[k] == out.stability[k + 1]) continue;
        double lo = out.values[k], hi = out.values[k + 1], flo = growth[k], fhi = growth[k + 1];
        const bool sign_change = (flo < 0) != (fhi < 0) && out.stability[k] != "marginally stable" &&
                                 out.stability[k + 1] != "marginally stable";
        SteadyMotion near = base;
        int side = 0;
        for (int i = 0; i < 200; ++i) {
            if (std::abs(hi - lo) <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(lo), std::abs(hi))) break;
            double mid = sign_change ? (lo * fhi - hi * flo) / (fhi - flo) : 0.5 * (lo + hi);
            if (!(mid > std::min(lo, hi) && mid < std::max(lo, hi))) mid = 0.5 * (lo + hi);
            near = solve_at(mid, near);
            const double f = near.growth_rate;
            const bool low_side = sign_change ? (f < 0) == (flo < 0) : near.stability == out.stability[k];
            if (sign_change && f == 0) {
                lo = hi = mid;
                break;
            }
            if (low_side) {
                lo = mid, flo = f;
                if (side == -1) fhi /= 2;
                side = -1;
            } else {
                hi = mid, fhi = f;
                if (side == 1) flo /= 2;
                side = 1;
            }
        }
        const double at = sign_change ? (std::abs(flo) < std::abs(fhi) ? lo : hi) : 0.5 * (lo + hi);
        out.changes.push_back({at, out.stability[k], out.stability[k + 1]});
    }
    return out;
}


}  // namespace eomgen
