/** @file coverage.cpp  The rows of math with a relation that produced no equation, as "not read". */
#include "checker/coverage.hpp"

#include <algorithm>
#include <cstring>
#include <string>

namespace eomgen::checker {
namespace {

constexpr const char* kRelationCommands[] = {"\\approx", "\\simeq", "\\equiv", "\\leq", "\\geq", "\\le", "\\ge",
                                             "\\neq", "\\ne", "\\cong", "\\propto", "\\sim"};

/// Length of the relation sign at text[i], 0 when there is none. `\left<`/`\langle` are no relations.
std::size_t relation_at(const std::string& s, std::size_t i) {
    const char c = s[i];
    if (c == '=' || c == '<' || c == '>') {
        if (c != '=' && i >= 5 && (s.compare(i - 5, 5, "\\left") == 0 || (i >= 6 && s.compare(i - 6, 6, "\\right") == 0)))
            return 0;
        return 1;
    }
    if (c != '\\') return 0;
    for (const char* cmd : kRelationCommands) {
        const std::size_t n = std::strlen(cmd);
        if (s.compare(i, n, cmd) == 0 && (i + n >= s.size() || !std::isalpha(static_cast<unsigned char>(s[i + n]))))
            return n;
    }
    return 0;
}

struct Opening {
    char c;
    std::size_t at;
};

std::string describe(const Derivation& d, std::size_t offset) {
    const SourcePos p = d.position(offset);
    return std::to_string(p.line) + ":" + std::to_string(p.column);
}

}  // namespace

std::vector<EquationCheck> unread_rows(const Derivation& d, const std::vector<const MathRow*>& rows,
                                       const std::vector<EquationCheck>& reported) {
    std::vector<std::size_t> reported_at;
    for (const EquationCheck& e : reported) {
        if (e.where.line < 1 || std::size_t(e.where.line) > d.line_starts.size()) continue;
        reported_at.push_back(d.line_starts[std::size_t(e.where.line - 1)] + std::size_t(std::max(e.where.column, 1) - 1));
    }
    std::vector<EquationCheck> out;
    for (const MathRow* row : rows) {
        const std::string& s = row->text;
        const std::size_t from = row->offset, to = row->offset + s.size();
        if (std::any_of(reported_at.begin(), reported_at.end(), [&](std::size_t a) { return a >= from && a < to; }))
            continue;
        // The first relation sign, with the groups open around it.
        std::vector<Opening> open;
        std::size_t sign = std::string::npos, sign_len = 0;
        std::vector<Opening> open_at_sign;
        for (std::size_t i = 0; i < s.size() && sign == std::string::npos; ++i) {
            const char c = s[i];
            if (c == '%' && (i == 0 || s[i - 1] != '\\')) {  // a comment up to the end of the line
                while (i < s.size() && s[i] != '\n') ++i;
                continue;
            }
            if (c == '\\' && i + 1 < s.size() && std::strchr("{}()[]%$&#_", s[i + 1])) {
                ++i;  // an escaped character, and \( \) \[ \] are no groups here
                continue;
            }
            if (const std::size_t n = relation_at(s, i)) {
                sign = i;
                sign_len = n;
                open_at_sign = open;
                break;
            }
            if (c == '(' || c == '[' || c == '{') open.push_back({c, i});
            if ((c == ')' || c == ']' || c == '}') && !open.empty()) open.pop_back();
        }
        if (sign == std::string::npos) continue;
        // Which of the groups open at the sign stay open to the end of the row.
        std::vector<Opening> still = open_at_sign;
        {
            std::vector<Opening> stack = open_at_sign;
            for (std::size_t i = sign + sign_len; i < s.size(); ++i) {
                const char c = s[i];
                if (c == '\\' && i + 1 < s.size()) {
                    ++i;
                    continue;
                }
                if (c == '(' || c == '[' || c == '{') stack.push_back({c, i});
                if ((c == ')' || c == ']' || c == '}') && !stack.empty()) stack.pop_back();
            }
            still.clear();
            for (const Opening& o : stack)
                if (o.at < sign) still.push_back(o);
        }
        EquationCheck e;
        e.verdict = Verdict::NotRead;
        e.where = d.position(from + sign);
        if (row->section >= 0) e.section = d.sections[std::size_t(row->section)].title;
        std::string eq = s;
        const std::size_t a = eq.find_first_not_of(" \t\r\n"), b = eq.find_last_not_of(" \t\r\n");
        e.equation = a == std::string::npos ? "" : eq.substr(a, b - a + 1);
        const std::string sign_text = s.substr(sign, sign_len);
        if (!still.empty()) {
            e.reason = "the '" + sign_text + "' is inside the '" + std::string(1, still.back().c) + "' opened at " +
                       describe(d, from + still.back().at) + ", which is not closed in the row: no equation is read";
        } else if (!open_at_sign.empty()) {
            e.reason = "the '" + sign_text + "' is inside the '" + std::string(1, open_at_sign.back().c) +
                       "' opened at " + describe(d, from + open_at_sign.back().at) +
                       " (a group or a command's argument), not between two sides: no equation is read";
        } else {
            e.reason = "no equation could be taken from this row around the '" + sign_text + "'";
        }
        out.push_back(std::move(e));
    }
    return out;
}

}  // namespace eomgen::checker
