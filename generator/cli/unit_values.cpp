/** @file unit_values.cpp  NAME=VALUE [UNIT] to NAME=SI value (unit_values.hpp). */
#include "cli/unit_values.hpp"

#include "model/units.hpp"

#include <eomgen/simulation.hpp>

#include <algorithm>
#include <cctype>
#include <iostream>
#include <optional>
#include <sstream>

namespace eomgen::cli {
namespace {

/// The declared unit of a parameter (state: of a coordinate, or per second for NAME_dot).
struct Declared {
    bool known = false;             ///< the model has the name
    std::optional<Unit> unit;       ///< its declared unit, if any
};

Declared declared(const DeclaredUnits& units, const std::string& name, bool state) {
    Declared d;
    if (!state) {
        for (const DeclaredUnits::Entry& p : units.parameters)
            if (p.name == name) return {true, p.unit};
        return d;
    }
    for (const DeclaredUnits::Entry& c : units.coordinates) {
        if (c.name == name) return {true, c.unit};
        if (c.name + "_dot" == name) {
            d.known = true;
            if (c.unit) d.unit = c.unit->per_second();
            return d;
        }
    }
    return d;
}

std::string number(double x) {
    std::ostringstream os;
    os.precision(17);
    os << x;
    return os.str();
}

}  // namespace

DeclaredUnits declared_units(const std::vector<const char*>& param_names, const std::vector<const char*>& param_units,
                             const std::vector<const char*>& coordinate_names,
                             const std::vector<const char*>& coordinate_units) {
    auto entries = [](const std::vector<const char*>& names, const std::vector<const char*>& units) {
        std::vector<DeclaredUnits::Entry> out;
        for (std::size_t i = 0; i < names.size(); ++i) {
            DeclaredUnits::Entry e{names[i], std::nullopt};
            if (i < units.size() && units[i] && *units[i]) {
                try {
                    e.unit = parse_unit(units[i]);
                } catch (const UnitError&) {
                    // read when the header was generated; unreadable now only with another units database
                }
            }
            out.push_back(std::move(e));
        }
        return out;
    };
    return {entries(param_names, param_units), entries(coordinate_names, coordinate_units)};
}

std::string assignment_in_si(const DeclaredUnits& model, const std::string& text, bool state, const char* option) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0) return text;  // the runtime says "expected NAME=VALUE"
    const std::string name = text.substr(0, eq), value = text.substr(eq + 1);
    const Declared d = declared(model, name, state);
    if (!d.known) return text;
    try {
        const double bare = sim::parse_value(value);  // a number: in the declared unit
        if (!d.unit || d.unit->to_si == 1.0) return text;  // already SI: the text as the user wrote it
        return name + "=" + number(bare * d.unit->to_si);
    } catch (const sim::UsageError&) {
    }
    // "45 deg", "45deg", "20 cm": the longest number in front, a unit after it.
    for (std::size_t cut = value.size(); cut-- > 1;) {
        std::string unit_text = value.substr(cut);
        if (!std::isalpha(static_cast<unsigned char>(unit_text[0]))) continue;
        std::string left = value.substr(0, cut);
        while (!left.empty() && left.back() == ' ') left.pop_back();
        double x = 0;
        try {
            x = sim::parse_value(left);
        } catch (const sim::UsageError&) {
            continue;
        }
        Unit u;
        try {
            u = parse_unit(unit_text);
        } catch (const UnitError& e) {
            throw std::invalid_argument(std::string(option) + " " + text + ": " + e.what());
        }
        if (d.unit && u.dimension != d.unit->dimension)
            throw std::invalid_argument(std::string(option) + " " + text + ": " + u.text + " has the dimension " +
                                        u.dimension.str() + ", but " + name + " is in " + d.unit->text +
                                        ", of dimension " + d.unit->dimension.str());
        return name + "=" + number(x * u.to_si);
    }
    return text;  // not a number: the runtime says so
}

void assignments_in_si(const DeclaredUnits& model, std::vector<std::string>& assignments, bool state, const char* option) {
    for (std::string& a : assignments) a = assignment_in_si(model, a, state, option);
}

bool options_in_si(const DeclaredUnits& model, std::vector<std::string>& set, std::vector<std::string>& init,
                   const char* program) {
    try {
        assignments_in_si(model, set, false, "--set");
        assignments_in_si(model, init, true, "--init");
        return true;
    } catch (const std::invalid_argument& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return false;
    }
}

namespace {

/// One value of NAME (a parameter, else a state) in SI, through assignment_in_si; the text as given when it is no
/// number (the design reports it).
std::string value_in_si(const DeclaredUnits& model, const std::string& name, const std::string& value, const char* option) {
    const bool parameter = std::any_of(model.parameters.begin(), model.parameters.end(),
                                       [&](const DeclaredUnits::Entry& p) { return p.name == name; });
    const std::string whole = assignment_in_si(model, name + "=" + value, !parameter, option);
    return whole.substr(name.size() + 1);
}

std::vector<std::string> split_on(const std::string& s, char c) {
    std::vector<std::string> out;
    std::size_t from = 0;
    for (std::size_t k = 0; k <= s.size(); ++k)
        if (k == s.size() || s[k] == c) {
            out.push_back(s.substr(from, k - from));
            from = k + 1;
        }
    return out;
}

}  // namespace

bool ensemble_in_si(const DeclaredUnits& model, std::vector<std::string>& sweeps, std::vector<std::string>& dists,
                    const char* program) {
    try {
        for (std::string& s : sweeps) {
            const auto eq = s.find('=');
            if (eq == std::string::npos || eq == 0) continue;  // the design says what is expected
            const std::string name = s.substr(0, eq), spec = s.substr(eq + 1);
            std::string out;
            if (spec.find(':') != std::string::npos) {
                const std::vector<std::string> r = split_on(spec, ':');
                if (r.size() != 3) continue;
                const std::string start = value_in_si(model, name, r[0], "--sweep");  // in order: the first
                const std::string stop = value_in_si(model, name, r[1], "--sweep");   // bad one is reported
                out = start + ":" + stop + ":" + r[2];
            } else {
                for (const std::string& v : split_on(spec, ','))
                    out += (out.empty() ? "" : ",") + (v.empty() ? v : value_in_si(model, name, v, "--sweep"));
            }
            s = name + "=" + out;
        }
        for (std::string& d : dists) {
            const auto eq = d.find('=');
            const auto open = d.find('(');
            if (eq == std::string::npos || open == std::string::npos || d.back() != ')' || open < eq) continue;
            const std::string name = d.substr(0, eq);
            const std::vector<std::string> args = split_on(d.substr(open + 1, d.size() - open - 2), ',');
            if (args.size() != 2) continue;
            // uniform(a, b), normal(mu, sigma): the units have no offset (UDUNITS' degC is refused), so a spread
            // converts by the same factor as a value.
            const std::string a = value_in_si(model, name, args[0], "--dist");
            const std::string b = value_in_si(model, name, args[1], "--dist");
            d = d.substr(0, open + 1) + a + "," + b + ")";
        }
        return true;
    } catch (const std::invalid_argument& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return false;
    }
}

}  // namespace eomgen::cli
