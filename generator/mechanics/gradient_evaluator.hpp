/**
 * @file gradient_evaluator.hpp  An expression's value and gradient in double precision, by forward
 * differentiation over the tree (dual numbers), without forming the derivative symbolically.
 *
 * The linearization about a steady motion needs ∂f/∂q, ∂f/∂q̇, ∂A/∂q and ∂c/∂q of the bicycle's equations at
 * hundreds of states (a sweep, the bisection for the stability boundaries): GiNaC's diff() of those trees and
 * their evaluation took over a second per state. Walking each tree once with a value and a gradient per node,
 * shared where a node occurs more than once, gives the same derivatives to round-off.
 */
#pragma once

#include "mechanics/double_evaluator.hpp"

#include <Eigen/Dense>

#include <optional>
#include <unordered_map>
#include <utility>

namespace eomgen {

class GradientEvaluator {
public:
    /// The most symbols differentiated for at once: the gradients live in fixed storage, not on the heap.
    static constexpr int kMaxSeeds = 64;
    using Gradient = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxSeeds, 1>;

    /// A value: the number and its gradient over the seeded symbols.
    struct Dual {
        double value = 0;
        Gradient gradient;
    };

    /// `values`: a double for every symbol; `seeds`: the symbols differentiated for, symbol → index in
    /// [0, kMaxSeeds) (std::length_error beyond).
    GradientEvaluator(SymbolValues values, const SymbolValues& seeds);

    /// e's value and gradient; nothing where a symbol has no value, a function is not one this knows (the
    /// elementary ones, abs, max, min, sign, heaviside), or a value is not finite.
    std::optional<Dual> operator()(const GiNaC::ex& e);

private:
    std::optional<Dual> evaluate(const GiNaC::ex& e);
    SymbolValues values_;
    std::unordered_map<GiNaC::ex, int, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> seeds_;
    Eigen::Index size_ = 0;
    std::unordered_map<const GiNaC::basic*, std::pair<GiNaC::ex, Dual>> cache_;
};

}  // namespace eomgen
