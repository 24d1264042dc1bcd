/** @file math_printer.hpp  Expressions as a person reads them: the model language or LaTeX, in canonical order. */
#pragma once

#include "codegen/cpp_emitter.hpp"

#include <ginac/ginac.h>

#include <string>

namespace eomgen::codegen {

enum class MathStyle { Text, Latex };

/// Prints e in the model file's own language (`1/6*m*w^2*psi'^2`) or as LaTeX
/// (`\frac{1}{6} m w^{2} \dot{\psi}^{2}`). Term order is canonical, not GiNaC's per-process order.
class MathPrinter {
public:
    explicit MathPrinter(const SymbolTable& table);
    std::string print(const GiNaC::ex& e, MathStyle style);

private:
    std::string term(const Term& t, MathStyle style);
    std::string sum(const Node& n, const GiNaC::numeric& factor, MathStyle style);
    std::string node(NodeId id, MathStyle style, int context);
    ExprDag dag_;
};

}  // namespace eomgen::codegen
