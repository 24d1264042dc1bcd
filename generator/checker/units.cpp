/** @file units.cpp  Units of measure and their factors to SI. */
#include "checker/units.hpp"

#include <cctype>
#include <cmath>
#include <map>
#include <string>

namespace eomgen::checker {

namespace {

/// The single units (no powers): length, time, mass, angle, and the derived SI units texts print.
std::optional<double> single_unit(const std::string& u) {
    static const std::map<std::string, double> factors = {
        {"m", 1.0},     {"cm", 1e-2},   {"mm", 1e-3}, {"km", 1e3}, {"s", 1.0},  {"sec", 1.0},   {"ms", 1e-3},
        {"min", 60.0},  {"hr", 3600.0}, {"kg", 1.0},  {"g", 1e-3}, {"N", 1.0},  {"mN", 1e-3},   {"J", 1.0},
        {"W", 1.0},     {"Hz", 1.0},    {"K", 1.0},   {"Pa", 1.0}, {"rad", 1.0}, {"deg", M_PI / 180.0},
        {"second", 1.0}, {"seconds", 1.0}, {"degree", M_PI / 180.0}, {"degrees", M_PI / 180.0}};
    const auto it = factors.find(u);
    if (it == factors.end()) return std::nullopt;
    return it->second;
}

}  // namespace

std::optional<double> unit_factor(std::string_view unit) {
    std::string u;
    for (char c : unit)
        if (c != '{' && c != '}') u += c == '~' ? ' ' : c;  // `\mathrm{~N~m}` is N·m
    // Trim, and read "a b/c^2" as factors separated by spaces, '.', '*' and '/'.
    double factor = 1.0;
    bool any = false, divide = false;
    std::size_t i = 0;
    while (i < u.size()) {
        const char c = u[i];
        if (std::isspace(static_cast<unsigned char>(c)) || c == '*' || c == '.') {
            ++i;
            continue;
        }
        if (c == '/') {
            if (divide || !any) return std::nullopt;  // "m//s", "/s"
            divide = true;
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < u.size() && std::isalpha(static_cast<unsigned char>(u[j]))) ++j;
        if (j == i) return std::nullopt;
        const std::optional<double> f = single_unit(u.substr(i, j - i));
        if (!f) return std::nullopt;
        int power = 1;
        if (j < u.size() && u[j] == '^') {
            std::size_t k = j + 1;
            const bool negative = k < u.size() && u[k] == '-';
            if (negative) ++k;
            if (k >= u.size() || !std::isdigit(static_cast<unsigned char>(u[k]))) return std::nullopt;
            power = u[k] - '0';
            if (negative) power = -power;
            j = k + 1;
        }
        factor *= std::pow(*f, divide ? -power : power);
        divide = false;
        any = true;
        i = j;
    }
    if (!any || divide) return std::nullopt;
    return factor;
}

bool is_unit(std::string_view unit) {
    return unit_factor(unit).has_value();
}

bool is_unit_command(std::string_view command, std::string_view argument) {
    if (!is_unit(argument)) return false;
    if (command == "\\mathrm") return true;
    if (command != "\\text" && command != "\\textrm" && command != "\\mbox") return false;
    const std::size_t first = argument.find_first_not_of(" ~");
    const std::size_t last = argument.find_last_not_of(" ~");
    bool word = true;  // one plain word: `\text{s}` may be a subscript, `\text{ s}` is a unit
    for (std::size_t k = first; k <= last; ++k) word = word && std::isalpha(static_cast<unsigned char>(argument[k]));
    return !word || first > 0;
}

}  // namespace eomgen::checker
