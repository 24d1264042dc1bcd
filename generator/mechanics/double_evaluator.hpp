/**
 * @file double_evaluator.hpp  An expression's value in double precision, without CLN.
 *
 * GiNaC's evalf() works in CLN floating point and allocates at every node: evaluating the equations of a
 * 12-link chain at a few dozen random states took most of a generation. This walks the tree once in doubles,
 * sharing the value of each node that occurs more than once. For sampling (Noether's search for symmetries);
 * where an exact decision matters, the result is verified symbolically after. The same walk in long double
 * (LongDoubleEvaluator) from the same inputs: where the two agree, the value is not round-off (is_zero's first look).
 */
#pragma once

#include <ginac/ginac.h>

#include <optional>
#include <unordered_map>
#include <utility>

namespace eomgen {

/// A double per symbol.
using SymbolValues = std::unordered_map<GiNaC::ex, double, std::hash<GiNaC::ex>, GiNaC::ex_is_equal>;

/// Real: double or long double (explicitly instantiated for both in double_evaluator.cpp).
template <class Real>
class FloatEvaluator {
public:
    /// `values`: a double for every symbol the expressions hold (others make the value nothing).
    explicit FloatEvaluator(SymbolValues values) : values_(std::move(values)) {}

    /// The values of `at` (symbols to numbers) as doubles.
    static FloatEvaluator at(const GiNaC::exmap& at);

    /// e's value; nothing where a symbol has no value, a function is not one of the elementary ones, or the value
    /// is not a finite real number.
    std::optional<Real> operator()(const GiNaC::ex& e);

private:
    std::optional<Real> evaluate(const GiNaC::ex& e);
    SymbolValues values_;  ///< by symbol
    /// By node: the ex is kept so that the node lives as long as its entry (a freed temporary's address could be
    /// reused by another expression, which would then read this value).
    std::unordered_map<const GiNaC::basic*, std::pair<GiNaC::ex, Real>> cache_;
};

using DoubleEvaluator = FloatEvaluator<double>;
using LongDoubleEvaluator = FloatEvaluator<long double>;

}  // namespace eomgen
