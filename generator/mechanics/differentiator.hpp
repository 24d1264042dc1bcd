/**
 * @file differentiator.hpp  Symbolic derivatives of many expressions that share their subexpressions.
 *
 * GiNaC's diff() differentiates every occurrence of a subexpression again and walks the parts of a tree that do
 * not hold the variable. The Differentiator remembers the derivative of every node it has met (for M and f of the
 * n-link pendulum O(n⁴) work becomes O(n³)), and, given a SymbolSupport, returns 0 for a node that does not hold
 * the variable without walking it (the momenta and ∂L/∂q of the 60-link pendulum took a second in GiNaC's diff).
 * The derivatives are those of GiNaC's own rules (add::derivative, mul::derivative, power::derivative, the chain
 * rule for functions), so the equations are the same expressions either way.
 */
#pragma once

#include <ginac/ginac.h>

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace eomgen {

/// Once per process, before the first derivative: the chain rule as the explicit derivative of every registered
/// function that has none (GiNaC 1.8 otherwise throws and catches an exception in every derivative of a sin).
void install_chain_rule();

/**
 * Which of a fixed list of symbols each node of a tree holds, as bits remembered by node: whether a subexpression
 * holds a variable is O(1) after one walk. The table keeps its nodes alive, so an address is never reused.
 */
class SymbolSupport {
public:
    explicit SymbolSupport(const std::vector<GiNaC::ex>& symbols);

    /// The bits of the symbols in `of` (its keys); `indexed` is false when one of them is not in the list.
    std::vector<std::uint64_t> mask(const GiNaC::exmap& of, bool& indexed) const;
    /// The bits of the symbols in `of` that are in the list.
    std::vector<std::uint64_t> mask(const std::vector<GiNaC::ex>& of) const;
    /// True when e holds one of the symbols of `mask`.
    bool holds(const GiNaC::ex& e, const std::vector<std::uint64_t>& mask);

private:
    std::size_t bits_of(const GiNaC::ex& e);  ///< offset of e's words in words_
    std::size_t words_per_node_;
    std::unordered_map<GiNaC::ex, std::size_t, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> index_;  ///< symbol → bit
    std::unordered_map<const GiNaC::basic*, std::pair<GiNaC::ex, std::size_t>> nodes_;  ///< node → offset
    std::vector<std::uint64_t> words_;
};

/// ∂e/∂x for one symbol x, or the directional derivative Σ_k v_k ∂e/∂x_k, over many expressions.
class Differentiator {
public:
    /// d/dx; with `support`, nodes without x are skipped (the support must outlive the Differentiator).
    explicit Differentiator(const GiNaC::symbol& x, SymbolSupport* support = nullptr)
        : Differentiator(GiNaC::exmap{{x, 1}}, support) {}
    /// The directional derivative Σ_k v_k ∂/∂x_k, one walk for every direction's component (seeds: x_k → v_k):
    /// Σ_j q̇_j ∂p_i/∂q_j in one pass instead of n derivatives each multiplied back.
    explicit Differentiator(GiNaC::exmap seeds, SymbolSupport* support = nullptr);

    GiNaC::ex operator()(const GiNaC::ex& e);

private:
    GiNaC::ex derivative(const GiNaC::ex& e);

    GiNaC::exmap seeds_;
    SymbolSupport* support_ = nullptr;  ///< null: no skipping
    std::vector<std::uint64_t> mask_;   ///< the seeds' bits in support_
    std::unordered_map<const GiNaC::basic*, std::pair<GiNaC::ex, GiNaC::ex>> memo_;
};

}  // namespace eomgen
