/** @file printed_numbers.cpp  Worked-out numbers: units to SI, parameters' values, printed digits. */
#include "checker/printed_numbers.hpp"

#include "checker/units.hpp"
#include "model/dimensions.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <map>
#include <sstream>

namespace eomgen::checker {

namespace {

bool digit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

/// End of the braced group that starts at `open` ('{'), or std::string::npos.
std::size_t group_end(const std::string& s, std::size_t open) {
    int depth = 0;
    for (std::size_t k = open; k < s.size(); ++k) {
        if (s[k] == '{') ++depth;
        if (s[k] == '}' && --depth == 0) return k + 1;
    }
    return std::string::npos;
}

/// `\circ` or `{\circ}` (spaces allowed) starts at `from` of `s`: an exponent that means degrees.
bool degrees_after(const std::string& s, std::size_t from) {
    std::string e;
    for (std::size_t k = from; k < s.size() && e.size() < 7; ++k)
        if (s[k] != ' ') e += s[k];
    return e.rfind("\\circ", 0) == 0 || e.rfind("{\\circ}", 0) == 0;
}

/// `x` with `digits` significant digits, in fixed notation (LaTeX has no `e+04`).
std::string fixed(double x, int digits) {
    if (x == 0) return "0";
    const int magnitude = int(std::floor(std::log10(std::abs(x))));
    std::ostringstream os;
    os << std::fixed << std::setprecision(std::max(0, digits - 1 - magnitude)) << x;
    return os.str();
}

/// `x` rounded to `digits` significant digits (half away from zero): 0.4576 to 2 is 0.46, 457.6 to 2 is 460.
double round_significant(double x, int digits) {
    if (x == 0 || digits <= 0) return x;
    const double unit = std::pow(10.0, std::floor(std::log10(std::abs(x))) - digits + 1);
    return std::round(x / unit) * unit;
}

/// "1.7", "0.042", "12", "201": a relative difference in percent, two significant digits below 10 %.
std::string percent(double rel) {
    const double p = rel * 100;
    return p >= 10 ? std::to_string(std::lround(p)) : fixed(p, 2);
}

/// The value of `e` with `subs`, when it is a real number.
std::optional<double> real_value(const GiNaC::ex& e, const GiNaC::exmap& subs) {
    try {
        const GiNaC::ex v = GiNaC::evalf(e.subs(subs));
        if (!GiNaC::is_a<GiNaC::numeric>(v)) return std::nullopt;
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(v);
        if (!n.is_real()) return std::nullopt;
        const double x = n.to_double();
        if (!std::isfinite(x)) return std::nullopt;
        return x;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

/// A side made numeric: units replaced by their SI factors.
struct NumericSide {
    GiNaC::ex value;
    std::optional<Dims> dims; ///< its dimension, from its units and the parameters' declared units, where known
    bool units = false;       ///< it holds units
    bool parameters = false;  ///< it holds parameters of the model
    bool other = false;       ///< it holds anything else (the state, time, an unknown name)
    std::vector<std::string> others;  ///< the known names of those others (`\dot{\psi}`, `t`), in order met
};

/// The name the text's context gives symbol `x` (`\psi`, `\dot{\psi}`), or "" when it has none.
std::string known_name(const GiNaC::ex& x, const LatexContext& ctx) {
    for (const auto& [name, value] : ctx.names)
        if (value.is_equal(x)) return name;
    return "";
}

NumericSide numeric_side(const GiNaC::ex& e, const Model& model, const LatexContext& ctx) {
    NumericSide s;
    GiNaC::exmap subs;
    std::map<GiNaC::ex, Dims, GiNaC::ex_is_less> dims = symbol_dimensions(model);
    std::vector<GiNaC::ex> stack{e};
    while (!stack.empty()) {
        const GiNaC::ex x = stack.back();
        stack.pop_back();
        for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
        if (!GiNaC::is_a<GiNaC::symbol>(x)) continue;
        bool parameter = false;
        for (const Parameter& p : model.parameters) parameter = parameter || x.is_equal(p.symbol);
        if (parameter) {
            s.parameters = true;
            continue;
        }
        const FreeName* f = ctx.free_name_of(x);
        if (f && f->kind == NameKind::Unit) {
            std::string u = f->name;
            if (u.rfind("\\mathrm{", 0) == 0 && u.back() == '}') u = u.substr(8, u.size() - 9);
            if (const std::optional<TextUnit> unit = text_unit(u)) {
                subs[x] = GiNaC::numeric(unit->factor);
                dims[x] = Dims::of(unit->dimension);
                s.units = true;
                continue;
            }
        }
        s.other = true;
        const std::string name = known_name(x, ctx);
        if (!name.empty() && std::find(s.others.begin(), s.others.end(), name) == s.others.end())
            s.others.push_back(name);
    }
    s.value = e.subs(subs);
    try {
        s.dims = dimension_of(e, dims);  // nothing where a parameter declares no unit
    } catch (const DimensionError&) {
        s.dims.reset();  // a sum of a length and a time: its value is judged, not its units
    }
    return s;
}

/// What follows a printed number, its unit (`\,\mathrm{sec}`, `^{\circ}`), without the spaces and the
/// punctuation that end a sentence.
std::string trim_unit(std::string u) {
    while (!u.empty() && (u.back() == ' ' || u.back() == '.' || u.back() == ',' || u.back() == ';')) u.pop_back();
    std::size_t k = 0;
    while (k < u.size() && u[k] == ' ') ++k;
    return u.substr(k);
}

/// A unit as LaTeX, after a number: "kg m^2/s" → `\,\mathrm{kg\,m^{2}/s}`.
std::string unit_latex(const std::string& unit) {
    std::string out = "\\,\\mathrm{";
    for (std::size_t k = 0; k < unit.size(); ++k) {
        if (unit[k] == ' ') {
            out += "\\,";
        } else if (unit[k] == '^') {
            std::size_t j = k + 1;
            while (j < unit.size() && (std::isdigit(static_cast<unsigned char>(unit[j])) || unit[j] == '-' || unit[j] == '.')) ++j;
            out += "^{" + unit.substr(k + 1, j - k - 1) + "}";
            k = j - 1;
        } else {
            out += unit[k];
        }
    }
    return out + "}";
}

std::size_t paragraph_end(const std::string& text, std::size_t at) {
    const std::size_t k = text.find("\n\n", at);
    return k == std::string::npos ? text.size() : k;
}

}  // namespace

std::optional<PrintedNumber> printed_number(const std::string& s) {
    std::vector<PrintedNumber> all;
    std::size_t k = 0;
    while (k < s.size()) {
        if (s[k] == '\\') {  // a command: units and text are skipped with their argument
            std::size_t j = k + 1;
            while (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) ++j;
            const std::string w = s.substr(k, j - k);
            if (w == "\\mathrm" || w == "\\text" || w == "\\textrm" || w == "\\mbox") {
                while (j < s.size() && s[j] == ' ') ++j;
                if (j < s.size() && s[j] == '{') j = group_end(s, j);
            }
            k = j == std::string::npos ? s.size() : std::max(j, k + 1);
            continue;
        }
        if (s[k] == '^' || s[k] == '_') {  // exponents (10^{-3}, ^{\circ}) and subscripts
            std::size_t j = k + 1;
            while (j < s.size() && s[j] == ' ') ++j;
            if (j < s.size() && s[j] == '{')
                j = group_end(s, j);
            else if (j < s.size() && s[j] == '\\') {
                ++j;
                while (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) ++j;
            } else {
                ++j;
            }
            k = j == std::string::npos ? s.size() : j;
            continue;
        }
        if (digit(s[k]) || (s[k] == '.' && k + 1 < s.size() && digit(s[k + 1]))) {
            PrintedNumber n;
            n.begin = k;
            std::size_t j = k;
            while (j < s.size() && digit(s[j])) ++j;
            if (j + 1 < s.size() && s[j] == '.' && digit(s[j + 1])) {
                const std::size_t point = j++;
                while (j < s.size() && digit(s[j])) ++j;
                n.decimals = int(j - point - 1);
            }
            n.end = j;
            k = j;
            // The base of a power (`10` of `10^{-3}`) is not the printed number; `1.3^{\circ}` is one.
            std::size_t after = j;
            while (after < s.size() && s[after] == ' ') ++after;
            if (after < s.size() && s[after] == '^' && !degrees_after(s, after + 1)) continue;
            const std::string text = s.substr(n.begin, j - n.begin);
            n.value = std::strtod(text.c_str(), nullptr);  // never throws: out of range is ±inf or 0
            if (!std::isfinite(n.value)) return std::nullopt;
            for (char c : text)
                if (digit(c) && (n.significant > 0 || c != '0')) ++n.significant;
            // An integer's trailing zeros are not counted: `590` is given to two digits, `3.10` to three.
            for (std::size_t z = text.size(); n.decimals == 0 && n.significant > 1 && z > 0 && text[z - 1] == '0'; --z)
                --n.significant;
            all.push_back(n);
            continue;
        }
        ++k;
    }
    std::vector<PrintedNumber> decimals;
    for (const PrintedNumber& n : all)
        if (n.decimals > 0) decimals.push_back(n);
    if (decimals.size() == 1) return decimals[0];
    if (decimals.empty() && all.size() == 1) return all[0];
    return std::nullopt;
}

ParameterValues::ParameterValues(const Model& model, const std::vector<std::pair<std::string, double>>& set)
    : model_(model), set_(model.parameters.size(), false) {
    for (const Parameter& p : model.parameters) values_.push_back(p.value);
    for (const auto& [name, value] : set) {
        std::size_t k = 0;
        while (k < model.parameters.size() && model.parameters[k].name != name) ++k;
        if (k == model.parameters.size()) {
            std::string names;
            for (const Parameter& p : model.parameters) names += (names.empty() ? "" : ", ") + p.name;
            throw CheckError("--set " + name + "=...: '" + name + "' is not a parameter of the model (" +
                             (names.empty() ? std::string("it has none") : "its parameters: " + names) + ")");
        }
        values_[k] = value;
        set_[k] = true;
    }
}

void ParameterValues::choose(std::size_t index, double value, std::size_t at, std::size_t until, int line) {
    choices_.push_back({index, at, until, value, line});
}

std::pair<double, std::string> ParameterValues::at(std::size_t index, std::size_t offset) const {
    for (auto c = choices_.rbegin(); c != choices_.rend(); ++c)
        if (c->index == index && c->from <= offset && offset < c->until)
            return {c->value, "chosen by the text on line " + std::to_string(c->line)};
    return {values_[index], set_[index] ? "from --set" : "from the model"};
}

bool check_number(const GiNaC::ex& a, const GiNaC::ex& b, const std::pair<std::string, std::string>& sources,
                  std::size_t at, const Model& model, const LatexContext& ctx, const Derivation& d,
                  ParameterValues& values, EquationCheck& r) {
    const NumericSide sa = numeric_side(a, model, ctx), sb = numeric_side(b, model, ctx);
    const GiNaC::exmap none;
    auto latex_of = [](const Parameter& p) { return p.latex.empty() ? p.name : p.latex; };
    // A number with units for a quantity of the state or of time: it has no value to compare with.
    for (int side : {1, 0}) {
        const NumericSide& num = side == 0 ? sa : sb;
        const NumericSide& formula = side == 0 ? sb : sa;
        if (num.other || num.parameters || !num.units || !formula.other || formula.others.empty()) continue;
        if (!printed_number(side == 0 ? sources.first : sources.second)) continue;
        std::string names;
        for (const std::string& n : formula.others) names += (names.empty() ? "$" : ", $") + n + "$";
        r.verdict = Verdict::NotComparable;
        r.reason = "a number for a quantity that depends on " + names +
                   ", which has no value (only the model's parameters have values): not compared";
        return true;
    }
    if (sa.other || sb.other) return false;
    // A parameter set to a number alone: the text's choice, for the rest of its paragraph.
    for (int side = 0; side < 2; ++side) {
        const GiNaC::ex& p = side == 0 ? a : b;
        const NumericSide& o = side == 0 ? sb : sa;
        for (std::size_t k = 0; k < model.parameters.size(); ++k) {
            if (!p.is_equal(model.parameters[k].symbol) || o.parameters) continue;
            const std::optional<double> v = real_value(o.value, none);
            if (!v) return false;
            const auto [before, origin] = values.at(k, std::size_t(-1));
            values.choose(k, *v, at, paragraph_end(d.text, at), d.position(at).line);
            std::ostringstream os;
            os << std::setprecision(6) << before;
            r.compared_with = "the value of $" + latex_of(model.parameters[k]) + "$";
            not_judged(r, Role::ChosenValue,
                       "a value the text chooses (" +
                           std::string(origin == "from --set" ? "--set gives " : "the model's is ") + os.str() +
                           "): the numbers that follow in its paragraph use it");
            return true;
        }
    }
    // Which side prints the number: the right one when both could.
    std::optional<PrintedNumber> printed;
    int number_side = -1;
    for (int side : {1, 0}) {
        const NumericSide& s = side == 0 ? sa : sb;
        if (s.parameters) continue;
        const std::optional<double> v = real_value(s.value, none);
        if (!v || *v == 0) continue;
        if (std::optional<PrintedNumber> n = printed_number(side == 0 ? sources.first : sources.second)) {
            if (n->decimals == 0 && !s.units) continue;  // an exact integer: the other comparisons decide
            printed = n;
            number_side = side;
            break;
        }
    }
    if (!printed) return false;
    const NumericSide& num = number_side == 0 ? sa : sb;
    const NumericSide& formula = number_side == 0 ? sb : sa;
    if (!formula.parameters && !num.units && !formula.units) return false;  // plain arithmetic
    GiNaC::exmap subs;
    std::ostringstream used;
    std::string origins;
    for (std::size_t k = 0; k < model.parameters.size(); ++k) {
        if (!formula.value.has(model.parameters[k].symbol)) continue;
        const auto [v, origin] = values.at(k, at);
        subs[model.parameters[k].symbol] = GiNaC::numeric(v);
        used << (used.tellp() > 0 ? ", " : "") << "$" << latex_of(model.parameters[k]) << " = "
             << std::setprecision(6) << v
             << (model.parameters[k].unit.empty() || model.parameters[k].unit == "1" ? "" : unit_latex(model.parameters[k].unit))
             << "$";
        if (origins.find(origin) == std::string::npos) origins += (origins.empty() ? "" : "; ") + origin;
    }
    const std::optional<double> computed = real_value(formula.value, subs);
    const std::optional<double> shown = real_value(num.value, none);
    if (!computed || !shown) return false;
    // In the text's units: the printed number times its unit (with 10^k) is `shown`, up to its sign.
    const double unit = std::abs(*shown / printed->value);
    const double text_value = *shown / unit, mine = *computed / unit;
    const std::string printed_text =
        (text_value < 0 ? "-" : "") +
        (number_side == 0 ? sources.first : sources.second).substr(printed->begin, printed->end - printed->begin);
    const std::string number_source = number_side == 0 ? sources.first : sources.second;
    r.compared_with = "the value eomgen computes" +
                      (used.tellp() > 0 ? " with " + used.str() + " (" + origins + ")" : std::string(""));
    // Units: a number printed in a unit of another dimension than the formula's is wrong whatever its digits.
    if (num.units && num.dims && formula.dims && *num.dims != *formula.dims) {
        const std::string printed_unit = trim_unit(number_source.substr(printed->end));
        r.verdict = Verdict::Disagrees;
        const std::string si = fixed(*computed, std::max(printed->significant, 2)) + unit_latex(si_unit_text(*formula.dims));
        r.wrong_terms.push_back("the text gives it in $" + printed_unit + "$, which is " + num.dims->str() +
                                ", but with the parameters' units it is " + formula.dims->str() +
                                ": eomgen computes $" + si + "$");
        // The correction: eomgen's value in SI, in place of the number and its unit.
        const std::string formula_source = number_side == 0 ? sources.second : sources.first;
        r.corrected = number_side == 0 ? si + " = " + formula_source : formula_source + " = " + si;
        return true;
    }
    // eomgen's value with its unit: the text's where it prints one (`\,\mathrm{sec}`, `\times 10^{-3}\,\mathrm{s}`),
    // else the SI unit of the formula where the parameters declare theirs.
    std::string value_unit;
    if (num.units)
        value_unit = " " + trim_unit(number_source.substr(printed->end));
    else if (formula.dims && !formula.dims->dimensionless())
        value_unit = unit_latex(si_unit_text(*formula.dims));
    const std::string value = fixed(mine, std::max(printed->significant + 2, 3)) + value_unit;
    // The digit rule: eomgen's value rounded to as many significant digits as the text prints is the printed
    // number (which is not 0: `shown` is not).
    const int digits = printed->significant;
    const double mine_rounded = round_significant(mine, digits);
    const std::string rounded = fixed(mine_rounded, digits);
    const bool agrees = std::abs(mine_rounded - text_value) <= 1e-9 * std::abs(text_value);
    if (agrees) {
        r.verdict = Verdict::Agrees;
        r.reason = "agrees to the printed digits: eomgen computes $" + value + "$, which rounds to the printed $" +
                   printed_text + "$";
        return true;
    }
    const double rel = std::abs(mine - text_value) / std::abs(mine);
    r.verdict = Verdict::Disagrees;
    r.difference = fixed(text_value - mine, std::max(digits, 2));
    r.wrong_terms.push_back("differs by " + percent(rel) + " %: eomgen computes $" + value + "$, which is $" +
                            rounded + value_unit + "$ to the printed " +
                            std::to_string(digits) + " significant digit" + (digits == 1 ? "" : "s") +
                            ", not the printed $" + printed_text + "$");
    std::string fixed_side = number_side == 0 ? sources.first : sources.second;
    // The digits are replaced; where eomgen's value has the other sign, the text's minus goes, or one comes.
    std::size_t begin = printed->begin;
    std::string digits_text = rounded[0] == '-' ? rounded.substr(1) : rounded;
    if ((mine < 0) != (text_value < 0)) {
        std::size_t k = begin;
        while (k > 0 && fixed_side[k - 1] == ' ') --k;
        if (k > 0 && fixed_side[k - 1] == '-')
            begin = k - 1;
        else
            digits_text = fixed_side.find_first_not_of(' ') == begin ? "-" + digits_text : "(-" + digits_text + ")";
    }
    fixed_side.replace(begin, printed->end - begin, digits_text);
    r.corrected = number_side == 0 ? fixed_side + " = " + sources.second : sources.first + " = " + fixed_side;
    return true;
}

}  // namespace eomgen::checker
