/** @file units.cpp  UDUNITS-2 behind parse_unit (units.hpp). */
#include "model/units.hpp"

#include <udunits2.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <sstream>
#include <vector>

namespace eomgen {
namespace {

constexpr const char* kBase[7] = {"kg", "m", "s", "A", "K", "mol", "cd"};

struct UnitDeleter {
    void operator()(ut_unit* u) const { ut_free(u); }
};
using UnitPtr = std::unique_ptr<ut_unit, UnitDeleter>;

/// The unit system, read once from UDUNITS-2's XML database, with "deg" and "rev" added.
ut_system* units() {
    static ut_system* system = [] {
        ut_set_error_message_handler(ut_ignore);
        ut_system* s = ut_read_xml(nullptr);
        if (!s) return s;
        // Each name for both encodings: a model file is UTF-8, and UDUNITS-2 keeps a map per encoding.
        // The maps hold their own copies: the units made here are freed (LeakSanitizer would count them).
        UnitPtr degree(ut_parse(s, "arc_degree", UT_ASCII)), radian(ut_parse(s, "rad", UT_ASCII));
        UnitPtr turn(radian ? ut_scale(2 * M_PI, radian.get()) : nullptr);
        for (const ut_encoding encoding : {UT_ASCII, UT_UTF8}) {
            if (degree) ut_map_symbol_to_unit("deg", encoding, degree.get());
            if (turn) ut_map_symbol_to_unit("rev", encoding, turn.get());
        }
        return s;
    }();
    return system;
}

std::mutex& lock() {
    static std::mutex m;  // UDUNITS-2 keeps a status and a parser state per process
    return m;
}


std::string format(const std::vector<std::pair<std::string, int>>& factors) {
    std::string num, den;
    for (const auto& [name, e] : factors) {
        if (e == 0) continue;
        std::string& side = e > 0 ? num : den;
        side += (side.empty() ? "" : " ") + name + (std::abs(e) == 1 ? "" : "^" + std::to_string(std::abs(e)));
    }
    if (num.empty() && den.empty()) return "1";
    if (den.empty()) return num;
    return (num.empty() ? "1" : num) + "/" + (den.find(' ') == std::string::npos ? den : "(" + den + ")");
}

}  // namespace

std::string Dimension::str() const {
    std::vector<std::pair<std::string, int>> f;
    for (int i = 0; i < 7; ++i) f.emplace_back(kBase[i], exponent[std::size_t(i)]);
    return format(f);
}

std::string Unit::si() const {
    std::vector<std::pair<std::string, int>> f;
    for (int i = 0; i < 7; ++i) f.emplace_back(kBase[i], dimension.exponent[std::size_t(i)]);
    f.insert(f.begin(), {"rad", radians});
    return format(f);
}

Unit parse_unit(const std::string& text) {
    const std::lock_guard<std::mutex> guard(lock());
    ut_system* system = units();
    if (!system) throw UnitError("the UDUNITS-2 units database could not be read (is libudunits2 installed?)");
    std::string trimmed = text;
    trimmed.erase(0, trimmed.find_first_not_of(' '));
    trimmed.erase(trimmed.find_last_not_of(' ') + 1);
    if (trimmed.empty()) throw UnitError("an empty unit");
    // UTF-8: "N·m", "m²", "µm", "°" as well as "N m", "m^2" (ASCII is a part of it).
    UnitPtr unit(ut_parse(system, trimmed.c_str(), UT_UTF8));
    if (!unit)
        throw UnitError("'" + trimmed + "' is not a unit UDUNITS-2 knows (SI units with prefixes and their products, "
                        "quotients and powers: kg*m^2, N/m, N·m, m/s^2, deg, rpm)");
    // Its definition in base units: "0.01 m", "m2.kg.s-2", "0.104719755119660 s-1.rad", "K @ 273.15".
    char buffer[512];
    const int length = ut_format(unit.get(), buffer, sizeof buffer, UT_ASCII | UT_DEFINITION);
    if (length < 0 || length >= int(sizeof buffer)) throw UnitError("'" + trimmed + "' cannot be written in SI base units");
    const std::string definition(buffer, std::size_t(length));
    if (definition.find('@') != std::string::npos)
        throw UnitError("'" + trimmed + "' has an offset (a temperature scale): write it in K");
    Unit out;
    out.text = trimmed;
    std::istringstream words(definition);
    std::string word, factors;
    while (words >> word) {
        char* end = nullptr;
        const double scale = std::strtod(word.c_str(), &end);
        if (end && *end == '\0' && end != word.c_str()) {
            out.to_si *= scale;  // replaced by the converter's exact factor below
            continue;
        }
        factors += (factors.empty() ? "" : ".") + word;
    }
    // Each factor: a name and an optional integer exponent, joined by '.'.
    std::size_t at = 0;
    while (at < factors.size()) {
        std::size_t next = factors.find('.', at);
        if (next == std::string::npos) next = factors.size();
        const std::string f = factors.substr(at, next - at);
        at = next + 1;
        std::size_t split = f.find_first_of("-0123456789");
        const std::string name = f.substr(0, split);
        const int exponent = split == std::string::npos ? 1 : std::atoi(f.c_str() + split);
        bool known = false;
        for (int i = 0; i < 7; ++i)
            if (name == kBase[i]) {
                out.dimension.exponent[std::size_t(i)] += exponent;
                known = true;
            }
        if (name == "rad") {
            out.radians += exponent;
            known = true;
        }
        if (name == "sr") known = true;  // dimensionless
        if (!known) throw UnitError("'" + trimmed + "' is defined through '" + name + "', which is not an SI base unit");
    }
    // The exact factor to the coherent SI unit, from UDUNITS-2's converter (the definition prints 15 digits).
    const std::string si_text = factors.empty() ? "1" : factors;
    UnitPtr si(ut_parse(system, si_text.c_str(), UT_ASCII));
    if (si && ut_are_convertible(unit.get(), si.get())) {
        if (cv_converter* convert = ut_get_converter(unit.get(), si.get())) {
            out.to_si = cv_convert_double(convert, 1.0);
            cv_free(convert);
        }
    }
    if (!std::isfinite(out.to_si) || out.to_si == 0) throw UnitError("'" + trimmed + "' has no finite factor to SI");
    return out;
}

}  // namespace eomgen
