/** @file cpp_emitter.hpp  C++ for a model: CSE'd straight-line code in a header that needs only Eigen and the runtime. */
#pragma once

#include "codegen/expr_dag.hpp"
#include "codegen/generation_timings.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <string>
#include <utility>
#include <vector>

namespace eomgen::codegen {

/// Arithmetic in emitted code, counted as it is printed (a−b counts as one addition).
struct OpCount {
    long additions = 0;
    long multiplications = 0;
    long divisions = 0;
    long function_calls = 0;
    long total() const { return additions + multiplications + divisions + function_calls; }
};

/// One value a generated function computes: `target = value;` (target "return" for a return statement).
struct Output {
    std::string target;
    GiNaC::ex value;
};

/// Straight-line code for several outputs together: shared subexpressions become `const Scalar tK = ...;`
/// (computed once), integer powers products, each sin/cos of an argument evaluated once.
struct FunctionBody {
    std::vector<std::string> lines;  ///< statements, without indentation
    std::vector<int> used_symbols;   ///< symbol-table indices the statements read
    std::vector<std::string> functions;  ///< math functions called (sin, cos, sqrt, ...), sorted
    OpCount ops;
};

/// The symbol table generated code reads: parameters (p_.name), coordinates q_(i), velocities qd_(i),
/// accelerations, time t and the constant pi; `exprs` are the matching GiNaC symbols.
struct SymbolTable {
    std::vector<SymbolInfo> info;
    std::vector<GiNaC::ex> exprs;
};
SymbolTable symbol_table(const Model& model);

FunctionBody emit_body(ExprDag& dag, const std::vector<Output>& outputs);

/// One static member function of the generated Model: signature, unused-argument markers, input locals, body.
struct FunctionSpec {
    std::string doc;
    std::string return_type;  ///< "void" or "Scalar"
    std::string name;
    std::vector<std::pair<std::string, std::string>> inputs;  ///< (type, name)
    std::vector<std::pair<std::string, std::string>> outputs;
    std::vector<Output> values;
    std::vector<std::string> delegate = {};  ///< when not empty: the whole body, calling another function
    std::string template_head = {};          ///< e.g. "template <class MatR>": a member template, compiled where called
    std::vector<std::string> before = {};    ///< lines before the CSE'd assignments (locals that `values` assign)
    std::vector<std::string> after = {};     ///< lines after them (e.g. a product of those locals)
};

/// The function as a member of the generated Model (4-space indented, EOMGEN_HD), its values CSE'd together.
std::string emit_function(const FunctionSpec& f, const SymbolTable& table);

/// The whole generated header for a model (see docs/generated_code.md). Deterministic: the same model
/// gives the same bytes in every process. `model_file` is the name printed in the header. The optional functions
/// are those model.generate asks for. With `timings`, each phase's time and peak memory is added to it.
std::string emit_model_header(const Model& model, const Equations& eq, const std::string& model_file,
                              GenerationTimings* timings = nullptr);

/// Shortest round-trip decimal for a double, as generated code and docs print defaults.
std::string shortest_decimal(double v);

}  // namespace eomgen::codegen
