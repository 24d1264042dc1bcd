/** @file math_printer.hpp  Expressions as a person reads them: the model language or LaTeX, in canonical order. */
#pragma once

#include "codegen/cpp_emitter.hpp"

#include <ginac/ginac.h>

#include <set>
#include <string>
#include <vector>

namespace eomgen::codegen {

enum class MathStyle { Text, Latex };

/// Prints e in the model file's own language (`1/6*m*w^2*psi'^2`) or as LaTeX
/// (`\frac{1}{6} m w^{2} \dot{\psi}^{2}`). Term order is canonical, not GiNaC's per-process order.
class MathPrinter {
public:
    explicit MathPrinter(const SymbolTable& table);
    std::string print(const GiNaC::ex& e, MathStyle style);

    /// Angle differences to print as given: sin(φ − θ) and cos(φ − θ) rather than the canonical −sin(θ − φ)
    /// and cos(θ − φ), the sign of a sine moved into its term's coefficient. For the author's own angles.
    void prefer_angles(const std::vector<GiNaC::ex>& angles);

private:
    /// How many sines of a reversed angle (to odd integer powers) a term's node holds.
    int flipped_sines(NodeId id) const;
    bool reversed(NodeId func) const;
    bool parameters_only(NodeId id) const;  ///< no symbol but parameters below id
    std::string term(const Term& t, MathStyle style);
    std::string sum(const Node& n, const GiNaC::numeric& factor, MathStyle style);
    std::string node(NodeId id, MathStyle style, int context);
    ExprDag dag_;
    std::set<NodeId> reversed_;  ///< canonical angle nodes (θ − φ) the author writes the other way round
    bool in_term_ = false;       ///< printing a term's factors: reversed sines' signs are in its coefficient
};

}  // namespace eomgen::codegen
