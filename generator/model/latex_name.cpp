/** @file latex_name.cpp  The safe set of LaTeX for names (see latex_name.hpp). */
#include "model/latex_name.hpp"

#include <algorithm>
#include <iterator>

namespace eomgen {
namespace {

// clang-format off
constexpr std::string_view kCommands[] = {
    // Greek letters and their variants
    "alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta", "vartheta", "iota",
    "kappa", "varkappa", "lambda", "mu", "nu", "xi", "pi", "varpi", "rho", "varrho", "sigma", "varsigma", "tau",
    "upsilon", "phi", "varphi", "chi", "psi", "omega", "digamma",
    "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi", "Psi", "Omega",
    "varGamma", "varDelta", "varTheta", "varLambda", "varXi", "varPi", "varSigma", "varUpsilon", "varPhi",
    "varPsi", "varOmega",
    // accents
    "dot", "ddot", "dddot", "hat", "widehat", "bar", "overline", "underline", "tilde", "widetilde", "vec",
    "check", "breve", "acute", "grave", "mathring",
    // alphabets and text
    "mathrm", "mathit", "mathbf", "mathsf", "mathtt", "mathcal", "mathscr", "mathfrak", "mathbb", "boldsymbol",
    "bm", "operatorname", "text", "textrm", "textit", "textbf",
    // symbols
    "ell", "hbar", "imath", "jmath", "prime", "infty", "partial", "nabla", "star", "ast", "circ", "bullet",
    "cdot", "times", "dagger", "ddagger", "perp", "parallel", "odot", "oplus", "otimes", "wp", "Re", "Im",
    "aleph", "flat", "sharp", "natural", "top", "bot"};
// clang-format on

constexpr std::string_view kPunctuation = "_^{}()[]',.:;+-*/|=<>! ";
constexpr std::string_view kControlSymbols = ",;:! {}|";
constexpr std::size_t kLongest = 200;

bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

LatexNameProblem latex_name_problem(std::string_view s) {
    if (s.empty()) return {0, "a LaTeX name may not be empty"};
    if (s.size() > kLongest) return {kLongest, "a LaTeX name may be at most 200 bytes long"};
    int depth = 0;
    for (std::size_t i = 0; i < s.size();) {
        const char c = s[i];
        if (c == '\\') {
            std::size_t j = i + 1;
            while (j < s.size() && is_letter(s[j])) ++j;
            if (j == i + 1) {
                if (j < s.size() && kControlSymbols.find(s[j]) != std::string_view::npos) {
                    i = j + 1;
                    continue;
                }
                return {i, "a backslash in a LaTeX name must start a letter command such as \\alpha or one of "
                           "\\, \\; \\: \\! \\{ \\} \\|"};
            }
            const std::string_view command = s.substr(i + 1, j - i - 1);
            if (std::find(std::begin(kCommands), std::end(kCommands), command) == std::end(kCommands))
                return {i, "\\" + std::string(command) +
                               " is not among the LaTeX commands a name may use (Greek letters, accents such as "
                               "\\dot and \\hat, alphabets such as \\mathrm, and symbols such as \\ell: see "
                               "docs/model_files.md)"};
            i = j;
            continue;
        }
        if (c == '{') ++depth;
        if (c == '}' && --depth < 0) return {i, "this '}' closes no '{'"};
        if (!is_letter(c) && !is_digit(c) && kPunctuation.find(c) == std::string_view::npos) {
            const unsigned char u = static_cast<unsigned char>(c);
            if (u >= 0x80) return {i, "a LaTeX name is ASCII: write Greek letters as commands, e.g. \\theta"};
            if (u < 0x20 || u == 0x7f) return {i, "a LaTeX name may not hold a control character or a line break"};
            return {i, "'" + std::string(1, c) + "' may not appear in a LaTeX name (allowed: letters, digits, "
                                                 "commands, and _ ^ { } ( ) [ ] ' , . : ; + - * / | = < > !)"};
        }
        ++i;
    }
    if (depth > 0) return {s.size(), "a '{' is not closed"};
    return {};
}

}  // namespace eomgen
