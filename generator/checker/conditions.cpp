/** @file conditions.cpp  A row that sets values after a cue such as "started with" or "with". */
#include "checker/conditions.hpp"

#include <algorithm>
#include <cctype>

namespace eomgen::checker {
namespace {

/// Words that lead into values being set, not claimed (whole words, lower case).
constexpr const char* kCues[] = {"initial", "initially", "started", "starts", "start", "released", "release",
                                 "with", "let", "assume", "assuming", "suppose", "take", "taking", "keep",
                                 "set", "setting", "given", "conditions", "condition"};

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool holds_motion(const GiNaC::ex& e, const Model& model, bool accelerations_only) {
    for (const Coordinate& c : model.coordinates) {
        if (e.has(c.qdd)) return true;
        if (!accelerations_only && (e.has(c.q) || e.has(c.qd))) return true;
    }
    return false;
}

}  // namespace

std::string lead_in(const Derivation& d, std::size_t offset, int sentences) {
    const std::string& s = d.text;
    if (offset > s.size()) return "";
    // The prose from the paragraph start to the math that holds `offset`, inline math left out; a display set
    // off by a blank line takes the paragraph before it (up to two back).
    std::string prose;
    std::size_t end = offset;
    for (int back = 0; back < 3; ++back) {
        const std::size_t para = end == 0 ? std::string::npos : s.rfind("\n\n", end - 1);
        const std::size_t floor = para == std::string::npos ? 0 : para + 2;
        prose.clear();
        bool in_math = false;
        std::size_t last_math_open = std::string::npos;
        for (std::size_t i = floor; i < end; ++i) {
            if (s[i] == '$' && (i == 0 || s[i - 1] != '\\')) {
                in_math = !in_math;
                if (in_math) last_math_open = prose.size();
                if (i + 1 < end && s[i + 1] == '$') ++i;
                continue;
            }
            if (!in_math) prose += s[i];
        }
        if (in_math && last_math_open != std::string::npos) prose.resize(last_math_open);
        for (const char* open : {"\\[", "\\begin{"}) {  // the delimiter that opens the display
            const std::size_t k = prose.rfind(open);
            if (k != std::string::npos) prose.resize(k);
        }
        if (prose.find_first_not_of(" \t\r\n") != std::string::npos || para == std::string::npos) break;
        end = para;
    }
    int seen = 0;
    for (std::size_t k = prose.size(); k-- > 1;)
        if ((prose[k - 1] == '.' || prose[k - 1] == ':' || prose[k - 1] == '?' || prose[k - 1] == '!') &&
            std::isspace(static_cast<unsigned char>(prose[k])) && ++seen == sentences) {
            prose = prose.substr(k);
            break;
        }
    std::string lower;
    for (char c : prose) lower += char(std::tolower(static_cast<unsigned char>(c)));
    return lower;
}

std::string condition_cue(const Derivation& d, std::size_t offset) {
    const std::string lower = lead_in(d, offset, 1);
    for (const char* cue : kCues) {
        const std::string w = cue;
        for (std::size_t k = lower.find(w); k != std::string::npos; k = lower.find(w, k + 1)) {
            const bool start_ok = k == 0 || !word_char(lower[k - 1]);
            const bool end_ok = k + w.size() >= lower.size() || !word_char(lower[k + w.size()]);
            if (start_ok && end_ok) return w;
        }
    }
    return "";
}

bool sets_a_value(const GiNaC::ex& a, const GiNaC::ex& b, const Model& model) {
    if (holds_motion(a, model, true) || holds_motion(b, model, true)) return false;
    auto name = [](const GiNaC::ex& e) { return GiNaC::is_a<GiNaC::symbol>(e); };
    return (name(a) && !holds_motion(b, model, false)) || (name(b) && !holds_motion(a, model, false));
}

}  // namespace eomgen::checker
