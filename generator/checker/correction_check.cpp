/** @file correction_check.cpp  Corrections parsed back and checked before they are printed. */
#include "checker/correction_check.hpp"

#include "checker/linear_algebra.hpp"

namespace eomgen::checker {
namespace {

std::string squeezed(const std::string& s) {
    std::string out;
    for (char c : s)
        if (c != ' ') out += c;
    return out;
}

}  // namespace

std::string correction_problem(const std::string& corrected, LatexContext& context, const LinkCheck& check) {
    const std::string flat = squeezed(corrected);
    if (flat.find("=0\\left(") != std::string::npos || flat.rfind("0\\left(", 0) == 0)
        return "it is a multiple of zero";
    if (flat.find("-\\left(0\\right)") != std::string::npos) return "it subtracts zero";
    const std::vector<Chain> chains = parse_math(corrected, context);
    if (chains.size() != 1 || chains[0].sides.size() < 2) return "it is not one equation";
    const Chain& c = chains[0];
    for (const Side& s : c.sides)
        if (!s.ok && !reads_as_array(s)) return "it cannot be read back (" + s.error + ")";
    for (std::size_t j = 1; j < c.sides.size(); ++j) {
        const EquationCheck r = check(c, j - 1, j);
        if (r.verdict != Verdict::Agrees)
            return std::string("checked, it ") + (r.verdict == Verdict::Disagrees ? "disagrees" : "is not comparable") +
                   (r.reason.empty() ? std::string() : " (" + r.reason + ")");
    }
    return "";
}

std::string scaled_step(const std::string& left, const std::string& k, const std::string& right) {
    if (k.empty() || k == "0") return "";
    if (k == "1") return left + " = " + right;
    if (k == "-") return left + " = -\\left(" + right + "\\right)";
    return left + " = " + k + " \\left(" + right + "\\right)";
}

std::string lagrange_form(const std::string& p, const std::string& q) {
    const std::string dt = "\\frac{d}{dt}\\left(" + p + "\\right)";
    if (q == "0") return dt + " = 0";
    return dt + " - \\left(" + q + "\\right) = 0";
}

}  // namespace eomgen::checker
