/** @file correction_check.cpp  Corrections parsed back and checked before they are printed. */
#include "checker/correction_check.hpp"

#include "checker/linear_algebra.hpp"

#include <cctype>
#include <cstring>

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

std::vector<TermEdit> one_term_edits(const std::string& side, std::size_t max_terms) {
    for (const char* refused : {"\\pm", "\\mp", "&", "\\\\"})
        if (side.find(refused) != std::string::npos) return {};
    struct Term {
        std::size_t sign;   // offset of its sign, or npos (the first term, unsigned)
        std::size_t begin;  // of its body
        std::size_t end;
    };
    std::vector<Term> terms;
    const std::size_t first = side.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return {};
    int depth = 0;
    std::size_t sign = std::string::npos, begin = first;
    char previous = 0;  // the last character outside spaces, at depth 0 or not
    for (std::size_t k = first; k < side.size(); ++k) {
        const char ch = side[k];
        if (ch == '\\' && k + 1 < side.size()) {
            const char next = side[k + 1];
            if (next == '{' || next == '[' || next == '(') ++depth;
            if (next == '}' || next == ']' || next == ')') --depth;
            previous = next;
            ++k;
            if (std::isalpha(static_cast<unsigned char>(next)))  // a command: its letters
                while (k + 1 < side.size() && std::isalpha(static_cast<unsigned char>(side[k + 1]))) previous = side[++k];
            continue;
        }
        if (ch == '{' || ch == '(' || ch == '[') ++depth;
        if (ch == '}' || ch == ')' || ch == ']') --depth;
        if (depth < 0) return {};
        if (depth == 0 && (ch == '+' || ch == '-')) {
            const bool unary = previous == 0 || std::strchr("+-^_({[=,", previous) != nullptr;
            if (k == first) {
                sign = k;
                begin = k + 1;
            } else if (!unary) {
                terms.push_back({sign, begin, k});
                sign = k;
                begin = k + 1;
            }
        }
        if (!std::isspace(static_cast<unsigned char>(ch))) previous = ch;
    }
    if (depth != 0) return {};
    terms.push_back({sign, begin, side.size()});
    if (terms.size() > max_terms) return {};
    const auto body = [&](const Term& t) {
        const std::size_t b = side.find_first_not_of(" \t\r\n", t.begin);
        const std::size_t e = side.find_last_not_of(" \t\r\n", t.end - 1);
        return b == std::string::npos || e == std::string::npos || e < b ? std::string() : side.substr(b, e + 1 - b);
    };
    std::vector<TermEdit> out;
    for (std::size_t t = 0; t < terms.size(); ++t) {
        const Term& term = terms[t];
        const std::string written = body(term);
        if (written.empty()) return {};
        std::string flipped = side;
        if (term.sign == std::string::npos)
            flipped.insert(term.begin, "-");
        else if (t == 0 && side[term.sign] == '-')
            flipped.erase(term.sign, 1);
        else
            flipped[term.sign] = side[term.sign] == '+' ? '-' : '+';
        out.push_back({flipped, written, false});
    }
    if (terms.size() >= 2)
        for (std::size_t t = 0; t < terms.size(); ++t) {
            const Term& term = terms[t];
            const std::size_t from = term.sign == std::string::npos ? term.begin : term.sign;
            std::string dropped = side.substr(0, from) + side.substr(term.end);
            if (t == 0) {  // the next term leads now: its `+` goes
                const std::size_t lead = dropped.find_first_not_of(" \t\r\n", from);
                if (lead != std::string::npos && dropped[lead] == '+') dropped.erase(lead, 1);
            }
            const std::size_t a = dropped.find_first_not_of(" \t\r\n"), e = dropped.find_last_not_of(" \t\r\n");
            if (a == std::string::npos) continue;
            out.push_back({dropped.substr(a, e + 1 - a), body(term), true});
        }
    return out;
}

}  // namespace eomgen::checker
