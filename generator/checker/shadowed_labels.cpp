/** @file shadowed_labels.cpp  A parameter's letter read as eomgen's label where only the label makes sense
 * (shadowed_labels.hpp). */
#include "checker/shadowed_labels.hpp"

#include "checker/state_symbols.hpp"

#include <algorithm>

namespace eomgen::checker {

std::string shadowed_label_note(const GiNaC::ex& parameter, const ShadowedLabel& l) {
    const std::string name = GiNaC::ex_to<GiNaC::symbol>(parameter).get_name();
    return "reads $" + l.what + "$ here as eomgen's $" + l.what + "$, not the model's parameter $" + name +
           "$ written with the same letter";
}

GiNaC::ex labels_under_derivatives(const GiNaC::ex& e, const detail::ExMap<ShadowedLabel>& shadowed,
                                   const Model& model, std::vector<std::string>& notes) {
    if (shadowed.empty() || e.nops() == 0) return e;
    if (is_ex_the_function(e, pdiff) && state_symbol(e.op(1), model)) {
        if (const auto it = shadowed.find(e.op(0)); it != shadowed.end()) {
            add_note_once(notes, shadowed_label_note(e.op(0), it->second));
            return pdiff(it->second.label, e.op(1));
        }
    }
    struct Each : GiNaC::map_function {
        const detail::ExMap<ShadowedLabel>& shadowed;
        const Model& model;
        std::vector<std::string>& notes;
        Each(const detail::ExMap<ShadowedLabel>& s, const Model& m, std::vector<std::string>& n)
            : shadowed(s), model(m), notes(n) {}
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            return labels_under_derivatives(x, shadowed, model, notes);
        }
    } each(shadowed, model, notes);
    return e.map(each);
}

const ShadowedLabel* label_on_the_left(const GiNaC::ex& first, const std::vector<GiNaC::ex>& others,
                                       const detail::ExMap<ShadowedLabel>& shadowed, const detail::ExSet& labels,
                                       const Model& model) {
    const auto it = shadowed.find(first);
    if (it == shadowed.end() || others.empty()) return nullptr;
    const auto energy = [&](const GiNaC::ex& x) {
        if (std::any_of(model.coordinates.begin(), model.coordinates.end(),
                        [&](const Coordinate& c) { return x.has(c.qd); }))
            return true;
        return std::any_of(labels.begin(), labels.end(), [&](const GiNaC::ex& l) { return x.has(l); });
    };
    return std::any_of(others.begin(), others.end(), energy) ? &it->second : nullptr;
}

}  // namespace eomgen::checker
