/** @file both_signs.cpp  `\theta_0 = \pm\arccos\frac{g}{\omega^2 R}`, `\dot r = \pm\sqrt{\dots}`: two equations in
 * one. Each is judged (`\pm` as + with `\mp` as −, then the other way round); the link agrees when both do, and
 * disagrees when one does, saying which sign. (Normal frequencies with ± are read by NormalModesCheck itself.) */
#include "checker/checker_internals.hpp"

namespace eomgen::checker::detail {

namespace {

/// `source` with `\pm` and `\mp` written as the signs of the upper (`upper`) or lower reading, of the same length
/// (so that offsets into it stay where they were).
std::string with_sign(std::string source, bool upper) {
    for (std::size_t k = source.find('\\'); k != std::string::npos; k = source.find('\\', k + 1)) {
        const bool pm = source.compare(k, 3, "\\pm") == 0, mp = source.compare(k, 3, "\\mp") == 0;
        if ((!pm && !mp) || (k + 3 < source.size() && std::isalpha(static_cast<unsigned char>(source[k + 3]))))
            continue;
        source.replace(k, 3, (pm == upper) ? "+  " : "-  ");
    }
    for (const auto& [sign, plus_first] : {std::pair<std::string, bool>{"\xC2\xB1", true},       // ±
                                           std::pair<std::string, bool>{"\xE2\x88\x93", false}}) {  // ∓
        for (std::size_t k = source.find(sign); k != std::string::npos; k = source.find(sign, k + 1))
            source.replace(k, sign.size(), std::string(plus_first == upper ? "+" : "-") + std::string(sign.size() - 1, ' '));
    }
    return source;
}

}  // namespace

bool two_equations_in_one(const Side& s) {
    return !s.ok && s.error.find("(two equations in one)") != std::string::npos;
}

EquationCheck Checker::check_both_signs(const FullChain& c, std::size_t i, std::size_t j, bool bridge) {
    EquationCheck result[2];
    for (int reading = 0; reading < 2; ++reading) {
        Side sides[2];
        for (int k = 0; k < 2; ++k) {
            const Side& original = *c.sides[k == 0 ? i : j].side;
            Side s = parse_expression(with_sign(original.source, reading == 0), ctx_);
            s.begin = original.begin;
            s.end = original.end;
            s.error_offset += original.begin;
            for (NameUse& u : s.uses) u.offset += original.begin;
            s.source = original.source;
            sides[k] = std::move(s);
        }
        FullChain signed_chain = c;
        signed_chain.sides[i].side = &sides[0];
        signed_chain.sides[j].side = &sides[1];
        // A ± spelled another way is still refused there: judged once, as refused, not again.
        both_signs_ = true;
        result[reading] = check_link(signed_chain, i, j, bridge);
        both_signs_ = false;
    }
    const char* const which[2] = {"the upper sign of ±", "the lower sign of ±"};
    if (result[0].verdict == Verdict::Agrees && result[1].verdict == Verdict::Agrees) {
        EquationCheck r = std::move(result[0]);
        r.reason = "with either sign of ±: " + r.reason;
        return r;
    }
    for (int reading = 0; reading < 2; ++reading)
        if (result[reading].verdict == Verdict::Disagrees) {
            EquationCheck r = std::move(result[reading]);
            r.reason = "with " + std::string(which[reading]) + ": " + r.reason;
            const Verdict other = result[1 - reading].verdict;
            r.notes.push_back(std::string("with ") + which[1 - reading] +
                              (other == Verdict::Agrees      ? " it agrees"
                               : other == Verdict::Disagrees ? " it disagrees too"
                                                             : std::string(" it is ") + verdict_name(other)));
            return r;
        }
    EquationCheck r = std::move(result[0].verdict == Verdict::Agrees ? result[1] : result[0]);
    r.reason = "with " + std::string(which[result[0].verdict == Verdict::Agrees ? 1 : 0]) + ": " + r.reason;
    return r;
}

}  // namespace eomgen::checker::detail
