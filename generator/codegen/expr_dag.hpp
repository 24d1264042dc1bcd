/** @file expr_dag.hpp  Canonical hash-consed expression DAG: GiNaC expressions in an order of our own. */
#pragma once

#include <ginac/ginac.h>

#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace eomgen::codegen {

/// What a leaf symbol stands for; also the order leaves are listed in products and sums.
enum class SymbolKind : std::uint8_t { Parameter, Coordinate, Velocity, Acceleration, Time, Constant };

struct SymbolInfo {
    SymbolKind kind;
    int index = 0;       ///< position among coordinates or parameters
    std::string name;    ///< C identifier in the generated code
    std::string text;    ///< name in the model language, e.g. "psi'"
    std::string latex;   ///< LaTeX for `eomgen show --latex`
    std::string source;  ///< where generated code reads it from, e.g. "q_(0)", "p_.m"
};

enum class Op : std::uint8_t { Number, Symbol, Func, Pow, Mul, Add };

using NodeId = std::int32_t;
constexpr NodeId kOne = -1;  ///< the empty product: a Term {c, kOne} is the number c

/**
 * One distinct subexpression. Products carry no coefficient (it moves to the enclosing sum's term),
 * sums have their leading term's coefficient positive (the sign moves out), and children are sorted by
 * a structural order, so the same mathematical input gives the same DAG whatever order or sign GiNaC
 * happened to use in this process (its term order follows hash values that ASLR moves).
 */
struct Node {
    Op op;
    std::vector<NodeId> args;            ///< Add: terms; Mul: factors; Pow: {base}; Func: arguments
    std::vector<GiNaC::numeric> coeffs;  ///< Add: coefficient of each term; Mul: exponent (±1, or any
                                         ///< integer when powers are not lowered) of each factor
    GiNaC::numeric value;                ///< Number: the value; Add: the constant term; Pow: exponent
    std::string name;                    ///< Func: function name
    int symbol = -1;                     ///< Symbol: index into the symbol table
};

/// A coefficient times a node (kOne for a pure number).
struct Term {
    GiNaC::numeric coeff;
    NodeId node = kOne;
};

class ExprDag {
public:
    /// `lower_powers`: integer powers become Pow nodes with exponent 2 or 3 (x⁴ = (x²)², x⁵ = (x²)²·x) so
    /// that generated code multiplies and shares the squares; off for printing mathematics.
    ExprDag(std::vector<SymbolInfo> symbols, const std::vector<GiNaC::ex>& symbol_exprs, bool lower_powers);

    /// Converts a GiNaC expression (rational numbers only, functions by name). Throws std::runtime_error
    /// for something generated code cannot express.
    Term add(const GiNaC::ex& e);

    /// The node for a whole term (c·n becomes a one-term sum node when c ≠ 1).
    NodeId node_of(const Term& t);

    const Node& node(NodeId id) const { return nodes_[static_cast<std::size_t>(id)]; }
    const SymbolInfo& symbol(int index) const { return symbols_[static_cast<std::size_t>(index)]; }
    std::size_t size() const { return nodes_.size(); }

    /// Structural total order: <0, 0, >0. Deterministic across processes.
    int compare(NodeId a, NodeId b) const;

private:
    NodeId intern(Node n);
    NodeId number(const GiNaC::numeric& v);
    Term make_add(std::vector<std::pair<NodeId, GiNaC::numeric>> terms, GiNaC::numeric constant);
    Term make_mul(std::map<NodeId, GiNaC::numeric> factors, GiNaC::numeric coeff);
    NodeId make_pow(NodeId base, long k);
    Term make_power(const Term& base, const GiNaC::numeric& exponent);
    Term make_func(const std::string& name, std::vector<Term> args);
    Term convert(const GiNaC::ex& e);

    std::vector<SymbolInfo> symbols_;
    GiNaC::exhashmap<int> symbol_index_;
    bool lower_powers_;
    std::vector<Node> nodes_;
    std::unordered_map<std::string, NodeId> interned_;
    GiNaC::exhashmap<Term> memo_;
};

/// Name of a numeric for keys and messages: exact rationals as "p/q".
std::string numeric_string(const GiNaC::numeric& v);

}  // namespace eomgen::codegen
