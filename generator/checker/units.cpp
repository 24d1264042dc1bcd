/** @file units.cpp  Units of measure and their factors to SI. */
#include "checker/units.hpp"

#include <cctype>
#include <cmath>
#include <map>
#include <mutex>
#include <string>

namespace eomgen::checker {

namespace {

/// The names a derivation prints as units (with their spellings): each read by UDUNITS-2.
bool printed_unit_name(const std::string& u) {
    static const char* const names[] = {"m",   "cm",     "mm",      "km",     "s",       "sec", "ms", "min", "hr",
                                        "kg",  "g",      "N",       "mN",     "J",       "W",   "Hz", "K",   "Pa",
                                        "rad", "deg",    "rev",     "rpm",    "ft",      "second", "seconds",
                                        "degree", "degrees"};
    for (const char* n : names)
        if (u == n) return true;
    return false;
}

}  // namespace

namespace {

std::optional<TextUnit> read_text_unit(std::string_view unit) {
    std::string u;
    for (char c : unit)
        if (c != '{' && c != '}') u += c == '~' ? ' ' : c;  // `\mathrm{~N~m}` is N·m
    // Read "a b/c^2" as factors separated by spaces, '.', '*' and '/', each a name of the list; UDUNITS-2 then
    // reads the whole, rewritten with its own operators.
    std::string udunits;
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
        const std::string name = u.substr(i, j - i);
        if (!printed_unit_name(name)) return std::nullopt;
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
        if (divide) power = -power;
        udunits += (udunits.empty() ? "" : ".") + std::string("(") + name + ")" + (power == 1 ? "" : std::to_string(power));
        divide = false;
        any = true;
        i = j;
    }
    if (!any || divide) return std::nullopt;
    try {
        const Unit parsed = parse_unit(udunits);
        return TextUnit{parsed.to_si, parsed.dimension};
    } catch (const UnitError&) {
        return std::nullopt;
    }
}

}  // namespace

std::optional<TextUnit> text_unit(std::string_view unit) {
    // The parser asks of every \mathrm and \text it meets: each text is read by UDUNITS-2 once.
    static std::mutex lock;
    static std::map<std::string, std::optional<TextUnit>, std::less<>> read;
    const std::lock_guard<std::mutex> guard(lock);
    if (const auto it = read.find(unit); it != read.end()) return it->second;
    return read.emplace(std::string(unit), read_text_unit(unit)).first->second;
}

std::optional<double> unit_factor(std::string_view unit) {
    const std::optional<TextUnit> u = text_unit(unit);
    if (!u) return std::nullopt;
    return u->factor;
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
