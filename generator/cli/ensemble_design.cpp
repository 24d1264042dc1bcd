/** @file ensemble_design.cpp  --sweep grids and seeded --sample draws: member index → values. */
#include "cli/ensemble_design.hpp"

#include "eomgen/simulation.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace eomgen::cli {

using eomgen::sim::UsageError;

namespace {

constexpr double kPi = 3.141592653589793238462643383279502884;
/// More members than this is surely a mistake (and would overflow a grid's product first).
constexpr std::size_t kMaxMembers = std::size_t(1) << 40;

/// "NAME" and "rest" of "NAME=rest", or a UsageError naming the option.
std::pair<std::string, std::string> split_assignment(const std::string& text, const std::string& option,
                                                     const std::string& expected) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw UsageError(option + " " + text + ": expected " + expected);
    return {text.substr(0, eq), text.substr(eq + 1)};
}

double number(const std::string& text, const std::string& option, const std::string& whole) {
    try {
        return eomgen::sim::parse_value(text);
    } catch (const UsageError& e) {
        throw UsageError(option + " " + whole + ": " + e.what());
    }
}

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream in(text);
    while (std::getline(in, part, separator)) parts.push_back(part);
    if (!text.empty() && text.back() == separator) parts.push_back("");
    return parts;
}

EnsembleVariable resolve(const std::string& name, const EnsembleNames& names, const std::string& option,
                         const std::string& whole) {
    for (std::size_t i = 0; i < names.params.size(); ++i)
        if (names.params[i] == name) return {name, false, int(i)};
    for (std::size_t i = 0; i < names.states.size(); ++i)
        if (names.states[i] == name) return {name, true, int(i)};
    std::vector<std::string> all = names.params;
    all.insert(all.end(), names.states.begin(), names.states.end());
    throw UsageError(option + " " + whole + ": no parameter or state '" + name + "'" +
                     eomgen::sim::did_you_mean(name, all) + " (parameters: " + eomgen::sim::list(names.params) +
                     "; states: " + eomgen::sim::list(names.states) + ")");
}

/// START:STOP:COUNT or v1,v2,...
std::vector<double> sweep_values(const std::string& spec, const std::string& whole) {
    const std::string option = "--sweep";
    const std::vector<std::string> range = split(spec, ':');
    std::vector<double> values;
    if (range.size() > 1) {
        if (range.size() != 3)
            throw UsageError(option + " " + whole + ": expected START:STOP:COUNT (e.g. theta=0.1:1.5:15)");
        const double start = number(range[0], option, whole), stop = number(range[1], option, whole);
        long long count = 0;
        std::size_t used = 0;
        try {
            count = std::stoll(range[2], &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != range[2].size())
            throw UsageError(option + " " + whole + ": COUNT '" + range[2] + "' is not a whole number");
        if (count < 1) throw UsageError(option + " " + whole + ": COUNT must be at least 1");
        if (std::size_t(count) > kMaxMembers) throw UsageError(option + " " + whole + ": COUNT is too large");
        if (count == 1 && start != stop)
            throw UsageError(option + " " + whole + ": COUNT 1 takes START alone; make STOP equal to START");
        for (long long k = 0; k < count; ++k)
            // start + k·step, and STOP itself at the end (no drift of accumulated steps).
            values.push_back(k + 1 == count ? stop : start + (stop - start) * double(k) / double(count - 1));
        return values;
    }
    for (const std::string& v : split(spec, ',')) {
        if (v.empty()) throw UsageError(option + " " + whole + ": an empty value in the list");
        values.push_back(number(v, option, whole));
    }
    return values;
}

}  // namespace

std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

EnsembleDesign::EnsembleDesign(const Request& r, const EnsembleNames& names) {
    auto add = [&](const EnsembleVariable& v, const std::string& option, const std::string& whole) {
        for (const EnsembleVariable& known : variables_)
            if (known.name == v.name) throw UsageError(option + " " + whole + ": " + v.name + " is varied twice");
        variables_.push_back(v);
    };
    if (!r.sweeps.empty() && (r.sample != -1 || !r.dists.empty()))
        throw UsageError("--sweep and --sample make different ensembles: give one of them");
    if (r.sample == -1 && !r.dists.empty()) throw UsageError("--dist needs --sample N (the number of members)");
    if (r.sample == -1 && r.seed_given) throw UsageError("--seed needs --sample N");
    if (!r.sweeps.empty()) {
        size_ = 1;
        for (const std::string& s : r.sweeps) {
            const auto [name, spec] =
                split_assignment(s, "--sweep", "NAME=START:STOP:COUNT or NAME=v1,v2,... (e.g. theta=0.1:1.5:15)");
            add(resolve(name, names, "--sweep", s), "--sweep", s);
            grid_.push_back(sweep_values(spec, s));
            if (size_ > kMaxMembers / grid_.back().size())
                throw UsageError("--sweep " + s + ": the grid has more than 2^40 members");
            size_ *= grid_.back().size();
        }
        return;
    }
    if (r.sample < 1 || std::size_t(r.sample) > kMaxMembers)
        throw UsageError("--sample " + std::to_string(r.sample) + ": the number of members must be 1 to 2^40");
    if (r.dists.empty()) throw UsageError("--sample needs at least one --dist NAME=uniform(a,b) or NAME=normal(mu,sigma)");
    size_ = std::size_t(r.sample);
    seed_ = r.seed;
    for (const std::string& d : r.dists) {
        const std::string expected = "NAME=uniform(a,b) or NAME=normal(mu,sigma)";
        const auto [name, spec] = split_assignment(d, "--dist", expected);
        const auto open = spec.find('(');
        if (open == std::string::npos || spec.back() != ')') throw UsageError("--dist " + d + ": expected " + expected);
        const std::string kind = spec.substr(0, open);
        const std::vector<std::string> args = split(spec.substr(open + 1, spec.size() - open - 2), ',');
        if ((kind != "uniform" && kind != "normal") || args.size() != 2)
            throw UsageError("--dist " + d + ": expected " + expected);
        Distribution dist{kind == "normal", number(args[0], "--dist", d), number(args[1], "--dist", d)};
        if (!dist.normal && !(dist.a < dist.b)) throw UsageError("--dist " + d + ": uniform(a,b) needs a < b");
        if (dist.normal && !(dist.b > 0)) throw UsageError("--dist " + d + ": normal(mu,sigma) needs sigma > 0");
        add(resolve(name, names, "--dist", d), "--dist", d);
        dists_.push_back(dist);
    }
}

std::vector<double> EnsembleDesign::values(std::size_t member) const {
    std::vector<double> v(variables_.size());
    if (!grid_.empty()) {
        // The last --sweep varies fastest, as in nested loops written in the order given.
        std::size_t rest = member;
        for (std::size_t k = grid_.size(); k-- > 0;) {
            v[k] = grid_[k][rest % grid_[k].size()];
            rest /= grid_[k].size();
        }
        return v;
    }
    for (std::size_t k = 0; k < dists_.size(); ++k) {
        // A stream per (seed, member, variable): adding a --dist leaves the others' draws as they were.
        std::uint64_t state = splitmix64(splitmix64(splitmix64(seed_) ^ std::uint64_t(member)) ^ std::uint64_t(k));
        auto next = [&state] {
            state += 0x9e3779b97f4a7c15ULL;
            return splitmix64(state);
        };
        const Distribution& d = dists_[k];
        if (!d.normal) {
            const double u = double(next() >> 11) * 0x1.0p-53;  // [0, 1)
            v[k] = d.a + (d.b - d.a) * u;
        } else {
            const double u1 = double((next() >> 11) + 1) * 0x1.0p-53;  // (0, 1]: log(u1) is finite
            const double u2 = double(next() >> 11) * 0x1.0p-53;
            v[k] = d.a + d.b * std::sqrt(-2 * std::log(u1)) * std::cos(2 * kPi * u2);
        }
    }
    return v;
}

std::string EnsembleDesign::describe() const {
    std::string names;
    for (const EnsembleVariable& v : variables_) names += (names.empty() ? "" : ", ") + v.name;
    if (!grid_.empty()) {
        std::string shape;
        for (const auto& g : grid_) shape += (shape.empty() ? "" : " x ") + std::to_string(g.size());
        return "grid " + shape + " over " + names;
    }
    return std::to_string(size_) + " samples of " + names + " (seed " + std::to_string(seed_) + ")";
}

}  // namespace eomgen::cli
