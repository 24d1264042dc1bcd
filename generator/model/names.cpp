/** @file names.cpp  Identifier rules, reserved names, "did you mean" hints, default LaTeX of names. */
#include "model/names.hpp"

#include "model/expression_parser.hpp"

#include <algorithm>
#include <cctype>
#include <iterator>

namespace eomgen {

namespace {

bool is_alpha(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
bool is_digit(char c) {
    return c >= '0' && c <= '9';
}

template <std::size_t N>
bool contains(const std::string_view (&list)[N], std::string_view name) {
    return std::find(std::begin(list), std::end(list), name) != std::end(list);
}

// clang-format off
// C++20 keywords (cppreference "C++ keywords"), with the alternative tokens and the TM-TS ones that
// compilers reserve. `final`, `override`, `import` and `module` are ordinary identifiers and not here.
constexpr std::string_view kCppKeywords[] = {
    "alignas", "alignof", "and", "and_eq", "asm", "atomic_cancel", "atomic_commit", "atomic_noexcept",
    "auto", "bitand", "bitor", "bool", "break", "case", "catch", "char", "char8_t", "char16_t", "char32_t",
    "class", "compl", "concept", "const", "consteval", "constexpr", "constinit", "const_cast", "continue",
    "co_await", "co_return", "co_yield", "decltype", "default", "delete", "do", "double", "dynamic_cast",
    "else", "enum", "explicit", "export", "extern", "false", "float", "for", "friend", "goto", "if",
    "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq", "nullptr",
    "operator", "or", "or_eq", "private", "protected", "public", "reflexpr", "register",
    "reinterpret_cast", "requires", "return", "short", "signed", "sizeof", "static", "static_assert",
    "static_cast", "struct", "switch", "synchronized", "template", "this", "thread_local", "throw", "true",
    "try", "typedef", "typeid", "typename", "union", "unsigned", "using", "virtual", "void", "volatile",
    "wchar_t", "while", "xor", "xor_eq"};

// Names the generated code declares or refers to unqualified.
constexpr std::string_view kGeneratedCodeNames[] = {
    "Scalar", "Model", "Params", "Config", "State", "MassMatrix", "Conserved", "Eigen", "std", "eomgen"};

// Every macro the standard headers, glibc and Eigen define (scripts/update_reserved_macros.sh), sorted:
// a variable with such a name would be rewritten by the preprocessor however the generated code qualifies
// it, and a program that includes a generated header includes those headers too. (M_PI, NAN, EOF, assert,
// errno, stdin, ... are all in it.)
constexpr std::string_view kPlatformMacros[] = {
#include "model/reserved_macros.inc"
};

struct GreekLetter {
    std::string_view name;
    std::string_view latex;
};

// Capitals that look like Latin letters have no LaTeX command; they are typeset as those letters.
constexpr GreekLetter kGreek[] = {
    {"alpha", "\\alpha"}, {"beta", "\\beta"}, {"gamma", "\\gamma"}, {"delta", "\\delta"},
    {"epsilon", "\\epsilon"}, {"zeta", "\\zeta"}, {"eta", "\\eta"}, {"theta", "\\theta"},
    {"iota", "\\iota"}, {"kappa", "\\kappa"}, {"lambda", "\\lambda"}, {"mu", "\\mu"}, {"nu", "\\nu"},
    {"xi", "\\xi"}, {"omicron", "o"}, {"pi", "\\pi"}, {"rho", "\\rho"}, {"sigma", "\\sigma"},
    {"tau", "\\tau"}, {"upsilon", "\\upsilon"}, {"phi", "\\phi"}, {"chi", "\\chi"}, {"psi", "\\psi"},
    {"omega", "\\omega"}, {"varepsilon", "\\varepsilon"}, {"vartheta", "\\vartheta"}, {"varpi", "\\varpi"},
    {"varrho", "\\varrho"}, {"varsigma", "\\varsigma"}, {"varphi", "\\varphi"},
    {"Alpha", "A"}, {"Beta", "B"}, {"Gamma", "\\Gamma"}, {"Delta", "\\Delta"}, {"Epsilon", "E"},
    {"Zeta", "Z"}, {"Eta", "H"}, {"Theta", "\\Theta"}, {"Iota", "I"}, {"Kappa", "K"},
    {"Lambda", "\\Lambda"}, {"Mu", "M"}, {"Nu", "N"}, {"Xi", "\\Xi"}, {"Omicron", "O"}, {"Pi", "\\Pi"},
    {"Rho", "P"}, {"Sigma", "\\Sigma"}, {"Tau", "T"}, {"Upsilon", "\\Upsilon"}, {"Phi", "\\Phi"},
    {"Chi", "X"}, {"Psi", "\\Psi"}, {"Omega", "\\Omega"},
};
// clang-format on

std::string greek_or_self(std::string_view word) {
    for (const auto& g : kGreek)
        if (g.name == word) return std::string(g.latex);
    return std::string(word);
}

std::string quoted(std::string_view name) {
    return "'" + std::string(name) + "'";
}

std::string to_lower(std::string_view s) {
    std::string r(s);
    for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return r;
}

}  // namespace

bool is_identifier(std::string_view name) {
    if (name.empty() || !is_alpha(name[0])) return false;
    return std::all_of(name.begin(), name.end(),
                       [](char c) { return is_alpha(c) || is_digit(c) || c == '_'; });
}

bool is_cpp_keyword(std::string_view name) {
    return contains(kCppKeywords, name);
}

std::string reserved_name_reason(std::string_view name, const std::vector<std::string>& coordinates) {
    const std::string q = quoted(name);
    if (is_cpp_keyword(name)) return q + " is a C++ keyword";
    if (name == "t") return q + " is reserved for time";
    if (name == "pi") return q + " is reserved for the constant pi";
    if (name == "dot") return q + " is reserved for velocities, as in dot(q)";
    const auto& functions = expression_function_names();
    if (std::find(functions.begin(), functions.end(), name) != functions.end())
        return q + " is the name of a function of the expression language";
    if (contains(kGeneratedCodeNames, name)) return q + " is a name the generated code uses";
    if (std::binary_search(std::begin(kPlatformMacros), std::end(kPlatformMacros), name))
        return q + " is a macro of the C/C++ standard library or of Eigen (a program that includes the generated "
                   "header would see it rewritten)";
    if (name.substr(0, 6) == "EIGEN_") return q + " starts with 'EIGEN_', which Eigen reserves for its macros";
    if (name.size() >= 2 && name[0] == 't' &&
        std::all_of(name.begin() + 1, name.end(), [](char c) { return is_digit(c); }))
        return q + " is reserved for temporaries of the generated code (t0, t1, ...)";
    if (!name.empty() && name.back() == '_') return q + " ends with '_', which the generated code reserves";
    if (name.find("__") != std::string_view::npos) return q + " contains '__', which C++ reserves";
    if (name.substr(0, 4) == "sin_" || name.substr(0, 4) == "cos_")
        return q + " starts with '" + std::string(name.substr(0, 4)) +
               "', which the generated code reserves for sines and cosines";
    for (const auto& c : coordinates) {
        if (name == c + "_dot") return q + " is the name of the velocity of coordinate '" + c + "'";
        if (name == c + "_ddot") return q + " is the name of the acceleration of coordinate '" + c + "'";
    }
    return {};
}

std::string name_problem(std::string_view name, const std::vector<std::string>& coordinates) {
    if (name.empty()) return "a name may not be empty";
    if (!is_identifier(name))
        return quoted(name) +
               " is not an identifier: use a letter followed by letters, digits and '_' "
               "([A-Za-z][A-Za-z0-9_]*)";
    return reserved_name_reason(name, coordinates);
}

std::string output_name_reason(std::string_view name, const std::vector<std::string>& coordinates,
                               const std::vector<std::string>& constraints) {
    const std::string q = quoted(name);
    if (name == "energy") return q + " is the CSV column of the energy function";
    if (name == "work") return q + " is the CSV column of the work of the forces (where h is not conserved)";
    if (name == "h") return q + " is the name of the energy function among the conserved quantities";
    for (const auto& c : coordinates)
        if (name == "p_" + c) return q + " is the name of the momentum of coordinate '" + c + "'";
    for (const auto& c : constraints) {
        if (name == "residual_" + c)
            return q + " is the CSV column of the residual of constraint '" + c + "'";
        if (name == "lambda_" + c) return q + " is the name of the multiplier of constraint '" + c + "'";
    }
    return {};
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    // Full table (the words are short): d[i][j] = distance between a[0..i) and b[0..j).
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[a.size()][b.size()];
}

std::string closest_name(std::string_view name, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t best_distance = 3;  // only distances 0..2 are suggested
    const std::string lower = to_lower(name);
    for (const auto& c : candidates) {
        if (c == name) continue;
        if (to_lower(c) == lower) return c;
        const std::size_t d = edit_distance(name, c);
        if (d < best_distance && 2 * d <= std::max(name.size(), c.size())) {
            best = c;
            best_distance = d;
        }
    }
    return best;
}

std::string default_latex(std::string_view name) {
    // base = up to the first '_', minus trailing digits; subscript = those digits and the '_' parts.
    const std::size_t underscore = name.find('_');
    std::string_view head = name.substr(0, underscore);
    std::size_t digits = head.size();
    while (digits > 0 && is_digit(head[digits - 1])) --digits;
    if (digits == 0) digits = head.size();  // all digits: not a valid identifier, keep it whole

    std::vector<std::string> subscripts;
    if (digits < head.size()) subscripts.emplace_back(head.substr(digits));
    if (underscore != std::string_view::npos) {
        std::string_view rest = name.substr(underscore + 1);
        while (true) {
            const std::size_t next = rest.find('_');
            std::string_view part = rest.substr(0, next);
            if (!part.empty()) subscripts.push_back(greek_or_self(part));
            if (next == std::string_view::npos) break;
            rest = rest.substr(next + 1);
        }
    }
    std::string latex = greek_or_self(head.substr(0, digits));
    if (subscripts.empty()) return latex;
    latex += "_{";
    for (std::size_t i = 0; i < subscripts.size(); ++i) latex += (i ? "," : "") + subscripts[i];
    return latex + "}";
}

}  // namespace eomgen
