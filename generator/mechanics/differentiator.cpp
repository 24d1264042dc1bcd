/** @file differentiator.cpp  Remembered, support-skipping symbolic derivatives (differentiator.hpp). */
#include "mechanics/differentiator.hpp"

#include "model/stored_terms.hpp"

#include <algorithm>

namespace eomgen {
namespace {

// GiNaC 1.8's function::derivative calls expl_derivative() inside a try block and, for a function without
// an explicit derivative (sin, cos, exp, ... all of them), applies the chain rule in the catch block: every
// derivative of a sin or cos throws and catches an exception, which was a fifth of derive_equations' time.
// Registering, for those functions, an explicit derivative that is that same chain rule (the catch block's
// code: Σ_i pderivative(i)·∂arg_i/∂s over the arguments with a nonzero derivative) gives the same
// expressions without the exception. pderivative and the function registry are protected members: reached
// through derived classes, as the language allows.
struct FunctionAccess : GiNaC::function {
    static std::vector<GiNaC::function_options>& registry() { return registered_functions(); }
    static GiNaC::ex partial(const GiNaC::function& f, unsigned i) { return (f.*(&FunctionAccess::pderivative))(i); }
};
struct FunctionOptionsAccess : GiNaC::function_options {
    static bool has_explicit_derivative(const GiNaC::function_options& o) {
        return o.*(&FunctionOptionsAccess::expl_derivative_f) != nullptr;
    }
};

/// The serials of the functions install_chain_rule() gave the chain rule (the others, abs or conjugate with
/// explicit derivatives of their own, are left to GiNaC::diff).
std::vector<char>& chain_rule_functions() {
    static std::vector<char> serials;
    return serials;
}

GiNaC::ex chain_rule(const GiNaC::exvector& args, const GiNaC::symbol& s) {
    const GiNaC::function f(GiNaC::function::current_serial, args);
    GiNaC::ex result;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const GiNaC::ex d = args[i].diff(s);
        if (!d.is_zero()) result += FunctionAccess::partial(f, static_cast<unsigned>(i)) * d;
    }
    return result;
}

struct MulAccess : GiNaC::mul {
    static GiNaC::expair split(const GiNaC::mul& m, const GiNaC::ex& e) { return (m.*(&MulAccess::split_ex_to_pair))(e); }
};

}  // namespace

SymbolSupport::SymbolSupport(const std::vector<GiNaC::ex>& symbols) {
    for (const GiNaC::ex& s : symbols) index_.emplace(s, index_.size());
    words_per_node_ = std::max<std::size_t>(1, (index_.size() + 63) / 64);
    words_.assign(words_per_node_, 0);  // offset 0: the empty set, for numbers and symbols not in the list
}

std::vector<std::uint64_t> SymbolSupport::mask(const GiNaC::exmap& of, bool& indexed) const {
    std::vector<std::uint64_t> m(words_per_node_, 0);
    indexed = true;
    for (const auto& entry : of) {
        const auto it = index_.find(entry.first);
        if (it == index_.end()) {
            indexed = false;
            continue;
        }
        m[it->second / 64] |= std::uint64_t{1} << (it->second % 64);
    }
    return m;
}

std::vector<std::uint64_t> SymbolSupport::mask(const std::vector<GiNaC::ex>& of) const {
    GiNaC::exmap keys;
    for (const GiNaC::ex& s : of) keys[s] = 1;
    bool indexed = false;
    return mask(keys, indexed);
}

bool SymbolSupport::holds(const GiNaC::ex& e, const std::vector<std::uint64_t>& mask) {
    const std::size_t at = bits_of(e);
    for (std::size_t w = 0; w < words_per_node_; ++w)
        if (words_[at + w] & mask[w]) return true;
    return false;
}

std::size_t SymbolSupport::bits_of(const GiNaC::ex& e) {
    if (GiNaC::is_exactly_a<GiNaC::numeric>(e)) return 0;
    const GiNaC::basic* key = &GiNaC::ex_to<GiNaC::basic>(e);
    if (const auto it = nodes_.find(key); it != nodes_.end()) return it->second.second;
    std::vector<std::uint64_t> bits(words_per_node_, 0);
    auto merge = [&](const GiNaC::ex& child) {
        const std::size_t at = bits_of(child);  // may grow words_: read after the call
        for (std::size_t w = 0; w < words_per_node_; ++w) bits[w] |= words_[at + w];
    };
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        if (const auto it = index_.find(e); it != index_.end())
            bits[it->second / 64] |= std::uint64_t{1} << (it->second % 64);
    } else {
        StoredTerms::for_each_child(e, merge);
    }
    const std::size_t at = words_.size();
    words_.insert(words_.end(), bits.begin(), bits.end());
    nodes_.emplace(key, std::make_pair(e, at));
    return at;
}

Differentiator::Differentiator(GiNaC::exmap seeds, SymbolSupport* support) : seeds_(std::move(seeds)) {
    if (!support) return;
    bool indexed = false;
    mask_ = support->mask(seeds_, indexed);
    if (indexed) support_ = support;  // a seed the support does not track: no skipping
}

GiNaC::ex Differentiator::operator()(const GiNaC::ex& e) {
    if (GiNaC::is_exactly_a<GiNaC::numeric>(e) || GiNaC::is_exactly_a<GiNaC::constant>(e)) return 0;
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        const auto it = seeds_.find(e);
        return it == seeds_.end() ? GiNaC::ex(0) : it->second;
    }
    const GiNaC::basic* key = &GiNaC::ex_to<GiNaC::basic>(e);
    if (auto it = memo_.find(key); it != memo_.end()) return it->second.second;
    GiNaC::ex d = support_ && !support_->holds(e, mask_) ? GiNaC::ex(0) : derivative(e);
    memo_.emplace(key, std::make_pair(e, d));  // e kept alive so that its address stays its own
    return d;
}

GiNaC::ex Differentiator::derivative(const GiNaC::ex& e) {
    if (GiNaC::is_exactly_a<GiNaC::add>(e)) {
        GiNaC::epvector terms;
        for (const GiNaC::expair& t : StoredTerms::pairs(e)) {
            GiNaC::ex d = (*this)(t.rest);
            if (!d.is_zero()) terms.push_back(GiNaC::expair(d, t.coeff));
        }
        if (terms.empty()) return 0;
        return GiNaC::dynallocate<GiNaC::add>(std::move(terms));
    }
    if (GiNaC::is_exactly_a<GiNaC::mul>(e)) {
        // D(a·b·c) = D(a)·b·c + a·D(b)·c + a·b·D(c), each factor a = rest^coeff.
        const GiNaC::mul& m = GiNaC::ex_to<GiNaC::mul>(e);
        const GiNaC::epvector& factors = StoredTerms::pairs(e);
        GiNaC::exvector terms;
        for (std::size_t k = 0; k < factors.size(); ++k) {
            const GiNaC::ex d = (*this)(factors[k].rest);
            if (d.is_zero()) continue;
            GiNaC::epvector seq = factors;
            seq[k] = MulAccess::split(m, GiNaC::pow(factors[k].rest, factors[k].coeff - 1) * d);
            terms.push_back(GiNaC::dynallocate<GiNaC::mul>(std::move(seq), StoredTerms::overall_coefficient(e) * factors[k].coeff));
        }
        if (terms.empty()) return 0;
        if (terms.size() == 1) return terms[0];
        return GiNaC::dynallocate<GiNaC::add>(std::move(terms));
    }
    if (GiNaC::is_exactly_a<GiNaC::power>(e) && GiNaC::is_exactly_a<GiNaC::numeric>(e.op(1))) {
        // D(b^r) = r·b^(r−1)·D(b)
        const GiNaC::ex d = (*this)(e.op(0));
        if (d.is_zero()) return 0;
        GiNaC::epvector seq{GiNaC::expair(e.op(0), e.op(1) - 1), GiNaC::expair(d, 1)};
        return GiNaC::dynallocate<GiNaC::mul>(std::move(seq), e.op(1));
    }
    const std::vector<char>& chain = chain_rule_functions();
    if (GiNaC::is_exactly_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_serial() < chain.size() &&
        chain[GiNaC::ex_to<GiNaC::function>(e).get_serial()]) {
        const GiNaC::function& f = GiNaC::ex_to<GiNaC::function>(e);
        GiNaC::ex result;
        for (std::size_t i = 0; i < f.nops(); ++i) {
            const GiNaC::ex d = (*this)(f.op(i));
            if (!d.is_zero()) result += FunctionAccess::partial(f, static_cast<unsigned>(i)) * d;
        }
        return result;
    }
    GiNaC::ex d;
    for (const auto& [x, v] : seeds_) d += GiNaC::diff(e, GiNaC::ex_to<GiNaC::symbol>(x)) * v;
    return d;
}

/// Once per process, before the first derivative: the chain rule as the explicit derivative of every
/// registered function that has none.
void install_chain_rule() {
    static const bool installed = [] {
        std::vector<GiNaC::function_options>& registry = FunctionAccess::registry();
        chain_rule_functions().assign(registry.size(), 0);
        for (std::size_t serial = 0; serial < registry.size(); ++serial)
            if (!FunctionOptionsAccess::has_explicit_derivative(registry[serial])) {
                registry[serial].expl_derivative_func(chain_rule);
                chain_rule_functions()[serial] = 1;
            }
        return true;
    }();
    static_cast<void>(installed);
}

}  // namespace eomgen
