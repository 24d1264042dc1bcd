/** @file definitions.cpp  The text's definitions, substituted where the text differentiates a defined name. */
#include "checker/definitions.hpp"

#include "checker/latex_normalize.hpp"

#include <algorithm>

namespace eomgen::checker {

void TextDefinitions::add(const GiNaC::ex& symbol, const std::string& name, const GiNaC::ex& value,
                          std::size_t offset, int line) {
    defs_[symbol].push_back({name, value, offset, line});
}

GiNaC::ex TextDefinitions::expand(const GiNaC::ex& operand, std::size_t at) const {
    GiNaC::ex e = operand;
    // A definition may use an earlier one: substitute until nothing changes (bounded: definitions come in
    // file order, and one of a name never uses itself).
    for (std::size_t round = 0; round <= defs_.size(); ++round) {
        GiNaC::exmap subs;
        for (const auto& [symbol, list] : defs_) {
            if (!e.has(symbol)) continue;
            const Definition* best = nullptr;
            for (const Definition& d : list)
                if (d.offset < at && (!best || d.offset > best->offset)) best = &d;
            if (!best) continue;
            subs[symbol] = best->value;
            const std::string note =
                "uses $" + best->name + "$ as the text defines it at line " + std::to_string(best->line);
            if (std::find(used_.begin(), used_.end(), note) == used_.end()) used_.push_back(note);
        }
        if (subs.empty()) break;
        e = e.subs(subs);
    }
    return e;
}

namespace {

/// The first free name of `ctx` in `e` for which `pick` holds, or nullptr.
template <class Pick>
const FreeName* find_free_name(const GiNaC::ex& e, const LatexContext& ctx, Pick pick) {
    std::vector<GiNaC::ex> stack{e};
    while (!stack.empty()) {
        const GiNaC::ex x = stack.back();
        stack.pop_back();
        for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
        const FreeName* f = ctx.free_name_of(x);
        if (f && pick(*f)) return f;
    }
    return nullptr;
}

}  // namespace

bool TextDefinitions::has_vector(const GiNaC::ex& operand, const LatexContext& ctx) {
    return find_free_name(operand, ctx, [](const FreeName& f) { return f.kind == NameKind::Vector; }) != nullptr;
}

void TextDefinitions::require_defined(const GiNaC::ex& operand, const LatexContext& ctx, const std::string& what) {
    const FreeName* f = find_free_name(operand, ctx, [](const FreeName& n) {
        return n.kind != NameKind::Unit && !is_constant_name(n.name);
    });
    if (!f) return;
    throw UndefinedInDerivative(f->name, "the " + what + " of $" + f->name +
                                             "$, which the text does not define and the model does not know: "
                                             "not taken as a constant (its derivative would be 0)");
}

std::vector<std::string> TextDefinitions::take_used() const {
    std::vector<std::string> out;
    out.swap(used_);
    return out;
}

}  // namespace eomgen::checker
