/** @file conditions.cpp  A row that sets values after a cue such as "started with" or "with". */
#include "checker/conditions.hpp"
#include "checker/latex_parser.hpp"

#include "checker/prose.hpp"

#include <algorithm>
#include <vector>
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

namespace {

/// A real number, written exactly or with constants (`20`, `\frac{\pi}{3}`): no symbol in it. (Anything with a
/// symbol or a function of the checker's is refused before evalf, which would throw on it, and GiNaC leaks what it
/// built when it throws.)
bool real_number(const GiNaC::ex& x) {
    if (GiNaC::is_a<GiNaC::numeric>(x)) return GiNaC::ex_to<GiNaC::numeric>(x).is_real();
    for (std::vector<GiNaC::ex> stack{x}; !stack.empty();) {
        const GiNaC::ex e = stack.back();
        stack.pop_back();
        if (GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::integral>(e)) return false;
        if (GiNaC::is_a<GiNaC::function>(e)) {
            const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
            if (name != "sin" && name != "cos" && name != "tan" && name != "sqrt" && name != "exp" && name != "log")
                return false;
        }
        for (std::size_t i = 0; i < e.nops(); ++i) stack.push_back(e.op(i));
    }
    try {
        const GiNaC::ex v = GiNaC::evalf(x);
        return GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real();
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace

bool names_an_instant(const GiNaC::ex& a, const GiNaC::ex& b, const Model& model) {
    const auto model_symbol = [&](const GiNaC::ex& x) {
        if (x.is_equal(model.t)) return true;
        for (const Parameter& p : model.parameters)
            if (x.is_equal(p.symbol)) return true;
        for (const Coordinate& c : model.coordinates)
            if (x.is_equal(c.q) || x.is_equal(c.qd) || x.is_equal(c.qdd)) return true;
        return false;
    };
    for (const auto& [time, other] : {std::pair(a, b), std::pair(b, a)}) {
        if (!time.is_equal(model.t)) continue;
        if (real_number(other)) return true;
        if (GiNaC::is_a<GiNaC::symbol>(other) && !model_symbol(other)) return true;
    }
    return false;
}

bool sets_initial_value(const std::string& name, const GiNaC::ex& value, const Model& model) {
    if (!real_number(value)) return false;
    for (const Coordinate& c : model.coordinates)
        for (const std::string& spelled : {c.latex, c.name})
            if (!spelled.empty() && (name == canonical_name(spelled) + "_{0}" || name == canonical_name(spelled) + "(0)" ||
                                     name == "\\dot{" + canonical_name(spelled) + "}(0)"))
                return true;
    return false;
}

}  // namespace eomgen::checker
