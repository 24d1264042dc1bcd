/** @file unit_values.cpp  NAME=VALUE [UNIT] to NAME=SI value (unit_values.hpp). */
#include "cli/unit_values.hpp"

#include "model/units.hpp"

#include <eomgen/simulation.hpp>

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

Declared declared(const Model& model, const std::string& name, bool state) {
    Declared d;
    if (!state) {
        for (const Parameter& p : model.parameters)
            if (p.name == name) return {true, p.declared_unit};
        return d;
    }
    for (const Coordinate& c : model.coordinates) {
        if (c.name == name) return {true, c.declared_unit};
        if (c.name + "_dot" == name) {
            d.known = true;
            if (c.declared_unit) d.unit = c.declared_unit->per_second();
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

std::string assignment_in_si(const Model& model, const std::string& text, bool state, const char* option) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0) return text;  // the runtime says "expected NAME=VALUE"
    const std::string name = text.substr(0, eq), value = text.substr(eq + 1);
    const Declared d = declared(model, name, state);
    if (!d.known) return text;
    try {
        const double bare = sim::parse_value(value);  // a number: in the declared unit
        return name + "=" + number(bare * (d.unit ? d.unit->to_si : 1.0));
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

void assignments_in_si(const Model& model, std::vector<std::string>& assignments, bool state, const char* option) {
    for (std::string& a : assignments) a = assignment_in_si(model, a, state, option);
}

bool options_in_si(const Model& model, std::vector<std::string>& set, std::vector<std::string>& init,
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

}  // namespace eomgen::cli
