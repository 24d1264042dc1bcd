/** @file conditions.cpp  A row that sets values after a cue such as "started with" or "with". */
#include "checker/conditions.hpp"

#include "checker/prose.hpp"

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
